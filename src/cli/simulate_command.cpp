// klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]
//                          [--lang en|th] [--dialect fanuc|classic]
//                          [--optional-stop] [--block-skip]
//                          [--png out.png] [--profile out.csv] [--json summary.json] [--resolution MM]
//                          [--no-stock]   (interpret only: no cutting, no stock collisions)
// Checks the program (errors -> printed, exit 1), runs it into a Timeline and
// writes what was asked for. An alarm is printed like a diagnostic
// (FILE:LINE:COL: alarm A104: ...) and gives exit 1; the trace up to it is
// still written.
#include <fmt/format.h>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "cut_outputs.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/machine/trace.h"
#include "klueng/core/messages.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

struct SimulateOptions {
  std::string file;
  std::string tracePath;
  bool cycleTime = false;
  std::string configDir;
  Lang lang = Lang::En;
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  bool optionalStop = false;
  bool blockSkip = false;
  CutOutputOptions cut;  // --png --profile --json --resolution (cut_outputs.h)
};

// One row per option: name, whether it takes a value, what it does. New
// outputs (--png, --json, ...) add a row here and a step in runSimulate.
struct OptionSpec {
  const char* name;
  bool takesValue;
  std::function<bool(SimulateOptions&, const std::string&)> apply;  // false: bad value
};

const std::vector<OptionSpec>& optionSpecs() {
  static const std::vector<OptionSpec> specs = {
      {"--trace", true, [](SimulateOptions& o, const std::string& v) { o.tracePath = v; return true; }},
      {"--cycle-time", false, [](SimulateOptions& o, const std::string&) { o.cycleTime = true; return true; }},
      {"--config", true, [](SimulateOptions& o, const std::string& v) { o.configDir = v; return true; }},
      {"--lang", true,
       [](SimulateOptions& o, const std::string& v) {
         if (v != "en" && v != "th") return false;
         o.lang = v == "th" ? Lang::Th : Lang::En;
         return true;
       }},
      {"--dialect", true,
       [](SimulateOptions& o, const std::string& v) {
         if (v != "fanuc" && v != "classic") return false;
         o.dialect = v == "classic" ? gcode::Dialect::Classic : gcode::Dialect::Fanuc;
         return true;
       }},
      {"--optional-stop", false, [](SimulateOptions& o, const std::string&) { o.optionalStop = true; return true; }},
      {"--block-skip", false, [](SimulateOptions& o, const std::string&) { o.blockSkip = true; return true; }},
      {"--png", true, [](SimulateOptions& o, const std::string& v) { o.cut.pngPath = v; return true; }},
      {"--profile", true, [](SimulateOptions& o, const std::string& v) { o.cut.profilePath = v; return true; }},
      {"--json", true, [](SimulateOptions& o, const std::string& v) { o.cut.jsonPath = v; return true; }},
      {"--no-stock", false, [](SimulateOptions& o, const std::string&) { o.cut.enabled = false; return true; }},
      {"--resolution", true,
       [](SimulateOptions& o, const std::string& v) { return parseResolution(v, o.cut.resolution); }},
  };
  return specs;
}

std::optional<SimulateOptions> parseOptions(const std::vector<std::string>& args) {
  SimulateOptions o;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0) {
      if (!o.file.empty()) {
        std::fprintf(stderr, "klueng-cli simulate: only one FILE (got '%s' and '%s')\n", o.file.c_str(), a.c_str());
        return std::nullopt;
      }
      o.file = a;
      continue;
    }
    const OptionSpec* spec = nullptr;
    for (const auto& s : optionSpecs())
      if (a == s.name) spec = &s;
    if (!spec) {
      std::fprintf(stderr, "klueng-cli simulate: unknown option '%s'\n", a.c_str());
      return std::nullopt;
    }
    std::string value;
    if (spec->takesValue) {
      if (i + 1 >= args.size()) {
        std::fprintf(stderr, "klueng-cli simulate: %s needs a value\n", a.c_str());
        return std::nullopt;
      }
      value = args[++i];
    }
    if (!spec->apply(o, value)) {
      std::fprintf(stderr, "klueng-cli simulate: bad value '%s' for %s\n", value.c_str(), a.c_str());
      return std::nullopt;
    }
  }
  if (o.file.empty()) {
    std::fputs("usage: klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
               "                              [--lang en|th] [--dialect fanuc|classic]\n"
               "                              [--optional-stop] [--block-skip]\n"
               "                              [--png out.png] [--profile out.csv] [--json summary.json]\n"
               "                              [--resolution MM] [--no-stock]\n",
               stderr);
    return std::nullopt;
  }
  return o;
}

