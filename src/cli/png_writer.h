#pragma once
// klueng-cli --png: draws the section with the screen's painters by opening the
// picture module (klueng-png.so) beside the program, or in ../lib/klueng when
// installed, and writes the file with core/io/file_write.h (checked, atomic,
// read-only files refused).
#include <optional>
#include <string>

#include "klueng/core/diagnostic.h"

#include "render/class_pdf_input.h"
#include "render/print_pdf_input.h"
#include "render/section_picture.h"

namespace klueng::cli {

// klueng-cli simulate --png: nullopt when written; else why (F1xx, in both languages), the old file unchanged.
std::optional<core::Diagnostic> writeSectionPng(const render::SectionPicture& picture, const std::string& path);
// klueng-cli class --pdf: the grades (and with sheets, each student's sheets) as one PDF at `path`.
// nullopt when written; else why (F1xx, io/file_write.h), the old file unchanged.
std::optional<core::Diagnostic> writeClassPdf(const KluengClassPdf& input, const std::string& path);
// klueng-cli print: the program's sheets as one PDF at `path`; as writeClassPdf.
std::optional<core::Diagnostic> writePrintPdf(const KluengPrintPdf& input, const std::string& path);

}  // namespace klueng::cli
