#pragma once
// Machine profiles (SPEC 13, issue 27): what differs between the machines, as data.
// A machine is a file (resources/machines/*.machine, docs/dialects.md): its
// control family picks a column of the code table (which G/M codes exist, with
// what meaning), its G-code system renames the G numbers (A, B, C), and its
// other keys fill one MachineProfile (word formats, program numbers, T words,
// cycle forms, power-on units ...). A rule that differs between machines is one
// field here, read by the checker, the interpreter and the cycles; they never
// branch on the machine itself. Sources of each value: the .machine files.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace klueng::core::gcode {

// A machine, by its place in the registry of loaded machine files. The three
// named ones are the shipped fanuc.machine, haas.machine and classic.machine,
// always in these places; other shipped and user machines follow (any value
// below machineCount()). As a control family (MachineProfile::family) only the
// three named values occur: the code table's columns.
enum class Dialect : std::uint8_t { Fanuc, Haas, Classic };

// The G-code system of a Fanuc lathe control (parameter 3401 GSB/GSC): the
// same functions under other G numbers (docs/dialects.md, "G-code systems").
enum class GcodeSystem : std::uint8_t { A, B, C };

// Bit of a control family in a code-table row's mask.
constexpr std::uint8_t dialectBit(Dialect d) { return static_cast<std::uint8_t>(1u << static_cast<unsigned>(d)); }

enum class InputUnits : std::uint8_t { Millimetre, Inch };

// How the control reads more decimals than the least input increment.
enum class ExtraDecimals : std::uint8_t {
  Error,             // classic: E111
  RoundWithWarning,  // Fanuc/Haas: rounded to the increment, a warning says so
};

// The format of the multiple repetitive cycles G70-G76.
enum class CycleForm : std::uint8_t {
  TwoBlock,  // Fanuc 0i-TF (G-code system A): G71 U R / G71 P Q U W F
  OneBlock,  // Haas: G71 P Q U W D I K F S T in one block
};

// The unit of G04 P.
enum class DwellPUnit : std::uint8_t {
  Milliseconds,            // classic, Fanuc: P is an integer in ms (P500 = 0.5 s)
  SecondsWithPointElseMs,  // Haas: P1.5 = 1.5 s, P1500 = 1.5 s (no point: ms)
};

// What a G28 without axis words does.
enum class BareG28 : std::uint8_t {
  Error,        // classic: E309
  NoMotion,     // Fanuc: moves nothing, warning W102
  HomeAllAxes,  // Haas: returns X and Z to the reference point
};

// What R means in the drilling cycles G81-G83 (docs/haas-cycles.md).
enum class DrillR : std::uint8_t {
  FromInitialLevel,  // Fanuc 0i-TF: the signed distance from the initial level to the R point
  Plane,             // Haas: the Z of the R plane
};

// Machine settings the cycles use where a program leaves a value out (Haas
// settings, Fanuc parameters), in inch and mm as the control keeps them.
struct CycleSettings {
  double roughDepthInch, roughDepthMm;      // G71/G72 depth per pass without D (Haas setting 72)
  double roughRetractInch, roughRetractMm;  // G71/G72 retract after a pass (Haas setting 73)
  double peckClearInch, peckClearMm;        // G74/G75 chip-breaking retract, G83 clearance above the
                                            // last peck (Haas setting 22; Fanuc parameter 5115)
  double threadMinCutInch, threadMinCutMm;  // G76 one-block: least depth of a pass (Haas setting 99)
  double threadFinishInch, threadFinishMm;  // G76 one-block: depth of the last pass (Haas setting 86)
  double threadChamferLeads;                // G76 one-block: pull-out length in leads (Haas setting 95)
  DrillR drillR;
  // G71/G72: profile pieces after the last cut that lie wholly at or beyond the
  // start point's depth level (outside the stock: `X1.6` back to the start's X,
  // then `N20 G00 G40 Z0.1`) are left out of the monotony check and the roughing
  // and travelled by the finishing pass (Haas); false: the whole shape must
  // move one way (Fanuc 0i-TF, alarm A121). docs/haas-cycles.md.
  bool profileTailBeyondStart;
  // G70-G73: the first block of the shape (N of P) must hold G00 or G01
  // (Fanuc 0i-TF alarm PS0065); false: a block without it is read as any other.
  bool profileFirstBlockNeedsG00G01;
};

// Program flow (issue 9): subprograms and custom macro B.
struct FlowSettings {
  bool macroB;               // #variables, expressions, IF/WHILE/GOTO, G65/G66
  bool packedRepeats;        // M98 P31000 = 3 x O1000 (Fanuc); Haas reads P as the program number
  int maxSubprogramNesting;  // M98/M97 levels below the main program
  int maxMacroNesting;       // G65/G66 levels
  bool programsInOneFile;    // an O block alone may start a subprogram anywhere in a file (else first block only)
  // ,C / ,R on G01: a G04 dwell may come between the corner's two moves (Haas
  // lathe manual, "Corner rounding and chamfering"); Fanuc wants the move next.
  bool dwellBeforeCornerMove;
  // "For chamfering a 90 degree angle only, an I or K value can be substituted
  // where ,C is used" (Haas lathe manual, "Corner rounding and chamfering").
  bool chamferWithIOrK;
  // R on a G01 without its comma is the corner R (Fanuc T series "Chamfering and corner R":
  // `G01 Z_ R±r`, B-63944EN-1/02 §4.5; the 0i-TF the same). Else W107 and a sharp corner.
  bool cornerRWithoutComma = false;
};

