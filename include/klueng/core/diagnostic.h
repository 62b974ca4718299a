#pragma once
// Errors are data: a stable code plus arguments. The core never builds user
// text itself; messages.h turns a Diagnostic into English or Thai.
#include <string>
#include <vector>

namespace klueng::core {

// Note: information for the user (where the stock came from, which dialect
// fits); never stops a check or a run.
enum class Severity { Warning, Error, Alarm, Note };

// Errors and alarms stop a run; warnings and notes do not.
constexpr bool isError(Severity s) { return s == Severity::Error || s == Severity::Alarm; }

// A place in a source file. line is 1-based in the whole file (header lines
// included); column is the 1-based index of the Unicode code point; length in
// code points (0 when it marks a point, not a word).
struct SourceRange {
  int line = 0;
  int column = 0;
  int length = 0;
  int file = 0;  // 0 = the program; else a subprogram file (gcode::Program::files)
  friend bool operator==(const SourceRange&, const SourceRange&) = default;
};

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;  // stable, e.g. "E104", "A203", "F012"
  SourceRange range;
  std::vector<std::string> args;  // fill the {0} {1} ... of the catalog's text
};

// Code ranges, one catalog file per module (src/core/base/messages_*.cpp):
//   E1xx word formats and lexical errors (SPEC 3-4)       gcode
//   E2nn block rule nn of SPEC 5 (E201 = rule 1 ... E213)  gcode
//   E3xx "ext" block rules (arcs, comp, tool table)         gcode
//   W1xx warnings of the checker                            gcode
//   F1xx file formats: program header, tools.cfg,
//        offset.cfg, machine.cfg, bitmaps                   io
//   A1xx run-time alarms of the interpreter (SPEC 8)        machine
//   A2xx nose radius compensation alarms                    comp
//   A3xx alarms that need the stock (collisions, cutting)   cut
//   I1xx informational notes (e.g. G28 without axes)        any
//   I4xx tools chosen from the program (notes)              io
//   F18x part design files, E5xx parts the generator cannot turn   design

bool hasErrors(const std::vector<Diagnostic>& diags);

// The order every list of diagnostics is shown in: by file, line and column;
// those at one place keep the order they were found in.
void sortByPlace(std::vector<Diagnostic>& diags);

}  // namespace klueng::core
