#pragma once
// Codes as data (SPEC 4, 6, 7, 13): one row per G or M code and meaning with its action, group,
// in-block phase, flags, names, example, explanation phrase, search keywords and word kinds.
// The checker, the interpreter, tool inference, the explain bar, the tooltips and the help
// read this one table, by action, never by number (so system B's G33 is system A's G32).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
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
  ToolLength,   // 08: G49 (a machining centre's tool length compensation; nothing to cancel on a lathe)
  // Machine functions that change no path Klueng draws, or that it does not simulate (CodeAction::NotSimulated)
  ExactStop,    // 15: G61 G64 (exact stop mode; G09, Fanuc group 00, exact stop in one block)
  StrokeCheck,  // 09: G22 G23 stored stroke check (Fanuc T)
  SpeedCheck,   // 08: G25 G26 spindle speed fluctuation detection (Fanuc T)
  MirrorImage,  // 04: G68 G69 mirror image for double turret (Fanuc T)
  Lookahead,    // G103 block lookahead (Haas)
  Smoothness,   // G187 smoothness and corner rounding (Haas)
  SpindleSwap,  // G14 G15 secondary spindle swap (Haas)
  PolarInterp,  // G112 G113 XY to XC interpolation (Haas; Fanuc G12.1 G13.1)
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
  DataSetting,       // G10: offsets written by the program
  LocalCoordinates,  // G52: a local coordinate system inside the work coordinates
  // A code of the control that Klueng does not simulate (G68 double turret, G112 XC interpolation ...):
  // the checker warns, the interpreter stops there with A117.
  NotSimulated,
  // group 16: the plane arcs and nose compensation work in (a lathe turns in ZX: G18)
  XyPlane,
  ZxPlane,
  YzPlane,
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

// A canned cycle that cuts (G70-G76, G81-G83; not G80), by its action.
constexpr bool isCuttingCycle(CodeAction a) {
  switch (a) {
    case CodeAction::Finishing:
    case CodeAction::TurnRoughing:
    case CodeAction::FaceRoughing:
    case CodeAction::PatternRepeating:
    case CodeAction::FacePecking:
    case CodeAction::Grooving:
    case CodeAction::ThreadCutting:
    case CodeAction::Drilling:
    case CodeAction::SpotDrilling:
    case CodeAction::PeckDrilling: return true;
    default: return false;
  }
}
// A drilling cycle on centre (G81-G83), by its action.
constexpr bool isDrillingCycle(CodeAction a) {
  return a == CodeAction::Drilling || a == CodeAction::SpotDrilling || a == CodeAction::PeckDrilling;
}

// How a word's value reads in a code's block, where the code wants it other
// than SPEC 4's kind for the letter (the checker's value rules).
enum class WordKind : std::uint8_t {
  Default,    // SPEC 4's kind for the letter
  Length,     // a signed length (U on a G71 Haas row)
  Positive,   // a positive real in F's range (D depth of cut)
  Whole,      // a whole number: block number, count, least increments (P, Q of G70)
  Dwell,      // a dwell time, read as the profile's dwellP says (G04 P)
  Increment,  // a positive increment: a length with a decimal point, else whole least input
              // increments (Fanuc G83 Q5000 = Q5. = 5 mm, as decimal point programming reads any length)
};

// The words of one code whose kind differs from the default, built in the table
// as WordKinds().whole("PQ").positive("DF"). Letters are A-Z and listed once: a
// table entry that breaks this does not compile (the table is constexpr).
class WordKinds {
 public:
  constexpr WordKinds& length(std::string_view letters) { return set(letters, WordKind::Length); }
  constexpr WordKinds& positive(std::string_view letters) { return set(letters, WordKind::Positive); }
  constexpr WordKinds& whole(std::string_view letters) { return set(letters, WordKind::Whole); }
  constexpr WordKinds& dwell(std::string_view letters) { return set(letters, WordKind::Dwell); }
  constexpr WordKinds& increment(std::string_view letters) { return set(letters, WordKind::Increment); }

