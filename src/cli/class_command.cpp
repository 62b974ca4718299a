// klueng-cli class DIR --reference REF.nc | --drawing PART.json: grade a class
// (issues 11 and 28). Every program in DIR is checked, run and cut like
// `simulate`, and its finished part compared with the reference's on the
// diameter (the largest material left on and cut away, both within the
// tolerance) and/or measured against each toleranced dimension of the
// teacher's drawing (a part file or DXF; ISO 286 fits, ±, ISO 2768 general
// tolerances), pass when everything is within and the program ran to its end.
// One row per program (CSV; with a drawing one per program and dimension); one
// bad file is one failed row, never the end of the batch.
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "klueng/core/diagnostic_codes.h"
#include "png_writer.h"
#include "commands.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/design/dxf_import.h"
#include "klueng/core/design/iso_fits.h"
#include "klueng/core/design/part_design.h"
#include "render/class_pdf_cells.h"
#include "klueng/core/gcode/word_format.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/folder_files.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

struct ClassOptions : JobOptions {
  std::string dir, reference, drawing, layer, generalTolerance, csv, pdf;
  bool sheets = false;
  double tolerance = 0.05;
};

// class's option table (cli_common.h): the shared rows, then its own.
std::optional<int> parseClassOptions(const std::vector<std::string>& args, ClassOptions& o) {
  std::vector<CliOption> options = machineOptions(o);
  const std::vector<CliOption> own = {
      valueOption("--reference", o.reference),
      valueOption("--drawing", o.drawing),
      valueOption("--layer", o.layer),
      valueOption("--csv", o.csv),
      valueOption("--pdf", o.pdf),
      flagOption("--sheets", o.sheets),
      {"--general-tolerance",
       {},
       true,
       codes::kCliAllowedGeneralTolerance,
       [&o](const std::string& v) {
         o.generalTolerance = v;
         return design::generalTolerance(v, 10.0).has_value();
       }},
      {"--tolerance",
       {},
       true,
       codes::kCliAllowedTolerance,
       [&o](const std::string& v) {
         char* end = nullptr;
         o.tolerance = std::strtod(v.c_str(), &end);
         return end && *end == '\0' && !v.empty() && o.tolerance >= 0.0 && o.tolerance <= 100.0;
       }},
  };
  options.insert(options.end(), own.begin(), own.end());
  const auto exit =
      parseCommandLine("class", codes::kCliClassUsage, args, options, oneFile("class", o.dir, langOfArgs(args)));
  if (exit) return exit;
  if (o.dir.empty() || (o.reference.empty() && o.drawing.empty()))
    return usageError("class", codes::kCliClassUsage, o.lang, codes::kCliClassNeeds);
  return std::nullopt;
}

// The table as the picture module draws it (klueng-png.so, opened only for --pdf).
bool writePdf(const ClassOptions& o, const std::vector<core::job::ClassRow>& rows, const std::string& configDir) {
  const render::ClassPdfCells cells(rows, o.lang, !o.reference.empty());
  const std::string reference = std::filesystem::path(o.reference).filename().string();
  const std::string drawing = std::filesystem::path(o.drawing).filename().string();
  KluengClassPdf in{};
  in.thai = o.lang == Lang::Th ? 1 : 0;
  in.reference = reference.c_str();
  in.tolerance = o.tolerance;
  cells.into(in);
  in.sheets = o.sheets ? static_cast<int>(rows.size()) : 0;
  in.configDir = configDir.c_str();
  in.dialect = static_cast<int>(o.dialect);
  in.drawing = o.drawing.empty() ? nullptr : drawing.c_str();
  in.hasReference = o.reference.empty() ? 0 : 1;
  return reportWrite(o.pdf, writeClassPdf(in, o.pdf), o.lang);
}

// The drawing's toleranced dimensions, or nullopt after saying why (its file's messages).
std::optional<std::vector<cut::DrawnDimension>> readDrawing(const ClassOptions& o, double chuckGrip) {
  std::optional<std::vector<cut::DrawnDimension>> read =
      readDrawnDimensions(o.drawing, o.layer, o.generalTolerance, chuckGrip, o.lang);
  if (!read) return std::nullopt;
  std::vector<cut::DrawnDimension> dims = std::move(*read);
  if (dims.empty()) {
    printCliError("class", codes::kCliDrawingNoTolerances, o.lang, {o.drawing});
    return std::nullopt;
  }
  return dims;
}

}  // namespace

