#pragma once
// Helpers shared by klueng-cli's commands: language and dialect options,
// loading the machine files and programs, and printing diagnostics in GCC
// style or as JSON.
#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/image.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/tool_inference.h"
#include "klueng/core/messages.h"

namespace klueng::cli {

// Thai when the first set of LC_ALL, LC_MESSAGES, LANG starts with "th", else English.
core::Lang langFromLocale();
std::optional<core::Lang> parseLang(std::string_view text);                  // "en" | "th"
std::optional<core::gcode::Dialect> parseDialect(std::string_view text);     // "fanuc" | "classic"

// A diagnostic with the file it belongs to (a program, a cfg file, a bitmap).
struct FileDiagnostic {
  std::string file;
  core::Diagnostic diagnostic;
};

// `FILE:LINE:COL: error E104: message` (`FILE: ...` when the line is unknown), no newline.
std::string formatGccStyle(const std::string& file, const core::Diagnostic& d, core::Lang lang);
void printDiagnostic(std::FILE* out, const std::string& file, const core::Diagnostic& d, core::Lang lang);

// JSON string contents (without quotes): escapes quotes, backslashes and
// control characters; invalid UTF-8 bytes become U+FFFD.
std::string jsonEscape(std::string_view text);
// {"file":...,"line":...,"column":...,"severity":"error","code":...,"message":...}
// severity is always English (for machines); the message is in `lang`.
std::string diagnosticJson(const std::string& file, const core::Diagnostic& d, core::Lang lang);

std::string joinPath(const std::string& dir, std::string_view name);

// True for diagnostics meaning "the file could not be read at all"
// (missing, a folder, no access, over 64 MB): klueng-cli exits 2 on them.
bool isUnreadable(const core::Diagnostic& d);

// tools.cfg, offset.cfg, machine.cfg (optional: defaults when absent) and the
// tool bitmaps, from findConfigDir(explicitDir).
struct LoadedConfig {
  std::string dir;
  core::io::ToolTable tools;
  core::io::OffsetTable offsets;
  core::io::MachineConfig machine;
  std::array<std::optional<core::io::RgbImage>, core::io::kToolCount> bitmaps;  // [0] = tool 01
  std::vector<FileDiagnostic> diagnostics;
  bool unreadable = false;  // tools.cfg or offset.cfg could not be read
  bool hasErrors() const;
  // Tools whose bitmap exists and decodes, for gcode::CheckOptions.
  std::vector<int> toolsWithBitmap() const;
};
LoadedConfig loadConfig(const std::string& explicitDir = {});

// Tools from the program (core/machine/tool_inference.h) for one program: the
// setup with the library's choices and the --tool overrides, the stations that
// then have a tool (for the checker's E305), and the notes to print.
struct JobTools {
  core::machine::MachineSetup setup;
  std::vector<int> toolsWithBitmap;
  std::vector<core::Diagnostic> notes;  // I401..I410
};
JobTools inferJobTools(const LoadedConfig& config, const std::string& programPath, core::gcode::Dialect dialect,
                       const std::vector<core::machine::StationOverride>& overrides);
// The highest station a T word may name: the dialect's limit, else the turret.
int stationLimit(const LoadedConfig& config, core::gcode::Dialect dialect);
// `FILE:LINE: note: message` (`FILE: note: ...` without a line), no newline; Thai "หมายเหตุ".
std::string formatNote(const std::string& file, const core::Diagnostic& d, core::Lang lang);

// Reads, parses and checks one program. diagnostics holds the file's own
// (header, encoding) and the checker's, sorted by line and column.
struct CheckedProgram {
  std::string path;
  std::optional<core::io::ProgramFile> file;
  std::vector<core::Diagnostic> diagnostics;
  bool unreadable = false;
};
CheckedProgram checkProgramFile(const std::string& path, const core::gcode::CheckOptions& options,
                                const core::io::JobHeader& defaultsForPlain = {});

}  // namespace klueng::cli
