#include "cli_common.h"
#include "klueng/core/job/run_inputs.h"

#include <fmt/format.h>

#include "klueng/core/machine/setup_files.h"
#include "klueng/core/machine/subprogram_files.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "klueng/core/design/dxf_import.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/gcode/dialect_fit.h"
#include "klueng/core/machine/machine_files.h"
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/io/macro_variables.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/io/text_encoding.h"
#include "klueng/core/infer/stock_inference.h"

namespace klueng::cli {

using namespace klueng::core;

Lang langFromLocale() {
  for (const char* name : {"LC_ALL", "LC_MESSAGES", "LANG"}) {
    const char* value = std::getenv(name);
    if (!value || !*value) continue;
    const std::string_view v(value);
    return v.substr(0, 2) == "th" ? Lang::Th : Lang::En;
  }
  return Lang::En;
}

Lang langOfArgs(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::optional<Lang> lang;
    if (args[i] == "--lang" && i + 1 < args.size())
      lang = parseLang(args[i + 1]);
    else if (args[i].rfind("--lang=", 0) == 0)
      lang = parseLang(std::string_view(args[i]).substr(7));
    if (lang) return *lang;
  }
  return langFromLocale();
}

std::string cliText(const char* code, Lang lang, std::vector<std::string> args) {
  return formatMessage(Diagnostic{Severity::Error, code, {}, std::move(args)}, lang);
}

void printCliError(const char* command, const char* code, Lang lang, std::vector<std::string> args) {
  const std::string line =
      fmt::format("klueng-cli{}{}: {}\n", *command ? " " : "", command, cliText(code, lang, std::move(args)));
  std::fwrite(line.data(), 1, line.size(), stderr);
}

int usageError(const char* command, const char* usage, Lang lang, const char* code, std::vector<std::string> args) {
  printCliError(command, code, lang, std::move(args));
  std::fputs(cliText(usage, lang).c_str(), stderr);
  return 2;
}

std::optional<int> parseCommandLine(const char* command, const char* usage, const std::vector<std::string>& args,
                                    const std::vector<CliOption>& options,
                                    const std::function<bool(const std::string&)>& positional) {
  // Mistakes before --lang are already said in its language.
  const Lang lang = langOfArgs(args);
  for (const std::string& a : args) {
    if (a == "--") break;  // a file may be called --help after it
    if (a == "--help" || a == "-h") {
      std::fputs(cliText(usage, lang).c_str(), stdout);
      return 0;
    }
  }
  bool onlyFiles = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    std::string arg = args[i];
    if (!onlyFiles && arg == "--") {
      onlyFiles = true;
      continue;
    }
    if (onlyFiles || arg.size() < 2 || arg[0] != '-') {
      if (!positional(arg)) {
        std::fputs(cliText(usage, lang).c_str(), stderr);
        return 2;
      }
      continue;
    }
    std::optional<std::string> value;  // "--opt=value"
    if (const std::size_t eq = arg.find('='); eq != std::string::npos && arg.rfind("--", 0) == 0) {
      value = arg.substr(eq + 1);
      arg.resize(eq);
    }
    const auto row = std::find_if(options.begin(), options.end(), [&](const CliOption& o) {
      return arg == o.name || (!o.alias.empty() && arg == o.alias);
    });
    if (row == options.end()) return usageError(command, usage, lang, codes::kCliUnknownOption, {arg});
    if (row->takesValue && !value) {
      // `--trace --cycle-time` is --trace without its file, not a file named "--cycle-time".
      const bool nextIsOption = i + 1 < args.size() && args[i + 1].size() > 2 && args[i + 1].rfind("--", 0) == 0;
      if (i + 1 >= args.size() || nextIsOption) return usageError(command, usage, lang, codes::kCliNeedsValue, {arg});
      value = args[++i];
    }
    // `--trace ""` names nothing: the same mistake.
    if (row->takesValue && value->empty()) return usageError(command, usage, lang, codes::kCliNeedsValue, {arg});
    if (!row->takesValue && value) return usageError(command, usage, lang, codes::kCliBadValueAnyOf, {*value, arg});
    if (row->apply(value.value_or(std::string()))) continue;
    if (row->allowed)
      return usageError(command, usage, lang, codes::kCliBadValue, {*value, arg, cliText(row->allowed, lang)});
    return usageError(command, usage, lang, codes::kCliBadValueAnyOf, {*value, arg});
  }
  return std::nullopt;
}

