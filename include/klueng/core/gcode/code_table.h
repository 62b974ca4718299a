#pragma once
// Codes as data: one row per G or M code with its modal group, in-block
// execution priority and help text, for both dialects (SPEC 6, 7, 13).
// The checker, the interpreter, the editor's tooltips and the help pages all
// read this one table.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "klueng/core/gcode/machine_profile.h"

namespace klueng::core::gcode {

enum class ModalGroup {
  NonModal,     // 00: G04 G27 G28 G29 G50 (G53 in Fanuc)
  Motion,       // 01: G00 G01 G02 G03 G32 (G90 G92 G94)
  Units,        // 06: G20 G21
  NoseComp,     // 07: G40 G41 G42
  SpindleMode,  // 02: G96 G97
  FeedMode,     // 05: G98 G99
  Plane,        // 16: G18 (Fanuc)
  WorkOffset,   // 14: G54..G59 (Fanuc)
  CannedCycle,  // 10/00: G70..G76, G80, G81..G83 drilling
  MacroModal,   // 12: G66 G67 (custom macro modal call; G65 is group 00)
  Distance,     // 03: G90 G91 absolute / incremental (G-code systems B and C)
  ReturnLevel,  // 11: G98 G99 drilling cycles' return level (G-code systems B and C)
  // M code groups, for rule 4 and the interpreter
  MSpindle,     // M03 M04 M05
  MCoolant,     // M08 M09
  MCAxis,       // M41 M91 (classic)
  MBrake,       // M86 M87
  MGear,        // M41 M42 (Fanuc gear range)
  MProgram,     // M00 M01 M02 M30
  MSubprogram,  // M98 M99 (M97 Haas)
  // Haas machine M codes: on/off pairs that may not share a block (rule 4)
  MChuck,                // M10 M11
  MAirBlast,             // M12 M13
  MTailstock,            // M21 M22
  MThreadChamfer,        // M23 M24
  MConveyor,             // M31 M33
  MPartsCatcher,         // M36 M37
  MDoor,                 // M85 M86
  MHighPressureCoolant,  // M88 M89
  MOther,
};

// When an M/G code acts inside its block (SPEC 7: lower runs first).
enum class Phase { State = 0, BeforeMotion = 1, Motion = 2, AfterMotion = 3 };

// What a code does when it runs. The interpreter and the cycles switch on this,
// never on the code's number (issue 12); a profile that gives a number another
// meaning gives its row another action. None: the code only selects a state its
// group keeps (G18), or is a machine function the simulator shows but does not
// model (M10 chuck, M31 conveyor ...). Work offsets (G54-G59) and gear ranges
// (M41-M44) carry their number as their value.
enum class CodeAction : std::uint8_t {
  None,
  // group 01
  Rapid,
  Line,
  ArcCw,
  ArcCcw,
  Thread,
  BoxTurning,
  BoxThreading,
  BoxFacing,
  // modal states
  Inch,
  Metric,
  CompOff,
  CompLeft,
  CompRight,
  ConstantSurface,
  ConstantRpm,
  FeedPerMinute,
  FeedPerRev,
  WorkOffset,
  // one block only
  Dwell,
  ReferenceCheck,
  ReferenceReturn,
  SecondReferenceReturn,
  ReturnFromReference,
  CoordinateSet,
  MachineCoordinates,
  MacroCall,
  MacroModalCall,
  MacroModalCancel,
  // group 03 (G-code systems B and C): X and Z absolute or incremental (as U and W)
  Absolute,
  Incremental,
  // group 11 (G-code systems B and C): where a drilling cycle returns, initial level or R point
  ReturnToInitialLevel,
  ReturnToRPoint,
  // canned cycles
  CycleCancel,
  Finishing,
  TurnRoughing,
  FaceRoughing,
  PatternRepeating,
  FacePecking,
  Grooving,
  ThreadCutting,
  Drilling,
  SpotDrilling,
  PeckDrilling,
  // M codes
  SpindleCw,
  SpindleCcw,
  SpindleStop,
  CoolantOn,
  CoolantOff,
  SpindleClamp,
  SpindleRelease,
  CAxisOn,
  CAxisOff,
  GearRange,
  ThreadChamferOn,
  ThreadChamferOff,
  ProgramStop,
  OptionalStop,
  ProgramEnd,
  LocalCall,
  SubprogramCall,
  SubprogramReturn,
};

struct CodeInfo {
  // The machine's control family has the row (whatever number its G-code system gives it).
  bool in(Dialect d) const;
  char letter;  // 'G' or 'M'
  int number;   // 0..99
  ModalGroup group;
  Phase phase;
  std::uint8_t dialects;    // dialectBit() of each dialect that accepts the row
  bool mustStandAlone;      // M00 M01 M02 M30 (and G98/G99 in classic)
  std::string_view nameEn;  // short help: "Rapid traverse"
  std::string_view nameTh;
  std::string_view exampleEn;  // one-line example with explanation
  std::string_view exampleTh;
  // The words the code takes whose value kind differs from the default, as
  // letter + kind pairs ("P#Q#D+"): '.' signed length, '+' positive real
  // (F-like range), '#' whole number (block number, count, least increments),
  // 'd' dwell time read as the profile's dwellP says, 'i' a positive increment:
  // a length with a decimal point, else whole least input increments (Fanuc
  // G83 Q5000 = Q5. = 5 mm, as decimal point programming reads any length). Letters not listed keep
  // SPEC 4's kind. Read by the checker (and the help pages).
  std::string_view words = {};
  CodeAction action = CodeAction::None;  // from the table's action list (code_table.cpp)
};

// The kind of `letter` in `row`'s word list; 0 when not listed.
char wordKind(const CodeInfo& row, char letter);

// Every row of every control family, numbered as G-code system A. A code whose
// meaning differs between the families (M41, G98/G99 standing alone) has one
// row per meaning. Systems B and C: their renamings (gcodeSystemRenames) and
// the rows only they have (G90/G91 absolute/incremental, systemOnlyRows).
std::span<const CodeInfo> codeTable();

// One G number of a G-code system: the system-A code it is (same row, same
// action), or, for a code system A has not, a row of systemOnlyRows().
struct SystemRename {
  GcodeSystem system;
  int number;     // in that system
  int numberInA;  // -1: a code system A has not (systemOnlyRows, same number)
};
std::span<const SystemRename> gcodeSystemRenames();
std::span<const CodeInfo> systemOnlyRows();
// The number a code has in a machine's G-code system (G32 -> G33 in system B); the number itself when
// unchanged, -1 when the system has no such code.
int numberInSystem(char letter, int numberInA, Dialect dialect);
// `text` written with system-A G numbers ("G50 S2500", "(G32 passes)"), as
// `dialect`'s G-code system numbers them ("G92 S2500", "(G33 passes)" in system
// B); the text itself in system A. A G word is a G not after a letter or digit,
// then its digits (not followed by a point).
std::string inSystemNumbers(std::string_view text, Dialect dialect);
// The system-A number of a code of `dialect`'s system (G33 -> 32 in system B);
// -1 for a code system A has not (G90 absolute).
int numberInA(char letter, int number, Dialect dialect);
// The row for a code in a dialect; nullopt when the dialect does not know it.
std::optional<CodeInfo> lookupCode(char letter, int number, Dialect dialect);
// Same, without a copy (constant time): nullptr when unknown.
const CodeInfo* findCode(char letter, int number, Dialect dialect);

struct Block;
struct Word;
// The block's first G word whose row calls a macro (G65, G66, G67: the code
// table's macro call actions) and, in `row`, that row; nullptr when none.
const Word* macroCallWord(const Block& block, Dialect dialect, const CodeInfo** row = nullptr);

// Fanuc's number of a modal group, as printed in messages ("01" for Motion).
std::string_view modalGroupNumber(ModalGroup group);
// "fanuc" / "haas" / "classic", as the CLI spells them.
std::string_view dialectName(Dialect dialect);

}  // namespace klueng::core::gcode
