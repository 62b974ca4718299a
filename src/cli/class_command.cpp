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
#include "commands.h"
#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_compare.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/job_file.h"

namespace klueng::cli {

namespace {

namespace fs = std::filesystem;
using namespace klueng::core;

constexpr const char* kClassUsage =
    "usage: klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
    "                            [--dialect fanuc|haas|classic] [--config DIR] [--lang en|th]\n"
    "  every program in DIR against REF.nc: errors, alarm, cycle time, the largest leftover\n"
    "  and gouge on the diameter (mm), pass when both are within --tolerance (mm)\n";

struct ClassOptions {
  std::string dir, reference, csv, configDir;
  double tolerance = 0.05;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  Lang lang = langFromLocale();
};

struct Graded {
  std::optional<cut::Stock> part;  // the finished part (none when it did not run to the end)
  int errors = 0;
  std::string firstError;          // code, line
  std::string alarm;               // code, line
  double cycleTime = 0.0;
};

struct Row {
  std::string file;
  Graded graded;
  cut::PartDeviation deviation;
  bool cut = false;  // it ran to its end and was compared
  bool pass = false;
};

std::string place(const Diagnostic& d) { return d.code + " line " + std::to_string(d.range.line); }

Graded grade(const std::string& path, const LoadedConfig& config, const machine::JobFileRequest& request) {
  Graded g;
  const machine::JobFile job = machine::loadJobFile(path, config.setup, request, io::shippedToolLibrary());
  for (const Diagnostic& d : job.diagnostics)
    if (isError(d.severity)) {
      if (g.errors++ == 0) g.firstError = place(d);
    }
  if (job.unreadable || !job.file || !job.program || job.hasErrors()) {
    if (g.errors == 0) g.errors = 1, g.firstError = "unreadable";
    return g;
  }
  const machine::Timeline timeline = machine::interpret(*job.program, job.setup, request.run);
  g.cycleTime = timeline.cycleTime();
  if (timeline.alarm) {
    g.alarm = place(*timeline.alarm);
    return g;
  }
  cut::CutOptions options;
  options.checkpointBudgetBytes = 0;  // one run forward
  cut::CutSimulator sim(timeline, cut::CutSetup::from(job.file->header, job.setup), options);
  sim.runToEnd();
  if (sim.alarm()) {
    g.alarm = place(*sim.alarm());
    return g;
  }
  g.part = sim.stock();
  return g;
}

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string csv(const std::vector<Row>& rows) {
  std::string out = "file,result,errors,first_error,alarm,cycle_time_s,leftover_mm,leftover_z,gouge_mm,gouge_z\n";
  for (const Row& r : rows) {
    const bool cut = r.cut;
    out += csvField(r.file) + "," + (r.pass ? "pass" : "fail") + "," + std::to_string(r.graded.errors) + "," +
           csvField(r.graded.firstError) + "," + csvField(r.graded.alarm) + "," +
           (r.graded.errors == 0 ? number(r.graded.cycleTime, 1) : "") + "," +
           (cut ? number(r.deviation.leftover, 3) + "," + number(r.deviation.leftoverZ, 2) + "," +
                      number(r.deviation.gouge, 3) + "," + number(r.deviation.gougeZ, 2)
                : ",,,") +
           "\n";
  }
  return out;
}

std::optional<ClassOptions> parse(const std::vector<std::string>& args) {
  ClassOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool hasValue = i + 1 < args.size();
    if (a == "--reference" && hasValue) o.reference = args[++i];
    else if (a == "--csv" && hasValue) o.csv = args[++i];
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
  const Graded reference = grade(o.reference, config, *request);
  if (!reference.part) {
    std::fprintf(stderr, "klueng-cli class: the reference %s does not run to its end (%s%s)\n", o.reference.c_str(),
                 reference.firstError.c_str(), reference.alarm.c_str());
    return 2;
  }
  std::error_code ec;
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(o.dir, ec))
    if (e.is_regular_file(ec) && !fs::equivalent(e.path(), o.reference, ec)) files.push_back(e.path());
  if (ec && files.empty()) {
    std::fprintf(stderr, "klueng-cli class: cannot read the folder %s: %s\n", o.dir.c_str(), ec.message().c_str());
    return 2;
  }
  std::sort(files.begin(), files.end());
  std::vector<Row> rows;
  int passed = 0;
  for (std::size_t i = 0; i < files.size(); ++i) {
    Row row;
    row.file = files[i].filename().string();
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, files.size(), row.file.c_str());
    try {
      row.graded = grade(files[i].string(), config, *request);
    } catch (const std::exception& ex) {  // one file must never end the batch
      row.graded = Graded{};
      row.graded.errors = 1;
      row.graded.firstError = std::string("internal error: ") + ex.what();
    }
    if (row.graded.part) {
      row.cut = true;
      row.deviation = cut::compareParts(*row.graded.part, *reference.part, o.tolerance);
      row.pass = row.deviation.leftover <= o.tolerance + 1e-9 && row.deviation.gouge <= o.tolerance + 1e-9;
    }
    passed += row.pass ? 1 : 0;
    row.graded.part.reset();  // thirty parts need not stay in memory
    rows.push_back(std::move(row));
  }
  const std::string table = csv(rows);
  if (o.csv.empty()) {
    std::fputs(table.c_str(), stdout);
  } else if (!io::writeTextFileAtomic(o.csv, table, &error)) {
    std::fprintf(stderr, "klueng-cli class: cannot write %s: %s\n", o.csv.c_str(), error.c_str());
    return 1;
  }
  std::fprintf(stderr, "%zu programs: %d pass, %zu fail\n", rows.size(), passed, rows.size() - static_cast<std::size_t>(passed));
  return 0;
}

}  // namespace klueng::cli