std::vector<CliOption> machineOptions(JobOptions& o) {
  o.lang = langFromLocale();
  return {
      {"--lang",
       {},
       true,
       codes::kCliAllowedLang,
       [&o](const std::string& v) {
         const auto lang = parseLang(v);
         if (lang) o.lang = *lang;
         return lang.has_value();
       }},
      {"--dialect",
       {},
       true,
       codes::kCliAllowedDialect,
       [&o](const std::string& v) {
         const auto dialect = parseDialect(v);
         if (dialect) o.dialect = *dialect;
         o.dialectGiven = true;
         return dialect.has_value();
       }},
      {"--machine",
       {},
       true,
       nullptr,
       [&o](const std::string& v) {
         o.machine = v;
         o.dialectGiven = true;
         return !v.empty();
       }},
      valueOption("--config", o.configDir),
  };
}

std::vector<CliOption> runOptions(JobOptions& o) {
  return {
      {"--stock",
       {},
       true,
       codes::kCliAllowedStock,
       [&o](const std::string& v) {
         o.stock = parseStock(v);
         return o.stock.has_value();
       }},
      {"--units",
       {},
       true,
       codes::kCliAllowedUnits,
       [&o](const std::string& v) {
         o.powerOnUnits = parseUnits(v);
         return o.powerOnUnits.has_value();
       }},
      {"--decimal-point",
       {},
       true,
       codes::kCliAllowedDecimalPoint,
       [&o](const std::string& v) {
         o.calculatorInput = parseDecimalPoint(v);
         return o.calculatorInput.has_value();
       }},
      {"--tool",
       {},
       true,
       nullptr,
       [&o](const std::string& v) {
         o.tools.push_back(v);  // its form and station are checked by jobRequest, in the run's language
         return true;
       }},
  };
}

CliOption flagOption(std::string name, bool& target) {
  return {std::move(name), {}, false, nullptr, [&target](const std::string&) {
            target = true;
            return true;
          }};
}

CliOption valueOption(std::string name, std::string& target, std::string alias) {
  return {std::move(name), std::move(alias), true, nullptr, [&target](const std::string& v) {
            target = v;
            return true;
          }};
}

std::function<bool(const std::string&)> oneFile(const char* command, std::string& target, Lang lang) {
  return [command, &target, lang](const std::string& arg) {
    if (!target.empty()) {
      printCliError(command, codes::kCliOneFile, lang, {target, arg});
      return false;
    }
    target = arg;
    return true;
  };
}

std::optional<Lang> parseLang(std::string_view text) {
  if (text == "en") return Lang::En;
  if (text == "th") return Lang::Th;
  return std::nullopt;
}

std::optional<gcode::Dialect> parseDialect(std::string_view text) {
  gcode::Dialect d{};
  if (gcode::parseDialectId(text, d)) return d;
  return std::nullopt;
}

bool chooseMachine(const std::string& machine, machine::LoadedSetup& config, gcode::Dialect& dialect, Lang lang) {
  if (!machine.empty()) {
    std::vector<FileDiagnostic> why;
    const auto chosen = machine::resolveMachine(machine, why);
    // `--machine deep` when machines/deep.machine is there but did not load: its own
    // errors say why, not "no such machine" (issue 42 item 6).
    if (!chosen && why.size() == 1 && why.front().diagnostic.code == codes::kUnknownMachine) {
      std::vector<FileDiagnostic> own;
      for (const FileDiagnostic& d : config.diagnostics)
        if (std::filesystem::path(d.file).filename() == machine + ".machine") own.push_back(d);
      if (!own.empty()) why = std::move(own);
    }
    for (const FileDiagnostic& d : why) printDiagnostic(stderr, d.file, d.diagnostic, lang);
    if (!chosen) return false;
    dialect = *chosen;
  }
  config.setup.machine = machine::withMachineKeys(config.setup.machine, gcode::machineProfile(dialect));
  return true;
}

gcode::Dialect programMachine(const std::string& file, bool chosen, gcode::Dialect dialect,
                              std::vector<Diagnostic>& warnings, std::optional<io::ProgramFile>* keep) {
  if (chosen) return dialect;
  io::ReadResult<io::ProgramFile> read = io::readProgramFile(file);
  if (!read.value) return dialect;  // the job's own reading reports why
  const gcode::Dialect own = machine::machineOfProgram(*read.value, warnings).value_or(dialect);
  // A read with something to say is read again by the job, which reports it.
  if (keep && read.diagnostics.empty()) *keep = std::move(read.value);
  return own;
}

