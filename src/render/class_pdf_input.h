#pragma once
// What klueng-cli class --pdf hands the picture module (klueng-png.so): plain C
// data, no Qt, so the CLI loads Qt only when a PDF is asked for. The module
// returns the PDF's bytes; the CLI writes them (io/file_write.h), so a full
// disk is seen and the old file kept.
#include <cstddef>

extern "C" {
enum { kClassPdfColumns = 8 };
struct KluengClassPdf {
  int thai;                       // 1: Thai texts and dates
  const char* reference;          // the reference program's name
  double tolerance;               // mm on the diameter
  int rows;                       // students
  const char* const* cells;       // rows x kClassPdfColumns (program, result, errors, alarm, cycle time s, leftover,
                                  // gouge, cutting-data warnings), UTF-8
  int sheets;                     // with --sheets: each student's program sheet and drawing follow
  const char* const* sheetPaths;  // sheets paths, in row order
  const char* configDir;          // the setup for the drawings
  int dialect;                    // core::gcode::Dialect
  // Against the teacher's drawing (issue 28): null when graded against a reference only.
  const char* drawing;                // the drawing's file name
  int hasReference;                   // 0: graded against the drawing only
  int dimensions;                     // toleranced dimensions per student
  const char* const* dimensionCells;  // rows x dimensions x 5 (feature, tolerance, limits, measured, verdict), UTF-8
  const int* verdicts;                // rows x dimensions: 0 in, 1 out, 2 missing
};
}
// 1 with *bytes (malloc'd, the caller frees) and *size; 0 with `error` filled.
using KluengClassPdfFn = int (*)(const KluengClassPdf*, char** bytes, std::size_t* size, char* error,
                                 std::size_t errorSize);
