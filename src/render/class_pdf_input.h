#pragma once
// What klueng-cli class --pdf hands the picture module (klueng-png.so): plain C
// data, no Qt, so the CLI loads Qt only when a PDF is asked for.
#include <cstddef>

extern "C" {
struct KluengClassPdf {
  const char* path;               // the PDF to write
  int thai;                       // 1: Thai texts and dates
  const char* reference;          // the reference program's name
  double tolerance;               // mm on the diameter
  int rows;                       // students
  const char* const* cells;       // rows x 7 (program, result, errors, alarm, cycle time s, leftover, gouge), UTF-8
  int sheets;                     // with --sheets: each student's program sheet and drawing follow
  const char* const* sheetPaths;  // sheets paths, in row order
  const char* configDir;          // the setup for the drawings
  int dialect;                    // core::gcode::Dialect
};
}
using KluengClassPdfFn = int (*)(const KluengClassPdf*, char* error, std::size_t errorSize);