ProgramArg programArg(const std::string& arg) {
  ProgramArg program{arg == "-" ? std::string(kStdinName) : arg, std::nullopt, std::nullopt};
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(arg, ec);
  const bool stream = arg == "-" || (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
                                     !std::filesystem::is_directory(status));
  if (!stream) return program;
  const std::string path = arg == "-" ? std::string("/dev/stdin") : arg;
  io::ReadResult<io::ProgramFile> read = io::readProgramFile(path);
  for (Diagnostic& d : read.diagnostics)
    for (std::string& a : d.args)
      if (a == path) a = program.name;
  program.file = std::move(read.value);
  program.readDiagnostics = std::move(read.diagnostics);
  return program;
}

void ProgramArg::into(core::job::JobInput& input) const {
  input.path = name;
  if (!readDiagnostics) return;
  input.file = file;
  input.readDiagnostics = readDiagnostics;
  input.folder = std::string();  // a pipe has no folder of subprograms
}

gcode::Dialect programMachine(const ProgramArg& program, bool chosen, gcode::Dialect dialect,
                              std::vector<Diagnostic>& warnings, std::optional<io::ProgramFile>* keep) {
  if (!program.readDiagnostics) return programMachine(program.name, chosen, dialect, warnings, keep);
  if (chosen || !program.file) return dialect;
  return machine::machineOfProgram(*program.file, warnings).value_or(dialect);
}

namespace {
std::optional<double> positiveNumber(std::string_view s) {
  if (s.empty() || s.size() > 32) return std::nullopt;
  const std::string text(s);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !(v > 0.0) || !std::isfinite(v) || text.front() == '+') return std::nullopt;
  return v;
}
}  // namespace

std::optional<io::JobHeader> parseStock(std::string_view text) {
  io::JobHeader h;
  io::LengthUnit unit = io::LengthUnit::Millimetre;
  if (text.size() > 2 && text.substr(text.size() - 2) == "in") {
    unit = io::LengthUnit::Inch;
    text.remove_suffix(2);
  } else if (text.size() > 2 && text.substr(text.size() - 2) == "mm") {
    text.remove_suffix(2);
  }
  std::vector<double> parts;
  while (true) {
    const std::size_t x = text.find_first_of("xX");
    const auto v = positiveNumber(text.substr(0, x));
    if (!v) return std::nullopt;
    parts.push_back(*v);
    if (x == std::string_view::npos) break;
    text.remove_prefix(x + 1);
  }
  if (parts.size() < 2 || parts.size() > 3) return std::nullopt;
  constexpr double kLargestStock = 9999.999;  // as Job details and the header's size lines hold it
  for (const double p : parts)
    if (p > kLargestStock) return std::nullopt;
  h.diameter = parts[0];
  h.length = parts[1];
  h.bore = parts.size() == 3 ? parts[2] : 0.0;
  if (h.bore >= h.diameter) return std::nullopt;
  h.diameterUnit = h.lengthUnit = unit;
  h.stockSource = io::StockSource::CommandLine;
  return h;
}

std::optional<bool> parseDecimalPoint(std::string_view text) {
  if (text == "whole" || text == "calculator") return true;
  if (text == "increments") return false;
  return std::nullopt;
}

std::optional<gcode::InputUnits> parseUnits(std::string_view text) {
  if (text == "mm") return gcode::InputUnits::Millimetre;
  if (text == "inch") return gcode::InputUnits::Inch;
  return std::nullopt;
}

std::string formatNote(const std::string& file, const Diagnostic& d, Lang lang) {
  return formatGccStyle(file, d, lang);
}

std::string formatGccStyle(const std::string& file, const Diagnostic& d, Lang lang) {
  return formatWithPlace(file, d, lang);
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if ((c < 0x20 && c != '\t') || c == 0x7F)
      out += fmt::format("\\x{:02x}", c);
    else
      out += ch;
  }
  return out;
}

void printDiagnostic(std::FILE* out, const std::string& file, const Diagnostic& d, Lang lang) {
  // One diagnostic, one line: a file name holding a line end cannot forge another.
  const std::string line = printable(formatGccStyle(file, d, lang)) + '\n';
  std::fwrite(line.data(), 1, line.size(), out);
}

std::string jsonEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 8);
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) {
      switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
          if (c < 0x20 || c == 0x7F)
            out += fmt::format("\\u{:04x}", c);
          else
            out += static_cast<char>(c);
      }
      ++i;
      continue;
    }
    // Copy a whole valid UTF-8 sequence; replace a broken byte.
    std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
    if (n > 1 && i + n <= text.size() && io::isValidUtf8(text.substr(i, n))) {
      out.append(text.substr(i, n));
      i += n;
    } else {
      out += "\\ufffd";
      ++i;
    }
  }
  return out;
}