// FILE:LINE:COL: severity CODE: message
void printDiagnostic(const std::string& file, const Diagnostic& d, Lang lang) {
  std::string where = file;
  if (d.range.line > 0) where += fmt::format(":{}:{}", d.range.line, d.range.column);
  std::fprintf(stderr, "%s: %s %s: %s\n", where.c_str(), std::string(severityName(d.severity, lang)).c_str(),
               d.code.c_str(), formatMessage(d, lang).c_str());
}

// Prints every diagnostic; true when none is an error.
bool report(const std::string& file, const std::vector<Diagnostic>& diags, Lang lang) {
  for (const auto& d : diags) printDiagnostic(file, d, lang);
  return !hasErrors(diags);
}

std::string joinPath(const std::string& dir, const char* name) {
  if (dir.empty()) return name;
  return dir.back() == '/' ? dir + name : dir + "/" + name;
}

}  // namespace

int runSimulate(const std::vector<std::string>& args) {
  const std::optional<SimulateOptions> parsed = parseOptions(args);
  if (!parsed) return 2;
  const SimulateOptions& o = *parsed;

  // The machine files first: the checker needs to know which tools have a bitmap.
  const std::string dir = io::findConfigDir(o.configDir);
  machine::MachineSetup setup;
  const std::string toolsPath = joinPath(dir, "tools.cfg");
  const std::string offsetsPath = joinPath(dir, "offset.cfg");
  const std::string machinePath = joinPath(dir, "machine.cfg");
  auto tools = io::readToolTable(toolsPath);
  auto offsets = io::readOffsetTable(offsetsPath);
  auto machineCfg = io::readMachineConfig(machinePath);
  bool configOk = report(toolsPath, tools.diagnostics, o.lang);
  configOk = report(offsetsPath, offsets.diagnostics, o.lang) && configOk;
  configOk = report(machinePath, machineCfg.diagnostics, o.lang) && configOk;
  if (!configOk || !tools.value || !offsets.value || !machineCfg.value) return 1;
  setup.tools = *tools.value;
  setup.offsets = *offsets.value;
  setup.machine = *machineCfg.value;

  const auto file = io::readProgramFile(o.file);
  if (!report(o.file, file.diagnostics, o.lang) || !file.value) return 1;
  const gcode::Program program = gcode::parse(file.value->gcode, file.value->gcodeFirstLine);
  gcode::CheckOptions checkOptions;
  checkOptions.dialect = o.dialect;
  std::vector<int> withBitmap;
  for (int t = 1; t <= io::kToolCount; ++t)
    if (!setup.tools.bitmap[static_cast<std::size_t>(t - 1)].empty()) withBitmap.push_back(t);
  checkOptions.toolsWithBitmap = withBitmap;
  if (!report(o.file, gcode::check(program, checkOptions), o.lang)) return 1;

  machine::RunOptions runOptions;
  runOptions.dialect = o.dialect;
  runOptions.optionalStop = o.optionalStop;
  runOptions.blockSkip = o.blockSkip;
  const machine::Timeline timeline = machine::interpret(program, setup, runOptions);

  if (!o.tracePath.empty()) {
    std::string error;
    if (!io::writeTextFileAtomic(o.tracePath, machine::formatTraceCsv(timeline), &error)) {
      std::fprintf(stderr, "klueng-cli simulate: cannot write %s: %s\n", o.tracePath.c_str(), error.c_str());
      return 1;
    }
  }
  // The stock: collisions stop the run on their block (SPEC 8), and the cut outputs.
  const CutOutcome cut = o.cut.enabled ? runCut(o.file, file.value->header, setup, timeline, o.cut) : CutOutcome{};
  for (const auto& d : cut.toolErrors) printDiagnostic(o.file, d, o.lang);
  if (o.cycleTime) std::printf("%.4f\n", timeline.cycleTime());
  if (cut.alarm) {
    printDiagnostic(o.file, *cut.alarm, o.lang);
    return 1;
  }
  if (!cut.written) return 1;
  if (timeline.alarm) {
    printDiagnostic(o.file, *timeline.alarm, o.lang);
    return 1;
  }
  return 0;
}

}  // namespace klueng::cli
