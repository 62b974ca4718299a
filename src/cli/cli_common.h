#pragma once
// Helpers shared by klueng-cli's commands: language and dialect options,
// loading the machine files and programs, and printing diagnostics in GCC
// style or as JSON.
#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/cut/inspection.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/image.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/infer/tool_inference.h"
#include "klueng/core/messages.h"

namespace klueng::cli {

// Thai when the first set of LC_ALL, LC_MESSAGES, LANG starts with "th", else English.
core::Lang langFromLocale();
// The language of a command's own texts: its `--lang en|th` (`--lang=th`) wherever
// it stands on the command line, so that a mistake before it is already said in
// that language; else langFromLocale().
core::Lang langOfArgs(const std::vector<std::string>& args);
// klueng-cli's own text `code` (messages_cli.cpp, codes::kCli*) in `lang`.
std::string cliText(const char* code, core::Lang lang, std::vector<std::string> args = {});
// "klueng-cli COMMAND: <text>\n" on stderr.
void printCliError(const char* command, const char* code, core::Lang lang, std::vector<std::string> args = {});

// One row of a command's option table (issue 30 item 5). Every command parses its
// command line with parseCommandLine over its own rows, so the forms ("--opt v",
// "--opt=v", "--" before file names, --help), the mistakes, their two languages
// and exit 2 are the same everywhere; the rows for the options that several
// commands share are made by the functions below, once.
struct CliOption {
  std::string name;                               // "--stock"
  std::string alias;                              // "-o", or empty
  bool takesValue = false;                        // a flag takes none
  const char* allowed = nullptr;                  // kCliAllowed*: what a refused value may be
  std::function<bool(const std::string&)> apply;  // false: the value is refused
};
// What several commands share: the language, the machine, the setup folder, the run's inputs.
struct JobOptions {
  core::Lang lang = core::Lang::En;
  core::gcode::Dialect dialect = core::gcode::Dialect::Fanuc;
  bool dialectGiven = false;                 // --dialect or --machine: wins over the machine a program names
  std::string machine;                       // --machine NAME|FILE, resolved once the machines folders are read
  std::string configDir;                     // --config DIR
  std::optional<core::io::JobHeader> stock;  // --stock
  std::optional<core::gcode::InputUnits> powerOnUnits;  // --units
  std::optional<bool> calculatorInput;                  // --decimal-point
  std::vector<std::string> tools;                       // --tool N=ID, checked once the turret size is known
};
// --lang --dialect --machine --config: every command's rows.
std::vector<CliOption> machineOptions(JobOptions& o);
// --stock --units --decimal-point --tool: the rows of the commands that run a program.
std::vector<CliOption> runOptions(JobOptions& o);
CliOption flagOption(std::string name, bool& target);
CliOption valueOption(std::string name, std::string& target, std::string alias = {});
// A positional argument handler taking one file into `target` (a second: kCliOneFile).
std::function<bool(const std::string&)> oneFile(const char* command, std::string& target, core::Lang lang);

// Parses `args` by `options`; `positional` takes the other arguments (false: it said why).
// Returns nullopt to go on, else the exit status: 0 after printing the usage (`usage`, a
// kCli*Usage code) for --help or -h, 2 after a mistake and the usage on stderr.
std::optional<int> parseCommandLine(const char* command, const char* usage, const std::vector<std::string>& args,
                                    const std::vector<CliOption>& options,
                                    const std::function<bool(const std::string&)>& positional);
// A mistake found after parsing (a missing file...): the message, the usage, 2.
int usageError(const char* command, const char* usage, core::Lang lang, const char* code,
               std::vector<std::string> args = {});

// A part design (JSON, or a DXF's outline on `layer`) read as its drawn
// dimensions with their tolerances (`general`: an ISO 2768 class for the ones
// without); nullopt after printing why (the file's own located messages).
std::optional<core::design::PartDesign> readPartDrawing(const std::string& path, const std::string& layer,
                                                        double chuckGrip, core::Lang lang);
std::optional<std::vector<core::cut::DrawnDimension>> readDrawnDimensions(const std::string& path,
                                                                          const std::string& layer,
                                                                          const std::string& general, double chuckGrip,
                                                                          core::Lang lang);
std::optional<core::Lang> parseLang(std::string_view text);               // "en" | "th"
std::optional<core::gcode::Dialect> parseDialect(std::string_view text);  // "fanuc" | "classic"
// --machine NAME|FILE (issue 27), once the setup (and with it the machines
// folders) is read: the machine into `dialect` and its machine.cfg keys into the
// setup. Empty `machine`: the dialect stays, only its keys apply. false after
// printing the located reasons (the caller exits 2).
bool chooseMachine(const std::string& machine, core::machine::LoadedSetup& config, core::gcode::Dialect& dialect,
                   core::Lang lang);
// The machine a program names at its head, `(MACHINE: romi-gl240m)` (Job details
// writes it), runs it unless --machine or --dialect chose one (`chosen`); else
// `dialect`. A machine that is not loaded: `dialect`, and warning F205 in `warnings`.
// `keep`, when given, receives the program as read when reading it said nothing (no
// diagnostic): the caller hands it to makeJob (JobInput::file), so the file is read once.
core::gcode::Dialect programMachine(const std::string& file, bool chosen, core::gcode::Dialect dialect,
                                    std::vector<core::Diagnostic>& warnings,
                                    std::optional<core::io::ProgramFile>* keep = nullptr);

// The name a program read from standard input (`check -`: an editor's linter pipes
// its buffer) goes by in every message, as GCC names it.
inline constexpr const char* kStdinName = "<stdin>";
// A program named on the command line (issue 42 item 4). One that is not an
// ordinary file — `-` (standard input), /dev/stdin, a shell's <(cmd), a named
// pipe — is read here, once, since a pipe cannot be read twice (a named pipe is
// refused unopened, F157); an ordinary file is left to the job, which reads it.
struct ProgramArg {
  std::string name;                           // what the messages say: the argument, kStdinName for "-"
  std::optional<core::io::ProgramFile> file;  // read here
  std::optional<std::vector<core::Diagnostic>> readDiagnostics;  // set when read here
  // The program into a job's input: its path (name), what was read, and no folder of
  // subprograms for a stream (it has none).
  void into(core::job::JobInput& input) const;
};
ProgramArg programArg(const std::string& arg);
// programMachine for a program that may have been read already.
// A regular file read for its machine is kept in `keep` (when given) for the job.
core::gcode::Dialect programMachine(const ProgramArg& program, bool chosen, core::gcode::Dialect dialect,
                                    std::vector<core::Diagnostic>& warnings,
                                    std::optional<core::io::ProgramFile>* keep = nullptr);

// --stock DxL[xBORE][in]: "50x100", "2.1x4in", "118x80x90" (Ø118 tube, 80 long,
// Ø90 bore). 0 < D, L <= 9999.999 (what a header line and Job details hold: a
// 1e308 bar would take minutes to draw and measure), 0 < BORE < D; mm unless
// "in". stockSource = CommandLine.
std::optional<core::io::JobHeader> parseStock(std::string_view text);
// --units mm|inch: the power-on units (before any G20/G21).
std::optional<core::gcode::InputUnits> parseUnits(std::string_view text);
// --decimal-point whole|increments: how lengths without a decimal point are
// read (true = whole units, calculator-type input; false = least increments).
std::optional<bool> parseDecimalPoint(std::string_view text);
// What the options accept, for the exit-2 messages: cliText(kCliAllowed*, lang).

// `FILE:LINE:COL: note I152: message` (`FILE: note ...` without a line), no newline; Thai "หมายเหตุ".
std::string formatNote(const std::string& file, const core::Diagnostic& d, core::Lang lang);

// A diagnostic with the file it belongs to (a program, a cfg file, a bitmap).
using FileDiagnostic = core::machine::SetupDiagnostic;

// `FILE:LINE:COL: error E104: message` (`FILE: ...` when the line is unknown), no newline.
std::string formatGccStyle(const std::string& file, const core::Diagnostic& d, core::Lang lang);
// Prints one line: printable(formatGccStyle(...)).
void printDiagnostic(std::FILE* out, const std::string& file, const core::Diagnostic& d, core::Lang lang);
// `text` with line ends and other control characters escaped (\n, \r, \x1b; tabs and UTF-8
// kept), so that a file name holding a newline cannot forge a line of output (issue 42).
std::string printable(std::string_view text);

// JSON string contents (without quotes): escapes quotes, backslashes and
// control characters; invalid UTF-8 bytes become U+FFFD.
std::string jsonEscape(std::string_view text);
// {"file":...,"line":...,"column":...,"severity":"error","code":...,"message":...}
// severity is always English (for machines); the message is in `lang`.
std::string diagnosticJson(const std::string& file, const core::Diagnostic& d, core::Lang lang);

std::string joinPath(const std::string& dir, std::string_view name);

// True for diagnostics meaning "the file could not be read at all"
// (missing, a folder, no access, over 64 MB): klueng-cli exits 2 on them.
using core::machine::isUnreadable;

// tools.cfg, offset.cfg, machine.cfg and the tool bitmaps, from
// findConfigDir(explicitDir): the core's one reader of a setup.
using LoadedConfig = core::machine::LoadedSetup;
LoadedConfig loadConfig(const std::string& explicitDir = {});

// Issue 29, checked before any work: an output option naming an input (the
// program, a subprogram file, the reference, a graded file, the part file, a
// setup file) would destroy it (F126); a read-only output is refused (F119).
// Prints each; true when there is none. Empty names are skipped.
bool outputsAllowed(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs, core::Lang lang);
// Every file a run with `config` reads (core::job::setupInputFiles: the setup tables,
// macro_variables.cfg, the tool pictures, the library, the cutting speeds, the machine files): inputs too.
std::vector<std::string> setupFiles(const LoadedConfig& config);
// What a run of `file` read: the program, its subprogram files and the setup files.
std::vector<std::string> programInputs(const std::string& file, const core::job::Job& job, const LoadedConfig& config);
// Writes with core/io/file_write.h; on failure prints the diagnostic (F1xx,
// path and reason, in `lang`) and returns false. The old file keeps its bytes.
bool writeOutput(const std::string& path, std::string_view bytes, core::Lang lang);
// Prints a write failure (nullopt: nothing) as writeOutput does; true when there was none.
bool reportWrite(const std::string& path, const std::optional<core::Diagnostic>& failure, core::Lang lang);

// The highest station a T word may name: the dialect's limit, else the turret.
int stationLimit(const LoadedConfig& config, core::gcode::Dialect dialect);

// What check, simulate, print and class ask of job::makeJob (the path left to
// set): the setup, the run's dialect and units, --stock, and the --tool N=ID
// choices (checked against the turret).
// nullopt with `error` set when a --tool choice is refused (exit 2).
std::optional<core::job::JobInput> jobRequest(const LoadedConfig& config, core::gcode::Dialect dialect,
                                              std::optional<core::gcode::InputUnits> powerOnUnits,
                                              const std::optional<core::io::JobHeader>& stock,
                                              const std::vector<std::string>& tools, std::string& error,
                                              core::Lang lang = core::Lang::En);

}  // namespace klueng::cli
