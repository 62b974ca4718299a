#pragma once
// Machine profiles (SPEC 13): what differs between the dialects, as data.
// A dialect is the code table (which G/M codes exist, with what meaning) plus
// one row of this table (word formats, program numbers, T words, cycle forms,
// power-on units ...). A rule that differs between dialects is one field here,
// read by the checker, the interpreter and the cycles; they never branch on
// the dialect itself. Sources of each Fanuc/Haas value: docs/dialects.md.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace klueng::core::gcode {

enum class Dialect : std::uint8_t { Fanuc, Haas, Classic };

// Bit of a dialect in a code-table row's mask.
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
  Milliseconds,             // classic, Fanuc: P is an integer in ms (P500 = 0.5 s)
  SecondsWithPointElseMs,   // Haas: P1.5 = 1.5 s, P1500 = 1.5 s (no point: ms)
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
  double roughDepthInch, roughDepthMm;        // G71/G72 depth per pass without D (Haas setting 72)
  double roughRetractInch, roughRetractMm;    // G71/G72 retract after a pass (Haas setting 73)
  double peckClearInch, peckClearMm;          // G74/G75 chip-breaking retract, G83 clearance above the
                                              // last peck (Haas setting 22; Fanuc parameter 5115)
  double threadMinCutInch, threadMinCutMm;    // G76 one-block: least depth of a pass (Haas setting 99)
  double threadFinishInch, threadFinishMm;    // G76 one-block: depth of the last pass (Haas setting 86)
  double threadChamferLeads;                  // G76 one-block: pull-out length in leads (Haas setting 95)
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
  bool macroB;                // #variables, expressions, IF/WHILE/GOTO, G65/G66
  bool packedRepeats;         // M98 P31000 = 3 x O1000 (Fanuc); Haas reads P as the program number
  int maxSubprogramNesting;   // M98/M97 levels below the main program
  int maxMacroNesting;        // G65/G66 levels
  bool programsInOneFile;     // an O block alone may start a subprogram anywhere in a file (else first block only)
  // ,C / ,R on G01: a G04 dwell may come between the corner's two moves (Haas
  // lathe manual, "Corner rounding and chamfering"); Fanuc wants the move next.
  bool dwellBeforeCornerMove;
  // "For chamfering a 90 degree angle only, an I or K value can be substituted
  // where ,C is used" (Haas lathe manual, "Corner rounding and chamfering").
  bool chamferWithIOrK;
};

struct MachineProfile {
  Dialect dialect;
  std::string_view id;       // "fanuc", "haas", "classic" (CLI, settings)
  std::string_view nameEn;   // "Fanuc 0i-TF"
  std::string_view nameTh;
  // Address letters a block may hold (SPEC 5 rule 1 and its extensions).
  std::string_view letters;
  // Program numbers: O (or ':' where colonProgramNumber) with 1..programNumberMax.
  int programNumberMax;
  bool colonProgramNumber;
  int sequenceNumberMax;     // N 1..max
  // Word formats: decimals of the least input increment, mm and inch.
  int decimalsMm;
  int decimalsInch;
  // Ranges of lengths (|value| <= maxAbs) and of F/S (>= minPositive), per input unit.
  double maxAbsMm;
  double maxAbsInch;
  double minPositiveMm;
  double minPositiveInch;
  ExtraDecimals extraDecimals;
  InputUnits powerOnUnits;   // before any G20/G21 (overridden by --units / the GUI setting)
  // T words: tool number and offset number. Digits: a T word has minToolDigits..4
  // digits (T101 = tool 01 offset 01 when 3 are allowed).
  int minToolDigits;
  int maxToolStation;        // 0 = the machine's turret size (machine.cfg turret_stations)
  int maxOffset;             // offset rows (16 classic, 64 others)
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
  CycleForm cycleForm;
  bool unknownMIsWarning;    // an M code 0-99 outside the table: W101 (true) or E115 (false)
  bool highMIsWarning;       // an M code from 100 up (machine options: live tooling...): W101 or E115
  bool blanksInWords;        // "X 38" reads as X38 (true, as a Fanuc), or E135 (false)
  bool commentToLineEnd;     // an unclosed '(' runs to the line end: W108 (true) or E105 (false)
  CycleSettings cycles;      // defaults of the cycles (one-block forms, drilling)
  FlowSettings flow;
};

// The row of a dialect.
const MachineProfile& machineProfile(Dialect dialect);
// Every profile, in menu order (Fanuc, Haas, classic).
std::span<const MachineProfile> machineProfiles();
// "fanuc" / "haas" / "classic" -> dialect; nullopt-like false when unknown.
bool parseDialectId(std::string_view id, Dialect& out);
// The units before any G20/G21: the ones chosen (--units, the GUI setting), else the dialect's.
inline InputUnits powerOnUnitsOf(Dialect dialect, const std::optional<InputUnits>& chosen) {
  return chosen.value_or(machineProfile(dialect).powerOnUnits);
}

}  // namespace klueng::core::gcode