struct MachineProfile {
  Dialect dialect;          // its place in the registry
  Dialect family;           // the code table's column: Fanuc, Haas or Classic
  GcodeSystem system;       // the G numbers: system A, B or C
  std::string_view id;      // "fanuc", "haas", "classic", "romi-gl240m" (CLI, settings, job header)
  std::string_view nameEn;  // "Fanuc 0i-TF"
  std::string_view nameTh;
  std::string_view file;  // the file it was read from; "" for a shipped one built in
  std::string_view text;  // the file's text (its machine.cfg keys are read by machine/machine_files.h)
  // Address letters a block may hold (SPEC 5 rule 1 and its extensions).
  std::string_view letters;
  // Program numbers: O (or ':' where colonProgramNumber) with 1..programNumberMax.
  int programNumberMax;
  bool colonProgramNumber;
  int sequenceNumberMax;  // N 1..max
  // Word formats: decimals of the least input increment, mm and inch.
  int decimalsMm;
  int decimalsInch;
  // Ranges of lengths (|value| <= maxAbs) and of F/S (>= minPositive), per input unit.
  double maxAbsMm;
  double maxAbsInch;
  double minPositiveMm;
  double minPositiveInch;
  ExtraDecimals extraDecimals;
  InputUnits powerOnUnits;  // before any G20/G21 (overridden by --units / the GUI setting)
  // T words: tool number and offset number. Digits: a T word has minToolDigits..4
  // digits (T101 = tool 01 offset 01 when 3 are allowed).
  int minToolDigits;
  int maxToolStation;  // 0 = the machine's turret size (machine.cfg turret_stations)
  int maxOffset;       // offset rows (16 classic, 64 others)
  // T0000 (tool 00, offset 00): the turret stays where it is and the offset is
  // cancelled, as a Fanuc or Haas turret reads T__00 (true); classic: E117.
  bool toolZeroKeepsTurret;
  DwellPUnit dwellP;
  BareG28 bareG28;
  // Threading under G96: an alarm (SPEC 8, the classic trainer) or a warning. Fanuc 0i-TF
  // operator's manual, "Constant surface speed control", notes: it stays effective during
  // threading and G97 is recommended before face and taper threads; the control runs it.
  bool threadUnderCssIsAlarm;
  // Group-00 codes that may share a block with G00/G01 (G28, G30, G53), as G numbers.
  std::span<const int> oneShotsWithMotion;
  // E codes of the classic rules that no manual of this control makes a stop (docs/dialects.md §10):
  // given as warnings here, the block read as the message says (106 = E106).
  std::span<const int> errorsAsWarnings;
  CycleForm cycleForm;
  bool unknownMIsWarning;  // an M code 0-99 outside the table: W101 (true) or E115 (false)
  bool highMIsWarning;     // an M code from 100 up (machine options: live tooling...): W101 or E115
  bool blanksInWords;      // "X 38" reads as X38 (true, as a Fanuc), or E135 (false)
  bool commentToLineEnd;   // an unclosed '(' runs to the line end: W108 (true) or E105 (false)
  // Fanuc reading of the end of a block and of comments (issue 38 item 5; docs/dialects.md §1):
  // ';' ends the block and what follows is the next block, and a comment ends at its first ')'.
  // False (Haas, classic): the rest of a line after ';' is a comment, parentheses may nest.
  bool semicolonEndsBlock = false;
  bool commentEndsAtFirstParen = false;
  // A without a comma is the angle of a G01 (`G01 X40. A-45.`, Fanuc parameter 3405#4, the 0-T
  // style), where the machine has no A axis (issue 38 item 4).
  bool angleWithoutComma = false;
  // Two G codes of one modal group in a block: the control uses the last (true, Fanuc: a warning)
  // or refuses the block (false: E205).
  bool sameGroupLastWins = false;
  // O0 (a CAM post's O0000 left as it came): refused (E116, the 1999 rules) or a warning (W117, where
  // no manual says the control stops on it).
  bool programNumberZeroIsError = false;
  // M00 M01 M02 M30 with other words in the block (`G00 X100. Z100. M30`): refused (E203, the 1999
  // rules) or run, the move first, with a warning (W118, where no manual says the control stops).
  bool stopCodesAloneIsError = false;
  // An S above the machine's maximum under G97: an alarm (the 1999 trainer) or clamped to the maximum
  // with a warning (a Fanuc or Haas clamps it); M03 <-> M04 without M05: an alarm, or reversed.
  bool spindleAboveMaximumIsAlarm = true;
  bool spindleReversalIsAlarm = true;
  // A canned cycle (G71-G76, G90/G92/G94) under G41/G42: an alarm (A123, the 1999 trainer), or run
  // with its passes uncompensated and a warning (W134), as no Fanuc or Haas source says it stops.
  bool cycleUnderCompensationIsAlarm = true;
  CycleSettings cycles;  // defaults of the cycles (one-block forms, drilling)
  FlowSettings flow;
  // The M codes the machine accepts, from its family's rows; empty = all of them.
  std::span<const int> mCodes;
};

// The profile of a machine (the first one for a value not below machineCount()).
const MachineProfile& machineProfile(Dialect dialect);
// How many machines are loaded (3 shipped families first, then the others).
int machineCount();
// Every machine, in menu order (Fanuc, Haas, classic, then the others as loaded).
std::vector<const MachineProfile*> machineProfiles();
// A machine's id -> its place; false when no machine has that id.
bool parseDialectId(std::string_view id, Dialect& out);
// The units before any G20/G21: the ones chosen (--units, the GUI setting), else the dialect's.
inline InputUnits powerOnUnitsOf(Dialect dialect, const std::optional<InputUnits>& chosen) {
  return chosen.value_or(machineProfile(dialect).powerOnUnits);
}

}  // namespace klueng::core::gcode
