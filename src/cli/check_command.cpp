// klueng-cli check FILE|FOLDER... [--lang en|th] [--dialect fanuc|haas|classic] [--json]
//                                 [--config DIR] [--summary] [--stock DxL[xBORE][in]] [--units mm|inch]
//                                 [--tool N=ID]... [--design PART.json|PART.dxf]
// Reads each program, parses and checks it (SPEC 3-5, 13) against the tool
// table found by findConfigDir, and prints every diagnostic: one GCC-style
// line each, or one JSON array for all files. A file without a job header
// gets a note saying where its stock comes from (--stock, or inferred). Tools
// the program names in comments or cycles come from the library (a note says
// which; --tool N=ID sets a station for this run); T words naming stations
// still without a tool are E305. Exit 0 = no errors, 1 = errors in a program,
// The cutting-data warnings (W330-W336, docs/cutting-data.md) come with the check's own,
// measured on the run the check records; --design gives W332 the part's roughness marks.
// 2 = a file could not be read, a setup file (machine.cfg, tools.cfg,
// offset.cfg, a tool bitmap) has errors, or the command line is wrong.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "batch_memory.h"
#include "cli_common.h"
#include "klueng/core/machine/machine_files.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/folder_files.h"
#include "klueng/core/job/job.h"
#include "commands.h"