int runClass(const std::vector<std::string>& args) {
  ClassOptions o;
  if (const auto exit = parseClassOptions(args, o)) return *exit;
  LoadedConfig config = loadConfig(o.configDir);
  if (!chooseMachine(o.machine, config, o.dialect, o.lang)) return 2;
  for (const auto& fd : config.diagnostics) printDiagnostic(stderr, fd.file, fd.diagnostic, o.lang);
  if (config.unreadable || config.hasErrors()) return 2;
  std::string error;
  std::optional<core::job::JobInput> request = jobRequest(config, o.dialect, std::nullopt, std::nullopt, {}, error);
  // Each student's program on the machine it names, unless --machine or --dialect chose one.
  if (request) request->programMachine = !o.dialectGiven;
  if (!request) {
    std::fprintf(stderr, "klueng-cli class: %s\n", error.c_str());
    return 2;
  }
  core::job::GradeAgainst against;
  against.tolerance = o.tolerance;
  core::job::GradedProgram reference;
  if (!o.reference.empty()) {
    // A named pipe is refused unopened, with its own message (issue 42 item 4).
    if (const auto refused = io::wouldBlockOnOpen(o.reference)) {
      printDiagnostic(stderr, o.reference, *refused, o.lang);
      return 2;
    }
    reference = core::job::gradeProgram(o.reference, *request);
    if (!reference.part) {
      printCliError("class", codes::kCliReferenceFails, o.lang, {o.reference, reference.firstError + reference.alarm});
      return 2;
    }
    against.referencePath = o.reference;
    against.reference = &*reference.part;
  }
  if (!o.drawing.empty()) {
    auto dims = readDrawing(o, config.setup.machine.chuckGrip);
    if (!dims) return 2;
    against.drawingPath = o.drawing;
    against.drawing = std::move(*dims);
    against.hasDrawing = true;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec)) {
    printCliError("class", codes::kCliNotAFolder, o.lang, {o.dir});
    return 2;
  }
  // Every program file in the folder is graded, so every one is an input the outputs must not
  // replace (the grades' own CSV or PDF beside them is not a program: a second run writes it again).
  std::vector<std::string> inputs = setupFiles(config);
  if (!o.reference.empty()) inputs.push_back(o.reference);
  if (!o.drawing.empty()) inputs.push_back(o.drawing);
  for (const io::FolderEntry& e : io::programFolderEntries(o.dir))
    if (e.kind == io::FolderEntryKind::Program) {
      inputs.push_back(e.path);
      inputs.push_back(core::job::touchOffFilePath(e.path));  // the setup exercise's offsets
    }
  if (!outputsAllowed({o.csv, o.pdf}, inputs, o.lang)) return 2;
  const std::vector<core::job::ClassRow> rows =
      core::job::gradeClass(o.dir, against, *request, [](int i, int n, const std::string& name) {
        // Progress is for a person watching; a script or a pipe reading stderr gets the diagnostics only.
        if (::isatty(STDERR_FILENO)) std::fprintf(stderr, "[%d/%d] %s\n", i + 1, n, printable(name).c_str());
      });
  const int passed =
      static_cast<int>(std::count_if(rows.begin(), rows.end(), [](const core::job::ClassRow& r) { return r.pass; }));
  const std::string table = core::job::classCsv(rows, against.hasDrawing);
  if (o.csv.empty()) {
    std::fputs(table.c_str(), stdout);
  } else if (!writeOutput(o.csv, table, o.lang)) {
    return 2;  // the old file keeps its bytes; the message says why (issue 29)
  }
  if (!o.pdf.empty() && !writePdf(o, rows, config.dir)) return 2;
  // The setup exercise (issue 31): each student's touch-off, tool by tool, in the chosen language.
  for (const core::job::ClassRow& r : rows)
    if (r.touchOff.asked)
      std::fprintf(stderr, "%s: %s\n", printable(r.file).c_str(),
                   printable(core::job::touchOffText(r.touchOff, o.tolerance, o.lang)).c_str());
  const std::string totals = cliText(codes::kCliClassTotals, o.lang,
                                     {std::to_string(rows.size()), std::to_string(passed),
                                      std::to_string(rows.size() - static_cast<std::size_t>(passed))});
  std::fprintf(stderr, "%s\n", totals.c_str());
  return 0;
}

}  // namespace klueng::cli
