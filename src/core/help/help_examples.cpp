// Worked examples for the help (issue 11). Most codes show best inside one
// small job: face, one turning pass, the code, retract, end. Motion codes,
// cycles and calls need a program of their own; those are written out here in
// the habits of shop programs (G50 limit before G96, retract before a tool
// change, G97 for threads). Every example runs clean: tests/core/help/help_test.cpp.
#include <array>
#include <string>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/help/help.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::machine {

namespace {

using gcode::Dialect;

constexpr std::string_view kStart =
    "O0001\n"
    "G21 G40\n"
    "G99\n"
    "G50 S2500\n"
    "T0101 (outside turning tool)\n"
    "G96 S180 M03\n"
    "G00 X52. Z2. M08\n"
    "G01 X48. F0.2\n"
    "Z-30.\n"
    "X52.\n"
    "G00 Z2.\n";
constexpr std::string_view kEnd = "G00 X100. Z100. M09\nM30\n";

// Where a one-line code goes in the small job.
enum class Slot {
  Running,  // after the turning pass, the spindle still turning
  Stopped,  // after M05: codes that want the spindle at rest
  End,      // the code ends the program itself
};

struct Example {
  char letter;
  int number;
  std::uint8_t dialects;  // bits of gcode::dialectBit; 0 = all
  std::string_view body;  // between kStart and kEnd, or the whole program when it starts with 'O'
};

constexpr std::uint8_t kF = 1u << static_cast<int>(Dialect::Fanuc);
constexpr std::uint8_t kH = 1u << static_cast<int>(Dialect::Haas);
constexpr std::uint8_t kC = 1u << static_cast<int>(Dialect::Classic);

// Threads: the threading tool at constant rpm (G32/G92/G76 want G97).
#define KLUENG_THREAD_TOOL "G00 X100. Z100.\nT0303 (threading tool 60 deg)\nG97 S800 M03\n"
#define KLUENG_DRILL "G00 X100. Z100.\nT0606 (drill 10 mm)\nG97 S800 M03\nG00 X0. Z5.\n"
#define KLUENG_GROOVE "G00 X100. Z100.\nT0404 (grooving tool 3 mm)\nG97 S600 M03\nG00 X52. Z-15.\n"
#define KLUENG_PROFILE "N10 G00 X30.\nG01 Z-20.\nX40. Z-30.\nZ-45.\nN20 X52.\n"
#define KLUENG_FACE_PROFILE "N10 G00 Z-6.\nG01 X30.\nX20. Z-1.\nN20 Z2.\n"

constexpr Example kExamples[] = {
    {'G', 1, 0, "G01 X44. F0.2 (cut in)\nZ-20. (along Z)\nX48. Z-24. (a taper)\nX52.\nG00 Z2.\n"},
    {'G', 2, 0, "G00 X40.\nG01 Z-20. F0.15\nG02 X48. Z-24. R4. (a concave fillet)\nG01 X52.\nG00 Z2.\n"},
    {'G', 3, 0, "G00 X40.\nG01 Z0. F0.15\nG03 X48. Z-4. R4. (round the corner)\nG01 X52.\nG00 Z2.\n"},
    {'G', 20, 0,
     "O0001\nG20 G40\nG99\nG50 S2500\nT0101\nG96 S600 M03\nG00 X2.1 Z0.1\nG01 X1.88 F0.008\nZ-1.\nX2.1\n"
     "G00 X4. Z4.\nM30\n"},
    {'G', 27, 0, "G28 U0. W0.\nG27 X200. Z300. (are we at the reference point?)\n"},
    {'G', 29, 0, "G28 U0. W0.\nG29 X60. Z5. (back through the G28 point)\n"},
    {'G', 32, 0, KLUENG_THREAD_TOOL "G00 X47.4 Z5.\nG32 Z-25. F1.5\nG00 X52.\nZ5.\nX47.\nG32 Z-25.\nG00 X52.\nZ5.\n"},
    {'G', 41, 0,
     KLUENG_DRILL "G01 Z-30. F0.1\nG00 Z5.\nX100. Z100.\nT0505 (boring bar)\nG96 S150 M03\nG41 G00 X14. Z2.\n"
                  "G01 Z-20. F0.1\nX10.\nG40 G00 Z5.\n"},
    {'G', 42, 0, "G42 G00 X44. Z2.\nG01 Z-20. F0.15\nX52.\nG40 G00 X100. Z100.\n"},
    {'G', 53, 0, "G53 X200. Z300. (machine coordinates)\n"},
    {'G', 65, 0,
     "O0001\nG21 G40\nG99\nG50 S2500\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG65 P9010 A10. B46. (depth 10, diameter 46)\n"
     "G00 X100. Z100.\nM30\nO9010 (turn diameter #2 over #1 mm)\nG01 X#2 F0.2\nW-#1\nG00 U4.\nW#1\nM99\n"},
    {'G', 66, 0,
     "O0001\nG21 G40\nG99\nG50 S2500\nT0101\nG96 S180 M03\nG00 X52. Z2.\nG66 P9020\nG00 Z-10.\nZ-20.\nG67\n"
     "G00 X100. Z100.\nM30\nO9020 (dwell 0.3 s after each move)\nG04 X0.3\nM99\n"},
    {'G', 70, kF | kC, "G71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 71, kF | kC, "G71 U1.5 R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 72, kF | kC, "G72 W1. R0.5\nG72 P10 Q20 U0.4 W0.1 F0.2\n" KLUENG_FACE_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 73, kF | kC, "G73 U3. W0.5 R3\nG73 P10 Q20 U0.4 W0.1 F0.2\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 74, kF | kC, KLUENG_DRILL "G74 R1.\nG74 Z-20. Q5000 F0.1\nG00 Z50.\n"},
    {'G', 75, kF | kC, KLUENG_GROOVE "G75 R0.5\nG75 X40. Z-18. P1500 Q2500 F0.05\nG00 X52.\nZ2.\n"},
    {'G', 76, kF | kC, KLUENG_THREAD_TOOL "G00 X52. Z5.\nG76 P020060 Q50 R0.05\nG76 X46.16 Z-25. P920 Q300 F1.5\n"},
    {'G', 70, kH, "G71 P10 Q20 U0.4 W0.1 D1.5 F0.25\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 71, kH, "G71 P10 Q20 U0.4 W0.1 D1.5 F0.25\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 72, kH, "G72 P10 Q20 U0.4 W0.1 D1. F0.2\n" KLUENG_FACE_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 73, kH, "G73 P10 Q20 U0.4 W0.1 I3. K0.5 D3 F0.2\n" KLUENG_PROFILE "G70 P10 Q20 F0.1\n"},
    {'G', 74, kH, KLUENG_DRILL "G74 Z-20. K5. F0.1\nG00 Z50.\n"},
    {'G', 75, kH, KLUENG_GROOVE "G75 X40. Z-18. I1.5 K2.5 F0.05\nG00 X52.\nZ2.\n"},
    {'G', 76, kH, KLUENG_THREAD_TOOL "G00 X52. Z5.\nG76 X46.16 Z-25. K0.92 D0.3 F1.5 A60\n"},
    {'G', 80, 0, KLUENG_DRILL "G81 Z-20. R2. F0.1\nG80\nG00 Z50.\n"},
    {'G', 81, 0, KLUENG_DRILL "G81 Z-20. R2. F0.1\nG80\nG00 Z50.\n"},
    {'G', 82, 0, KLUENG_DRILL "G82 Z-5. R2. P0.3 F0.1\nG80\nG00 Z50.\n"},
    {'G', 83, kF, KLUENG_DRILL "G83 Z-30. R-3. Q5000 F0.1\nG80\nG00 Z50.\n"},
    {'G', 83, kH, KLUENG_DRILL "G83 Z-30. R2. Q5. F0.1\nG80\nG00 Z50.\n"},
    {'G', 90, 0, "G90 X46. Z-30. F0.2\nX44.\nX42.\nG00 X52. Z2.\n"},
    {'G', 92, 0, KLUENG_THREAD_TOOL "G00 X52. Z5.\nG92 X47.2 Z-25. F1.5\nX46.8\nX46.5\nX46.3\nG00 X52. Z5.\n"},
    {'G', 94, 0, "G94 X20. Z-1. F0.2\nZ-2.\nG00 X52. Z2.\n"},
    {'M', 41, kC, "M05\nM86 (brake on)\nM41 (C-axis mode)\nC90.\nM91\nM87\n"},
    {'M', 97, 0,
     "O0001\nG21 G40\nG99\nG50 S2500\nT0101\nG96 S180 M03\nG00 X52. Z2.\nM97 P1000\nG00 X100. Z100.\nM30\n"
     "N1000 G01 X46. F0.2\nZ-10.\nG00 X52. Z2.\nM99\n"},
    // The classic control keeps one program per file: the subprogram is the file O1234.nc beside it.
    {'M', 98, kC, "M98 P1234 (O1234.nc in the same folder)\n"},
    {'M', 99, kC, "M98 P1234 (O1234.nc ends with M99)\n"},
    {'M', 98, 0,
     "O0001\nG21 G40\nG99\nG50 S2500\nT0101\nG96 S180 M03\nG00 X52. Z2.\nM98 P1234\nG00 X100. Z100.\nM30\n"
     "O1234 (one pass)\nG01 X46. F0.2\nZ-10.\nG00 X52. Z2.\nM99\n"},
    {'M', 99, 0,
     "O0001\nG21 G40\nG99\nG50 S2500\nT0101\nG96 S180 M03\nG00 X52. Z2.\nM98 P1234\nG00 X100. Z100.\nM30\n"
     "O1234 (one pass)\nG01 X46. F0.2\nZ-10.\nG00 X52. Z2.\nM99 (back to the line after M98)\n"},
};

const Example* handWritten(char letter, int number, Dialect dialect) {
  for (const Example& e : kExamples)
    if (e.letter == letter && e.number == number &&
        (e.dialects == 0 || (e.dialects & (1u << static_cast<int>(dialect)))))
      return &e;
  return nullptr;
}

Slot slotOf(const gcode::CodeInfo& row) {
  using A = gcode::CodeAction;
  if (row.action == A::ProgramEnd) return Slot::End;
  if (row.letter == 'M' &&
      (row.action == A::SpindleCw || row.action == A::SpindleCcw || row.action == A::SpindleClamp ||
       row.action == A::SpindleRelease || row.action == A::CAxisOff))
    return Slot::Stopped;
  // Haas chuck, spindle lock and orient: the spindle must be at rest.
  if (row.flags & gcode::CodeInfo::kSpindleAtRest) return Slot::Stopped;
  return Slot::Running;
}

// The code's one-line example from the table ("M08 - coolant on" -> "M08").
std::string exampleLine(const gcode::CodeInfo& row) {
  std::string_view e = row.exampleEn;
  const std::size_t dash = e.find(" - ");
  if (dash != std::string_view::npos) e = e.substr(0, dash);
  return std::string(e);
}

}  // namespace

std::vector<std::pair<std::string, std::string>> workedExampleFiles(char letter, int number, gcode::Dialect dialect) {
  // The classic control keeps one program per file: its M98/M99 examples call the file beside them.
  const gcode::CodeInfo* row = gcode::findCode(letter, number, dialect);
  const bool call =
      row && (row->action == gcode::CodeAction::SubprogramCall || row->action == gcode::CodeAction::SubprogramReturn);
  if (call && gcode::machineProfile(dialect).family == Dialect::Classic)
    return {{"O1234.nc", "O1234 (one pass)\nG01 X46. F0.2\nZ-10.\nG00 X52. Z2.\nM99\n"}};
  return {};
}

std::vector<Segment> workedExamplePath(char letter, int number, gcode::Dialect dialect, std::vector<bool>* rapid) {
  std::vector<Segment> out;
  const std::string text = workedExample(letter, number, dialect);
  if (text.empty()) return out;
  RunOptions options;
  options.dialect = dialect;
  const Timeline t = interpret(gcode::parse(text, 1), MachineSetup{}, options);
  for (const Move& m : t.moves) {
    if (m.kind == MoveKind::Dwell) continue;
    out.push_back(m.path);
    if (rapid) rapid->push_back(m.kind == MoveKind::Rapid);
  }
  return out;
}

std::string workedExample(char letter, int number, gcode::Dialect dialect) {
  const gcode::CodeInfo* row = gcode::findCode(letter, number, dialect);
  if (!row) return {};
  // The examples are written in system A's numbers for the machine's control
  // family; a machine in system B or C reads them in its own (G32 -> G33).
  const Dialect family = gcode::machineProfile(dialect).family;
  const auto own = [dialect](std::string_view text) { return gcode::inSystemNumbers(text, dialect); };
  std::string text;
  const int inA = gcode::numberInA(letter, number, dialect);
  if (const Example* e = inA >= 0 ? handWritten(letter, inA, family) : nullptr) {
    if (e->body.starts_with("O")) return own(e->body);
    return own(kStart) + own(e->body) + own(kEnd);
  }
  const std::string line = exampleLine(*row);  // the row's own example: the machine's numbers already
  text = own(kStart);
  switch (slotOf(*row)) {
    case Slot::Running: text += line + "\n" + own(kEnd); break;
    case Slot::Stopped: text += "G00 X100. Z100. M09\nM05\n" + line + "\nM30\n"; break;
    case Slot::End: text += "G00 X100. Z100. M09\n" + line + "\n"; break;
  }
  return text;
}

}  // namespace klueng::core::machine
