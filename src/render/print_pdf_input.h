#pragma once
// What klueng-cli print hands the picture module (klueng-png.so): the program
// as the CLI loaded it (stock resolved, tools chosen), so the sheets show the
// same run as `simulate`.
#include <cstddef>

#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/job.h"

struct KluengPrintPdf {
  const char* path;                                 // the PDF to write
  int thai;                                         // 1: Thai texts and dates
  int programSheet;                                 // 1: the program sheet (portrait)
  int drawingSheet;                                 // 1: the drawing sheet (landscape)
  const char* fileName;                             // shown on the sheets
  const klueng::core::io::ProgramFile* program;     // header (with the run's stock) + G-code
  const klueng::core::machine::MachineSetup* setup; // tools and offsets of the run
  const klueng::core::machine::JobOptions* job;     // dialect, power-on units, subprogram folder
};
using KluengPrintPdfFn = int (*)(const KluengPrintPdf*, char* error, std::size_t errorSize);
