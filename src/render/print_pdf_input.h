#pragma once
// What klueng-cli print hands the picture module (klueng-png.so): the program
// as the CLI loaded it (stock resolved, tools chosen), so the sheets show the
// same run as `simulate`. The module returns the PDF's bytes; the CLI writes
// them (io/file_write.h), so a full disk is seen and the old file kept.
#include <cstddef>
#include <vector>

#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"

struct KluengPrintPdf {
  int thai;                           // 1: Thai texts and dates
  int programSheet;                   // 1: the program sheet (portrait)
  int drawingSheet;                   // 1: the drawing sheet (landscape)
  const char* fileName;               // shown on the sheets
  const klueng::core::job::Job* job;  // the program (stock resolved), its tools and its run
  int inch;                           // 1: the drawing's dimensions in inches (a G20 program)
  // The part design the program was made from (print --design): its tolerances
  // and roughness marks go on the drawing; nullptr: none.
  const klueng::core::design::PartDesign* design;
};
// 1 with *bytes (malloc'd, the caller frees) and *size; 0 with `error` filled.
using KluengPrintPdfFn = int (*)(const KluengPrintPdf*, char** bytes, std::size_t* size, char* error,
                                 std::size_t errorSize);
