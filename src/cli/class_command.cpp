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
#include "klueng/core/diagnostic_codes.h"
#include "png_writer.h"
#include "commands.h"
#include "klueng/core/cut/class_grading.h"
#include "klueng/core/gcode/word_format.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

struct ClassOptions {
  std::string dir, reference, csv, pdf, configDir;
  bool sheets = false;
  double tolerance = 0.05;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  std::string machine;  // --machine NAME|FILE
  Lang lang = langFromLocale();
};

// The options, or nullopt after saying what is wrong (in the command's language).
std::optional<ClassOptions> parse(const std::vector<std::string>& args) {
  ClassOptions o;
  o.lang = langOfArgs(args);
  const Lang lang = o.lang;
  const auto bad = [lang](const std::string& option, const std::string& value, const char* allowed) {
    if (allowed) printCliError("class", codes::kCliBadValue, lang, {value, option, cliText(allowed, lang)});
    else printCliError("class", codes::kCliBadValueAnyOf, lang, {value, option});
    return std::nullopt;
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool takesValue = a == "--reference" || a == "--csv" || a == "--pdf" || a == "--config" ||
                            a == "--tolerance" || a == "--dialect" || a == "--machine" || a == "--lang";
    if (takesValue && i + 1 >= args.size()) {
      printCliError("class", codes::kCliNeedsValue, lang, {a});
      return std::nullopt;
    }
    if (a == "--reference") o.reference = args[++i];
    else if (a == "--csv") o.csv = args[++i];
    else if (a == "--pdf") o.pdf = args[++i];
    else if (a == "--sheets") o.sheets = true;
    else if (a == "--config") o.configDir = args[++i];
    else if (a == "--machine") o.machine = args[++i];
    else if (a == "--tolerance") {
      const std::string& v = args[++i];
      char* end = nullptr;
      o.tolerance = std::strtod(v.c_str(), &end);
      if (!end || *end != '\0' || v.empty() || !(o.tolerance >= 0.0) || o.tolerance > 100.0) return bad(a, v, nullptr);
    } else if (a == "--dialect") {
      const auto d = parseDialect(args[++i]);
      if (!d) return bad(a, args[i], codes::kCliAllowedDialect);
      o.dialect = *d;
    } else if (a == "--lang") {
      const auto l = parseLang(args[++i]);
      if (!l) return bad(a, args[i], codes::kCliAllowedLang);
      o.lang = *l;
    } else if (a.starts_with("--")) {
      printCliError("class", codes::kCliUnknownOption, lang, {a});
      return std::nullopt;
    } else if (o.dir.empty()) {
      o.dir = a;
    } else {
      printCliError("class", codes::kCliOneFile, lang, {o.dir, a});
      return std::nullopt;
    }
  }
  if (o.dir.empty() || o.reference.empty()) {
    printCliError("class", codes::kCliClassNeeds, lang);
    return std::nullopt;
  }
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
    std::fputs(cliText(codes::kCliClassUsage, langOfArgs(args)).c_str(), stdout);
    return 0;
  }
  std::optional<ClassOptions> parsed = parse(args);
  if (!parsed) {
    std::fputs(cliText(codes::kCliClassUsage, langOfArgs(args)).c_str(), stderr);
    return 2;
  }
  ClassOptions& o = *parsed;
  LoadedConfig config = loadConfig(o.configDir);
  if (!chooseMachine(o.machine, config, o.dialect, o.lang)) return 2;
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
    printCliError("class", codes::kCliReferenceFails, o.lang, {o.reference, reference.firstError + reference.alarm});
    return 2;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(o.dir, ec)) {
    printCliError("class", codes::kCliNotAFolder, o.lang, {o.dir});
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
  const std::string totals = cliText(codes::kCliClassTotals, o.lang,
                                     {std::to_string(rows.size()), std::to_string(passed),
                                      std::to_string(rows.size() - static_cast<std::size_t>(passed))});
  std::fprintf(stderr, "%s\n", totals.c_str());
  return 0;
}

}  // namespace klueng::cli