  // The kind of `letter`; Default when not listed (or not a letter A-Z).
  constexpr WordKind of(char letter) const {
    return letter >= 'A' && letter <= 'Z' ? kinds_[static_cast<std::size_t>(letter - 'A')] : WordKind::Default;
  }
  constexpr bool any() const {
    for (WordKind k : kinds_)
      if (k != WordKind::Default) return true;
    return false;
  }

 private:
  // Not constexpr: reaching it while the table is built stops the compile.
  static void badWordLetter() {}
  constexpr WordKinds& set(std::string_view letters, WordKind kind) {
    for (char c : letters) {
      if (c < 'A' || c > 'Z' || kinds_[static_cast<std::size_t>(c - 'A')] != WordKind::Default) badWordLetter();
      kinds_[static_cast<std::size_t>(c - 'A')] = kind;
    }
    return *this;
  }
  std::array<WordKind, 26> kinds_{};
};

// One sentence in both languages.
struct Phrase {
  std::string_view en, th;
};

// G and M numbers a row may have (Haas G103, G154, G187 lie above 99).
inline constexpr int kCodeNumbers = 300;

// One row per code and dialect meaning: everything Klueng knows about the code.
struct CodeInfo {
  // Flags: alone in its block (M00 M01 M02 M30, and G98/G99 in classic, SPEC 5 rule 7).
  static constexpr std::uint8_t kStandsAlone = 1;
  // Wants the spindle at rest (Haas M10/M11 chuck, M14/M15 brake, M19 orient): its worked example stops it first.
  static constexpr std::uint8_t kSpindleAtRest = 2;

  // The machine's control family has the row (whatever number its G-code system gives it).
  bool in(Dialect d) const;
  bool mustStandAlone() const { return (flags & kStandsAlone) != 0; }
  char letter;  // 'G' or 'M'
  int number;   // 0..kCodeNumbers-1
  ModalGroup group;
  Phase phase;
  std::uint8_t dialects;    // dialectBit() of each dialect that accepts the row
  std::uint8_t flags;       // kStandsAlone, kSpindleAtRest
  CodeAction action;        // what the interpreter, the checker and the cycles do with it
  std::string_view nameEn;  // short help: "Rapid traverse"
  std::string_view nameTh;
  std::string_view exampleEn;  // one-line example with explanation
  std::string_view exampleTh;
  Phrase says;                // what it does, as a teacher says it (the explain bar's clause)
  std::string_view keywords;  // what students type looking for it, beyond its name (help search)
  WordKinds words = {};       // its words' kinds where they differ from SPEC 4 (the checker)
};

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

// A G code written with a decimal point that a control has (Fanuc G12.1 polar coordinate
// interpolation, G05.1 AI contour control): its name, and whether it changes the path Klueng
// draws (then a run stops at it with A117, as at any code it does not simulate) or only how
// the control moves along it (then it is read and does nothing here).
struct DecimalCode {
  double value;  // 12.1
  std::uint8_t dialects;
  bool changesPath;
  Phrase name;
};
const DecimalCode* findDecimalCode(double value, Dialect dialect);
// The code as a control shows it: "G01", "M98".
std::string codeWord(const CodeInfo& row);
// The dialect's row for `action` under its own number (G33 for Thread in
// system B), the lowest number first; nullptr when the dialect has none.
const CodeInfo* findAction(char letter, CodeAction action, Dialect dialect);

struct Block;
struct Word;
// What a G or M word does in `dialect` (G33 threads in system B): its row's
// action; None for another letter, an unknown code, G#1 or G1.5.
CodeAction actionOf(const Word& word, Dialect dialect);
// The block's first G word whose row calls a macro (G65, G66, G67: the code
// table's macro call actions) and, in `row`, that row; nullptr when none.
const Word* macroCallWord(const Block& block, Dialect dialect, const CodeInfo** row = nullptr);

// Fanuc's number of a modal group, as printed in messages ("01" for Motion).
std::string_view modalGroupNumber(ModalGroup group);
// "fanuc" / "haas" / "classic", as the CLI spells them.
std::string_view dialectName(Dialect dialect);

}  // namespace klueng::core::gcode