namespace klueng::cli {

namespace {

using namespace klueng::core;

struct CheckOptions : JobOptions {
  std::vector<std::string> files;
  bool json = false;
  bool summary = false;
  std::string design;  // --design PART.json|PART.dxf: its roughness marks judge the finishing feeds (W332)
};

// A --tool choice refused once the turret is known (a text already in `lang`), then the usage.
int toolChoiceError(Lang lang, const std::string& text) {
  std::fprintf(stderr, "klueng-cli check: %s\n%s", text.c_str(), cliText(codes::kCliCheckUsage, lang).c_str());
  return 2;
}

// The command line by check's option table (cli_common.h). Returns an exit code to stop with.
std::optional<int> parseArgs(const std::vector<std::string>& args, CheckOptions& o) {
  std::vector<CliOption> options = machineOptions(o);
  for (CliOption& row : runOptions(o)) options.push_back(std::move(row));
  options.push_back(flagOption("--json", o.json));
  options.push_back(flagOption("--summary", o.summary));
  options.push_back(valueOption("--design", o.design));
  const auto file = [&o](const std::string& arg) {
    o.files.push_back(arg);
    return true;
  };
  if (const auto exit = parseCommandLine("check", codes::kCliCheckUsage, args, options, file)) return exit;
  if (o.files.empty()) return usageError("check", codes::kCliCheckUsage, o.lang, codes::kCliNoFile);
  return std::nullopt;
}

// One file to check: a named one, or an entry of a named folder.
struct CheckedFile {
  std::string path;
  bool inFolder = false;              // read as a folder run: only a G-code program is parsed
  std::optional<Diagnostic> refusal;  // a folder entry not read (a link out of it, a pipe...)
};

// A folder stands for the program files in it (not its subfolders), sorted by name; an entry
// that is not read (io::folderEntryRefusal) is listed with why, so it is never left out silently.
std::vector<CheckedFile> expandFolders(const std::vector<std::string>& args) {
  namespace fs = std::filesystem;
  std::vector<CheckedFile> files;
  for (const std::string& arg : args) {
    std::error_code ec;
    if (!fs::is_directory(arg, ec)) {
      files.push_back({arg, false, std::nullopt});
      continue;
    }
    const std::vector<io::FolderEntry> entries = io::programFolderEntries(arg);
    if (entries.empty()) files.push_back({arg, false, std::nullopt});  // reported as unreadable (a folder)
    for (const io::FolderEntry& e : entries) files.push_back({e.path, true, io::folderEntryRefusal(e)});
  }
  return files;
}

struct FileSummary {
  std::string file;
  int errors = 0;
  int warnings = 0;
  bool unreadable = false;
};

void printSummary(const std::vector<FileSummary>& rows, Lang lang) {
  const auto text = [lang](const char* code) { return cliText(code, lang); };
  std::size_t width = 4;
  for (const auto& r : rows) width = std::max(width, printable(r.file).size());
  std::string out =
      fmt::format("\n{:<{}}  {:>6}  {:>8}  {}\n", text(codes::kCliSummaryFile), width, text(codes::kCliSummaryErrors),
                  text(codes::kCliSummaryWarnings), text(codes::kCliSummaryResult));
  for (const auto& r : rows) {
    const std::string result = text(r.unreadable ? codes::kCliSummaryUnreadable
                                    : r.errors   ? codes::kCliSummaryFail
                                                 : codes::kCliSummaryOk);
    out += fmt::format("{:<{}}  {:>6}  {:>8}  {}\n", printable(r.file), width, r.errors, r.warnings, result);
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
}

}  // namespace

int runCheck(const std::vector<std::string>& args) {
  CheckOptions o;
  if (const auto exit = parseArgs(args, o)) return *exit;

  LoadedConfig config = loadConfig(o.configDir);
  if (!chooseMachine(o.machine, config, o.dialect, o.lang)) return 2;
  std::string error;
  std::optional<core::job::JobInput> request =
      jobRequest(config, o.dialect, o.powerOnUnits, o.stock, o.tools, error, o.lang);
  if (!request) return toolChoiceError(o.lang, error);
  request->calculatorInput = o.calculatorInput;
  if (!o.design.empty()) {
    const std::optional<design::PartDesign> part =
        readPartDrawing(o.design, {}, config.setup.machine.chuckGrip, o.lang);
    if (!part) return 2;  // said, on its line
    request->finishMarks = design::finishMarks(*part);
  }

  std::vector<FileDiagnostic> all = config.diagnostics;
  bool anyError = false;
  // A setup file that cannot be read or holds a wrong value is the machine's fault, not the program's: exit 2.
  bool anyUnreadable = config.unreadable || config.hasErrors();
  std::vector<FileSummary> summary;
  std::vector<FileDiagnostic> notes;  // each file's tool choices and where its stock comes from

  const std::vector<CheckedFile> files = expandFolders(o.files);
  for (const CheckedFile& file : files) {
    const ProgramArg program =
        file.inFolder ? ProgramArg{file.path, std::nullopt, std::nullopt} : programArg(file.path);
    const std::string& path = program.name;
    if (file.refusal) {
      all.push_back({path, *file.refusal});
      summary.push_back(FileSummary{path, 1, 0, true});
      anyUnreadable = true;
      continue;
    }
    // A program that names its machine is checked on it (the setup with that machine's keys).
    std::vector<Diagnostic> machineWarnings;
    std::optional<io::ProgramFile> read;  // a file read once, for the machine and the job
    const gcode::Dialect own = programMachine(program, o.dialectGiven, o.dialect, machineWarnings, &read);
    core::job::JobInput input = *request;
    program.into(input);
    if (read) input.file = std::move(read);
    input.folderRun = file.inFolder;
    if (own != o.dialect) {
      input.run.dialect = own;
      input.stations = stationLimit(config, own);
      input.setup.machine = machine::withMachineKeys(config.setup.machine, gcode::machineProfile(own));
    }
    std::shared_ptr<const core::job::Job> job = core::job::makeJob(std::move(input));
    for (const Diagnostic& n : job->toolNotes()) notes.push_back({path, n});
    for (const Diagnostic& n : job->stockNotes()) notes.push_back({path, n});
    FileSummary row{path};
    for (const Diagnostic& d : machineWarnings) {
      ++row.warnings;
      all.push_back({path, d});
    }
    for (const Diagnostic& d : job->diagnostics()) {
      if (isError(d.severity))
        ++row.errors;
      else if (d.severity == Severity::Warning)
        ++row.warnings;
      all.push_back({job->fileOf(d), d});
    }
    row.unreadable = job->unreadable();
    anyUnreadable = anyUnreadable || job->unreadable();
    anyError = anyError || row.errors > 0;
    summary.push_back(row);
    if (&file == &files.back()) keepUntilExit(std::move(job));
  }

  if (o.json) {
    // The stock and tool notes stay out of the array (they describe the run,
    // not the program); the checker's own notes (I102) are in it.
    std::string out = "[";
    for (std::size_t i = 0; i < all.size(); ++i)
      out += (i ? ",\n  " : "\n  ") + diagnosticJson(all[i].file, all[i].diagnostic, o.lang);
    out += all.empty() ? "]\n" : "\n]\n";
    std::fwrite(out.data(), 1, out.size(), stdout);
  } else {
    for (const FileDiagnostic& f : all) printDiagnostic(stdout, f.file, f.diagnostic, o.lang);
    for (const FileDiagnostic& n : notes) printDiagnostic(stdout, n.file, n.diagnostic, o.lang);
    if (o.summary) printSummary(summary, o.lang);
  }
  std::fflush(stdout);
  return anyUnreadable ? 2 : anyError ? 1 : 0;
}

}  // namespace klueng::cli
