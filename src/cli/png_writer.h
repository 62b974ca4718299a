#pragma once
// klueng-cli --png: draws the section with the screen's painters by opening the
// picture module (klueng-png.so) beside the program, or in ../lib/klueng when
// installed, and writes the file atomically.
#include <string>

#include "render/class_pdf_input.h"
#include "render/print_pdf_input.h"
#include "render/section_picture.h"

namespace klueng::cli {

bool writeSectionPng(const render::SectionPicture& picture, const std::string& path, std::string* error);
// klueng-cli class --pdf: the grades (and with sheets, each student's sheets) as one PDF at `path`.
bool writeClassPdf(KluengClassPdf input, const std::string& path, std::string* error);
// klueng-cli print: the program's sheets as one PDF at `path`.
bool writePrintPdf(KluengPrintPdf input, const std::string& path, std::string* error);

}  // namespace klueng::cli
