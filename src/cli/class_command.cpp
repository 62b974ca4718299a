// klueng-cli class DIR --reference REF.nc: grade a class (issue 11). Every
// program in DIR is checked, run and cut like `simulate`, and its finished part
// compared with the reference's on the diameter: the largest material left on
// (leftover) and cut away (gouge), pass when both are within the tolerance and
// the program ran to its end. One row per program (CSV); one bad file is one
// failed row, never the end of the batch.
#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_common.h"
#include "png_writer.h"
#include "commands.h"
#include "klueng/core/cut/class_grading.h"
#include "klueng/core/gcode/word_format.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

constexpr const char* kClassUsage =
    "usage: klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
    "                            [--pdf OUT.pdf [--sheets]] [--dialect fanuc|haas|classic]\n"
    "                            [--config DIR] [--lang en|th]\n"
    "  every program in DIR against REF.nc: errors, alarm, cycle time, the largest leftover\n"
    "  and gouge on the diameter (mm), pass when both are within --tolerance (mm);\n"
    "  --pdf: the same table as a page (Thai with --lang th), --sheets: then every\n"
    "  student's program sheet and drawing in the same PDF\n";

struct ClassOptions {
  std::string dir, reference, csv, pdf, configDir;
  bool sheets = false;
  double tolerance = 0.05;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  Lang lang = langFromLocale();
};

std::optional<ClassOptions> parse(const std::vector<std::string>& args) {
  ClassOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool hasValue = i + 1 < args.size();
    if (a == "--reference" && hasValue) o.reference = args[++i];
    else if (a == "--csv" && hasValue) o.csv = args[++i];
    else if (a == "--pdf" && hasValue) o.pdf = args[++i];
    else if (a == "--sheets") o.sheets = true;
    else if (a == "--config" && hasValue) o.configDir = args[++i];
    else if (a == "--tolerance" && hasValue) {
      char* end = nullptr;
      o.tolerance = std::strtod(args[++i].c_str(), &end);
      if (!end || *end != '\0' || !(o.tolerance >= 0.0) || o.tolerance > 100.0) return std::nullopt;
    } else if (a == "--dialect" && hasValue) {
      const auto d = parseDialect(args[++i]);
      if (!d) return std::nullopt;
      o.dialect = *d;
    } else if (a == "--lang" && hasValue) {
      const auto l = parseLang(args[++i]);
      if (!l) return std::nullopt;
      o.lang = *l;
    } else if (!a.starts_with("--") && o.dir.empty()) {
      o.dir = a;
    } else {
      return std::nullopt;
    }
  }
  if (o.dir.empty() || o.reference.empty()) return std::nullopt;
  return o;
}

// The table as the picture module draws it (klueng-png.so, opened only for --pdf).
bool writePdf(const ClassOptions& o, const std::vector<cut::ClassRow>& rows, const std::string& configDir) {
  std::vector<std::string> cells;
  std::vector<std::string> paths;
  for (const cut::ClassRow& r : rows) {
    cells.push_back(r.file);
    cells.push_back(r.pass ? "pass" : "fail");
    cells.push_back(r.graded.errors > 0 ? std::to_string(r.graded.errors) + " (" + r.graded.firstError + ")" : "0");
    cells.push_back(r.graded.alarm);
    cells.push_back(r.graded.errors == 0 ? gcode::formatFixed(r.graded.cycleTime, 1) : "");
    cells.push_back(r.compared ? gcode::formatFixed(r.deviation.leftover, 3) : "");
    cells.push_back(r.compared ? gcode::formatFixed(r.deviation.gouge, 3) : "");
    paths.push_back(r.path);
  }
  std::vector<const char*> cellPtrs, pathPtrs;
  for (const std::string& c : cells) cellPtrs.push_back(c.c_str());
  for (const std::string& p : paths) pathPtrs.push_back(p.c_str());
  const std::string reference = std::filesystem::path(o.reference).filename().string();
  KluengClassPdf in{};
  in.thai = o.lang == Lang::Th ? 1 : 0;
  in.reference = reference.c_str();
  in.tolerance = o.tolerance;
  in.rows = static_cast<int>(rows.size());
  in.cells = cellPtrs.data();
  in.sheets = o.sheets ? static_cast<int>(rows.size()) : 0;
  in.sheetPaths = pathPtrs.data();
  in.configDir = configDir.c_str();
  in.dialect = static_cast<int>(o.dialect);
  return reportWrite(o.pdf, writeClassPdf(in, o.pdf), o.lang);
}

}  // namespace

int runClass(const std::vector<std::string>& args) {
  if (std::find(args.begin(), args.end(), "--help") != args.end()) {
    std::fputs(kClassUsage, stdout);
    return 0;
  }
  const std::optional<ClassOptions> parsed = parse(args);
  if (!parsed) {
    std::fputs(kClassUsage, stderr);
    return 2;
  }
  const ClassOptions& o = *parsed;
  const LoadedConfig config = loadConfig(o.configDir);
  for (const auto& fd : config.diagnostics) printDiagnostic(stderr, fd.file, fd.diagnostic, o.lang);
  if (config.unreadable || config.hasErrors()) return 2;
  std::string error;
  const std::optional<machine::JobFileRequest> request = jobRequest(config, o.dialect, std::nullopt, std::nullopt, {}, error);
  if (!request) {
    std::fprintf(stderr, "klueng-cli class: %s\n", error.c_str());
    return 2;
  }
  const cut::GradedProgram reference = cut::gradeProgram(o.reference, config.setup, *request);
  if (!reference.part) {
    std::fprintf(stderr, "klueng-cli class: the reference %s does not run to its end (%s%s)\n", o.reference.c_str(),
                 reference.firstError.c_str(), reference.alarm.c_str());
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec)) {
    std::fprintf(stderr, "klueng-cli class: %s is not a folder\n", o.dir.c_str());
    return 2;
  }
  // Every program file in the folder is graded, so every one is an input the outputs must not
  // replace (the grades' own CSV or PDF beside them is not a program: a second run writes it again).
  std::vector<std::string> inputs = setupFiles(config);
  inputs.push_back(o.reference);
  for (const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(o.dir, ec))
    if (e.is_regular_file(ec) && io::isProgramFileName(e.path().string())) inputs.push_back(e.path().string());
  if (!outputsAllowed({o.csv, o.pdf}, inputs, o.lang)) return 2;
  const std::vector<cut::ClassRow> rows = cut::gradeClass(
      o.dir, o.reference, *reference.part, config.setup, *request, o.tolerance,
      [](int i, int n, const std::string& name) { std::fprintf(stderr, "[%d/%d] %s\n", i + 1, n, name.c_str()); });
  const int passed = static_cast<int>(std::count_if(rows.begin(), rows.end(), [](const cut::ClassRow& r) { return r.pass; }));
  const std::string table = cut::classCsv(rows);
  if (o.csv.empty()) {
    std::fputs(table.c_str(), stdout);
  } else if (!writeOutput(o.csv, table, o.lang)) {
    return 2;  // the old file keeps its bytes; the message says why (issue 29)
  }
  if (!o.pdf.empty() && !writePdf(o, rows, config.dir)) return 2;
  std::fprintf(stderr, "%zu programs: %d pass, %zu fail\n", rows.size(), passed, rows.size() - static_cast<std::size_t>(passed));
  return 0;
}

}  // namespace klueng::cli