std::string diagnosticJson(const std::string& file, const Diagnostic& d, Lang lang) {
  return fmt::format(R"({{"file": "{}", "line": {}, "column": {}, "severity": "{}", "code": "{}", "message": "{}"}})",
                     jsonEscape(file), d.range.line, d.range.column, severityName(d.severity, Lang::En),
                     jsonEscape(d.code), jsonEscape(formatMessage(d, lang)));
}

std::string joinPath(const std::string& dir, std::string_view name) {
  if (dir.empty()) return std::string(name);
  return (std::filesystem::path(dir) / name).string();
}

LoadedConfig loadConfig(const std::string& explicitDir) { return machine::loadMachineSetup(explicitDir, true); }

bool outputsAllowed(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, Lang lang) {
  bool allowed = true;
  for (const std::string& output : outputs) {
    if (output.empty()) continue;
    if (const auto clash = io::outputOverwritesInput(output, inputs)) {
      printDiagnostic(stderr, output, *clash, lang);
      allowed = false;
    } else if (io::isReadOnlyFile(output)) {
      printDiagnostic(stderr, output, Diagnostic{Severity::Error, codes::kFileReadOnly, {}, {output}}, lang);
      allowed = false;
    }
  }
  return allowed;
}

std::vector<std::string> setupFiles(const LoadedConfig& config) { return core::job::setupInputFiles(config); }

std::vector<std::string> programInputs(const std::string& file, const core::job::Job& job, const LoadedConfig& config) {
  return core::job::runInputFiles(file, &job, config);
}

bool reportWrite(const std::string& path, const std::optional<Diagnostic>& failure, Lang lang) {
  if (failure) printDiagnostic(stderr, path, *failure, lang);
  return !failure;
}

bool writeOutput(const std::string& path, std::string_view bytes, Lang lang) {
  return reportWrite(path, io::writeFileAtomic(path, bytes), lang);
}

int stationLimit(const LoadedConfig& config, gcode::Dialect dialect) {
  const int profileLimit = gcode::machineProfile(dialect).maxToolStation;
  return profileLimit > 0 ? std::min(profileLimit, config.setup.tools.stations) : config.setup.tools.stations;
}

std::optional<core::job::JobInput> jobRequest(const LoadedConfig& config, gcode::Dialect dialect,
                                              std::optional<gcode::InputUnits> powerOnUnits,
                                              const std::optional<io::JobHeader>& stock,
                                              const std::vector<std::string>& tools, std::string& error, Lang lang) {
  core::job::JobInput request;
  request.setup = config.setup;
  request.run.dialect = dialect;
  request.run.powerOnUnits = powerOnUnits;
  request.stock = stock;
  request.stations = stationLimit(config, dialect);
  // Without a readable tool table nothing is known about bitmaps: do not check T words against it.
  request.toolTable = !config.unreadable;
  for (const std::string& t : tools) {
    machine::StationOverride o;
    if (!machine::parseStationOverride(t, request.stations, io::shippedToolLibrary(), o, error, lang))
      return std::nullopt;
    request.overrides.push_back(o);
  }
  return request;
}

std::optional<core::design::PartDesign> readPartDrawing(const std::string& path, const std::string& layer,
                                                        double chuckGrip, core::Lang lang) {
  const core::io::ReadResult<std::string> read = core::design::readPartFile(path);
  for (const core::Diagnostic& d : read.diagnostics) printDiagnostic(stderr, path, d, lang);
  if (!read.ok()) return std::nullopt;
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  core::design::DxfImportOptions dxf;
  dxf.chuckGrip = chuckGrip;
  dxf.layer = layer;
  const auto part =
      ext == ".dxf" ? core::design::importDxf(*read.value, path, dxf) : core::design::readPartDesign(*read.value, path);
  for (const core::Diagnostic& d : part.diagnostics) printDiagnostic(stderr, path, d, lang);
  if (!part.ok()) return std::nullopt;
  return *part.value;
}

std::optional<std::vector<core::cut::DrawnDimension>> readDrawnDimensions(const std::string& path,
                                                                          const std::string& layer,
                                                                          const std::string& general, double chuckGrip,
                                                                          core::Lang lang) {
  const std::optional<core::design::PartDesign> part = readPartDrawing(path, layer, chuckGrip, lang);
  if (!part) return std::nullopt;
  return core::design::drawnDimensions(*part, general);
}

}  // namespace klueng::cli
