// The grammar checker (SPEC 4-5, 13 and the "ext" rules): one pass over the
// blocks, every diagnostic reported, driven by the code table.
#include "klueng/core/gcode/checker.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string>

#include "diagnostic_codes.h"
#include "klueng/core/gcode/address_table.h"
#include "flow_check.h"
#include "modal_check.h"
#include "klueng/core/gcode/word_format.h"

namespace klueng::core::gcode {

namespace {

constexpr double kMaxWholeNumber = 99999999.0;

// Rule 2: letters that may appear at most once per block (the address table says which).
bool onceOnly(char l) {
  const AddressInfo* a = addressInfo(l);
  return a && a->oncePerBlock;
}

bool hasSign(const Word& w) { return !w.number.empty() && (w.number[0] == '-' || w.number[0] == '+'); }
std::string wordText(const Word& w) { return w.text(); }

// A limit as SPEC 4 prints it: "9999.999", "0.0001" (no trailing zeros).
std::string limitText(double v) {
  std::string s = formatFixed(v, 4);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

// "CFG" -> "C F G", for E201.
std::string spaced(std::string_view letters) {
  std::string s;
  for (char c : letters) {
    if (!s.empty()) s += ' ';
    s += c;
  }
  return s;
}
std::string twoDigits(int n) { return n < 10 ? "0" + std::to_string(n) : std::to_string(n); }

// The code number of a G/M/T/N/O word when it is a plain non-negative integer
// that fits; -1 otherwise (no undefined float-to-int conversion on junk).
long long wholeNumber(const Word& w) {
  if (w.hasDecimalPoint || hasSign(w) || !(w.value <= kMaxWholeNumber)) return -1;
  return static_cast<long long>(w.value);
}

// The station of a well-formed T word (T0101 -> 1), or -1 when the word itself
// is wrong (its digits, station or offset out of range: E203/E204).
int toolStation(const Word& w, const MachineProfile& profile, int turretStations) {
  const auto digits = static_cast<int>(w.number.size());
  const long long n = wholeNumber(w);
  const bool shapeOk = n >= 0 && digits >= profile.minToolDigits && digits <= 4;
  const int tool = static_cast<int>(n / 100);
  const int offset = static_cast<int>(n % 100);
  const int maxTool = profile.maxToolStation > 0 ? profile.maxToolStation : turretStations;
  // T0000: the turret stays and the offset is cancelled (an offset for tool 00, T0017, is refused).
  const bool keepTurret = profile.toolZeroKeepsTurret && tool == 0 && offset == 0;
  return !shapeOk || (tool < 1 && !keepTurret) || tool > maxTool || offset > profile.maxOffset ? -1 : tool;
}

bool isRuleFourGroup(ModalGroup g) {
  return g == ModalGroup::MSpindle || g == ModalGroup::MCoolant || g == ModalGroup::MCAxis ||
         g == ModalGroup::MBrake || g == ModalGroup::MGear || g == ModalGroup::MSubprogram ||
         g == ModalGroup::MChuck || g == ModalGroup::MAirBlast || g == ModalGroup::MTailstock ||
         g == ModalGroup::MThreadChamfer || g == ModalGroup::MConveyor || g == ModalGroup::MPartsCatcher ||
         g == ModalGroup::MDoor || g == ModalGroup::MHighPressureCoolant;
}

constexpr int kGroupCount = static_cast<int>(ModalGroup::MOther) + 1;
static_assert(kGroupCount <= 32, "group masks are 32-bit");

class Checker {
 public:
  Checker(const CheckOptions& options, std::vector<Diagnostic>& out)
      : options_(options),
        profile_(machineProfile(options.dialect)),
        out_(out),
        letters_(spaced(profile_.letters)),
        allowedLetters_(letterMask(profile_.letters)),
        inch_(options.powerOnUnits.value_or(profile_.powerOnUnits) == InputUnits::Inch) {}

  bool full() const { return full_; }

  void checkBlock(const Block& block, bool firstBlock) {
    if (block.statement.kind != StatementKind::None) {
      // A macro statement: its N word and the dialect (expressions are checked by the reader).
      for (const Word& w : block.words)
        if (w.letter == 'N' && w.expr < 0) {
          const long long n = wholeNumber(w);
          if (n < 1 || n > profile_.sequenceNumberMax)
            emit(codes::kBadSequenceNumber, w, {wordText(w), "N", std::to_string(profile_.sequenceNumberMax)});
        }
      if (!profile_.flow.macroB) emit(codes::kMacroNotInDialect, block.statement.range, {"#"});
      return;
    }
    // A macro call's block: its letters are arguments (A -> #1 ...), not addresses.
    bool macroCall = false;
    for (const Word& w : block.words)
      if (w.letter == 'G' && w.expr < 0 && !w.hasDecimalPoint && (w.value == 65.0 || w.value == 66.0))
        macroCall = profile_.flow.macroB;
    // Units apply to the whole block they appear in, then stay modal.
    for (const Word& w : block.words)
      if (w.letter == 'G') {
        const long long n = wholeNumber(w);
        if (n == 20) inch_ = true;
        else if (n == 21) inch_ = false;
      }

    // Slots are valid only where the mask bit is set: no per-block clearing
    // of the arrays (this runs for every block of a 100,000-block program).
    std::uint32_t letterMask = 0, groupMask = 0, mGroupMask = 0;
    std::array<const Word*, 26> firstOfLetter;
    std::array<const Word*, kGroupCount> firstOfGroup;
    std::array<const Word*, kGroupCount> firstMOfGroup;
    const Word* standAlone[4] = {};
    int standAloneCount = 0;
    const Word* motionWord = nullptr;  // last valid group-01 G word
    int motionCode = -1;
    const Word* oneShotWord = nullptr;
    int oneShotCode = -1;
    const CodeInfo* wordRow = nullptr;  // the code whose word list sets the kinds of this block's words
    const Word* g04 = nullptr;
    const Word* g28 = nullptr;
    const Word* singleCycle = nullptr;  // G90/G92/G94 (system A), G77/G78/G79 (B)
    const Word* compWord = nullptr;
    int compCode = -1;
    bool cannedCycle = false;
    int nonNWords = 0;

    const int wordCount = static_cast<int>(block.words.size());
    for (int i = 0; i < wordCount && !full_; ++i) {
      const Word& w = block.words[static_cast<std::size_t>(i)];
      const char l = w.letter;
      if (l != 'N') ++nonNWords;
      if (w.comma) continue;  // ,C ,R ,A: checked with the corner rules
      if (w.expr >= 0) {
        // X#1: the value is known when the block runs; only the letter is checked here.
        if (!profile_.flow.macroB) emit(codes::kMacroNotInDialect, w, {wordText(w)});
        else if (!allowed(l) && !macroCall)
          emit(codes::kLetterNotAllowed, w, {wordText(w), std::string(1, l), letters_});
        continue;
      }
      if (macroCall && l != 'G' && l != 'N' && l != 'O') {
        if (letterMask & (1u << static_cast<std::size_t>(l - 'A'))) emit(codes::kLetterTwice, w, {std::string(1, l)});
        letterMask |= 1u << static_cast<std::size_t>(l - 'A');
        continue;  // an argument: any value
      }
      if (!allowed(l)) {
        // X1e9, Z2.5E-3: a number written with an exponent reads as two words; say so.
        const Word* before = i > 0 ? &block.words[static_cast<std::size_t>(i - 1)] : nullptr;
        if (l == 'E' && before && before->expr < 0 && !before->comma && before->range.line == w.range.line &&
            before->range.column + before->range.length == w.range.column && !before->number.empty() &&
            (std::isdigit(static_cast<unsigned char>(before->number.back())) != 0 || before->number.back() == '.')) {
          SourceRange both = before->range;
          both.length = before->range.length + w.range.length;
          emit(codes::kExponentNumber, both, {wordText(*before), wordText(w)});
          continue;
        }
        emit(codes::kLetterNotAllowed, w, {wordText(w), std::string(1, l), letters_});
        continue;
      }
      const auto letterIndex = static_cast<std::size_t>(l - 'A');
      const std::uint32_t letterBit = 1u << letterIndex;
      if (letterMask & letterBit) {
        // A second N is reported once, by rule 9 (N only first).
        if (onceOnly(l) && l != 'N') emit(codes::kLetterTwice, w, {std::string(1, l)});
      } else {
        letterMask |= letterBit;
        firstOfLetter[letterIndex] = &w;
      }

      switch (l) {
        case 'N': {
          const long long n = wholeNumber(w);
          if (n < 1 || n > profile_.sequenceNumberMax)
            emit(codes::kBadSequenceNumber, w, {wordText(w), "N", std::to_string(profile_.sequenceNumberMax)});
          if (i != 0) emit(codes::kNNotFirst, w, {wordText(w)});
          break;
        }
        case 'O': {
          if (w.colon && !profile_.colonProgramNumber) {
            // ':' is not an address of this control: the seed's E104, naming ':'.
            emit(codes::kUnknownCharacter, SourceRange{w.range.line, w.range.column, 1}, {":"});
            break;
          }
          const long long n = wholeNumber(w);
          if (n < 1 || n > profile_.programNumberMax)
            emit(codes::kBadSequenceNumber, w, {wordText(w), "O", std::to_string(profile_.programNumberMax)});
          const bool alone = i == 0 && wordCount == 1;
          if (!(alone && (firstBlock || profile_.flow.programsInOneFile))) emit(codes::kMisplacedO, w, {wordText(w)});
          break;
        }
        case 'G': case 'M': {
          if (w.hasDecimalPoint) {
            emit(codes::kCodeNotInteger, w, {wordText(w)});
            break;
          }
          const long long n = wholeNumber(w);
          const CodeInfo* row = n >= 0 && n <= 99 ? findCode(l, static_cast<int>(n), options_.dialect) : nullptr;
          if (!row) {
            if (l == 'G') emit(codes::kUnknownGCode, w, {wordText(w)});
            else if (n > 99 ? profile_.highMIsWarning : profile_.unknownMIsWarning)
              emit(codes::kMachineSpecificM, w, {wordText(w)}, Severity::Warning);
            else emit(codes::kUnknownMCode, w, {wordText(w)});
            break;
          }
          const auto group = static_cast<std::size_t>(row->group);
          if (row->mustStandAlone && standAloneCount < 4) standAlone[standAloneCount++] = &w;
          const std::uint32_t groupBit = 1u << group;
          if (l == 'G') {
            if (groupMask & groupBit) {
              emit(codes::kSameModalGroup, w,
                   {wordText(*firstOfGroup[group]), wordText(w), std::string(modalGroupNumber(row->group))});
            } else {
              groupMask |= groupBit;
              firstOfGroup[group] = &w;
            }
            if (row->group == ModalGroup::Motion) {
              motionWord = &w;
              motionCode = row->number;
            } else if (row->group == ModalGroup::NonModal && !oneShotWord) {
              oneShotWord = &w;
              oneShotCode = row->number;
            } else if (row->group == ModalGroup::NoseComp) {
              compWord = &w;
              compCode = row->number;
            } else if (row->group == ModalGroup::CannedCycle) {
              cannedCycle = true;
            }
            if (!row->words.empty() && !wordRow) wordRow = row;
            if (row->number == 4) g04 = &w;
            if (row->action == CodeAction::BoxTurning || row->action == CodeAction::BoxThreading ||
                row->action == CodeAction::BoxFacing)
              singleCycle = &w;
            if (row->number == 28) g28 = &w;
          } else if (isRuleFourGroup(row->group)) {
            if (mGroupMask & groupBit) {
              emit(codes::kConflictingMCodes, w, {wordText(*firstMOfGroup[group]), wordText(w)});
            } else {
              mGroupMask |= groupBit;
              firstMOfGroup[group] = &w;
            }
          }
          break;
        }
        default:
          break;
      }
    }
    if (full_) return;

    // Values, once the block's codes are known: a word's kind may depend on
    // its code (Haas G83 Q0.1 is a length, Fanuc G83 Q5000 least increments).
    if (macroCall) return;  // the arguments are the macro's to judge
    for (const Word& w : block.words) {
      if (full_) return;
      if (allowed(w.letter) && w.expr < 0 && !w.comma) checkValue(w, wordRow);
    }

    const auto has = [&](char l) -> const Word* {
      const auto index = static_cast<std::size_t>(l - 'A');
      return (letterMask >> index) & 1u ? firstOfLetter[index] : nullptr;
    };
    const auto later = [](const Word* a, const Word* b) { return a->range.column > b->range.column ? a : b; };

    // Rules 3 and 7: stand-alone codes (N may come before them).
    for (int k = 0; k < standAloneCount; ++k)
      if (nonNWords > 1)
        emit(standAlone[k]->letter == 'G' ? codes::kFeedModeNotAlone : codes::kMustStandAlone, *standAlone[k],
             {wordText(*standAlone[k])});

    // Rule 6: a one-shot G with a motion G.
    const auto& withMotion = profile_.oneShotsWithMotion;
    if (oneShotWord && motionWord &&
        std::find(withMotion.begin(), withMotion.end(), oneShotCode) == withMotion.end()) {
      const Word* second = later(oneShotWord, motionWord);
      emit(codes::kOneShotWithMotion, *second, {wordText(*oneShotWord), wordText(*motionWord)});
    }

    // Rule 10: absolute and incremental words of one axis.
    static constexpr std::array<std::pair<char, char>, 3> kPairs{{{'X', 'U'}, {'Z', 'W'}, {'C', 'H'}}};
    for (const auto& [abs, inc] : kPairs)
      if (has(abs) && has(inc))
        emit(codes::kAbsoluteAndIncremental, *later(has(abs), has(inc)), {std::string(1, abs), std::string(1, inc)});

    // Rule 11 and the dwell's own rules.
    if (g04) checkDwell(block, *g04, has('U') ? has('U') : has('X'), has('P'));

    // G28 without axis words moves nothing.
    const bool axisWords = has('X') || has('Z') || has('U') || has('W');
    // A single cycle block names its end point: `G92 S3000` (system B's clamp, read in
    // system A) would select the threading cycle and set 3000 rpm.
    if (singleCycle && !axisWords) emit(codes::kSingleCycleWithoutEnd, *singleCycle, {wordText(*singleCycle)});
    if (g28 && !axisWords) {
      if (profile_.bareG28 == BareG28::NoMotion) emit(codes::kG28NoMotion, *g28, {}, Severity::Warning);
      else if (profile_.bareG28 == BareG28::Error) emit(codes::kG28WithoutAxes, *g28, {});
    }

    // Arc rules: the motion group is modal, so "X20 Z-5 R2" after a G02 is an arc too.
    if (motionCode >= 0) motion_ = motionCode;

    // Chamfer and corner words (Fanuc 0i-TF ",C" ",R" ",A"): on a G01 only, one corner kind.
    const Word* chamfer = nullptr;
    const Word* corner = nullptr;
    for (const Word& w : block.words) {
      if (!w.comma) continue;
      const bool known = w.letter == 'C' || w.letter == 'R' || w.letter == 'A';
      if (!known || motion_ != 1 || cannedCycle || oneShotWord) {
        emit(codes::kCornerNotOnG01, w, {"," + wordText(w)});
        continue;
      }
      if (w.letter == 'C') chamfer = &w;
      if (w.letter == 'R') corner = &w;
      if (w.expr < 0) checkValue(w, nullptr);
    }
    if (chamfer && corner) emit(codes::kChamferAndCorner, *later(chamfer, corner), {"," + wordText(*chamfer), "," + wordText(*corner)});
    // The old forms "X30. K-2." / "Z-20. R3." (a 90-degree chamfer or round without the
    // comma) are not simulated: say so rather than leave the corner sharp without a word.
    if (motion_ == 1 && !cannedCycle && !oneShotWord) {
      for (const char letter : {'I', 'K', 'R'})
        if (const Word* w = has(letter); w && !w->comma && w->expr < 0 && (letter == 'R' || !profile_.flow.chamferWithIOrK)) {
          std::string size(w->number.view());
          if (!size.empty() && (size[0] == '-' || size[0] == '+')) size.erase(0, 1);
          emit(codes::kCornerWordWithoutComma, *w, {wordText(*w), (letter == 'R' ? ",R" : ",C") + size}, Severity::Warning);
        }
    }
    const bool arc = motion_ == 2 || motion_ == 3;
    if (arc) {
      const std::string arcCode = motion_ == 2 ? "G02" : "G03";
      if (motionWord && !axisWords) emit(codes::kArcWithoutEndPoint, *motionWord, {wordText(*motionWord)});
      if (!cannedCycle && has('R') && (has('I') || has('K'))) emit(codes::kArcRadiusAndCentre, *has('R'), {arcCode});
      // No R, I or K: "not on one circle (radius 0)" at run time said nothing useful.
      if (!cannedCycle && axisWords && !has('R') && !has('I') && !has('K'))
        emit(codes::kArcWithoutRadius, motionWord ? *motionWord : *(has('X') ? has('X') : has('Z') ? has('Z') : has('U') ? has('U') : has('W')), {arcCode});
      if (compWord && (motionWord || axisWords)) {
        if (compCode == 40) emit(codes::kCompEndOnArc, *compWord, {arcCode});
        else emit(codes::kCompStartOnArc, *compWord, {wordText(*compWord), arcCode});
      }
    }
  }

 private:
  const CheckOptions& options_;
  const MachineProfile& profile_;
  std::vector<Diagnostic>& out_;
  std::string letters_;  // the profile's letters, spaced, for E201
  std::uint32_t allowedLetters_;  // the profile's letters, one bit each (Block::letterBit)
  bool inch_;            // inch in force: G20 seen last, or inch at power-on
  int motion_ = 0;      // group 01 code in force (G00 at start)
  bool full_ = false;

  // (A bit test: it is asked twice for every word of the program.)
  bool allowed(char l) const { return (allowedLetters_ & Block::letterBit(l)) != 0; }
  static std::uint32_t letterMask(std::string_view letters) {
    std::uint32_t mask = 0;
    for (char l : letters) mask |= Block::letterBit(l);
    return mask;
  }

  void emit(const char* code, const Word& w, std::vector<std::string> args, Severity severity = Severity::Error) {
    emit(code, w.range, std::move(args), severity);
  }
  void emit(const char* code, SourceRange range, std::vector<std::string> args,
            Severity severity = Severity::Error) {
    if (full_) return;
    if (out_.size() + 1 >= codes::kMaxDiagnostics) {
      out_.push_back(Diagnostic{Severity::Error, codes::kTooManyDiagnostics, {range.line, range.column, 0},
                                {std::to_string(codes::kMaxDiagnostics)}});
      full_ = true;
      return;
    }
    out_.push_back(Diagnostic{severity, code, range, std::move(args)});
  }

  InputUnits units() const { return inch_ ? InputUnits::Inch : InputUnits::Millimetre; }

  // SPEC 4's kind of a letter, unless the block's code lists it otherwise.
  static char defaultKind(char l) {
    switch (l) {
      case 'F': case 'S': return '+';
      case 'P': case 'Q': return '#';
      case 'T': return 'T';
      case 'G': case 'M': case 'N': case 'O': return 0;  // checked with the codes
      default: return '.';
    }
  }

  void checkValue(const Word& w, const CodeInfo* row) {
    char kind = row ? wordKind(*row, w.letter) : 0;
    if (!kind) kind = defaultKind(w.letter);
    if (kind == 'd')  // a dwell time: the profile says how P is read
      kind = profile_.dwellP == DwellPUnit::SecondsWithPointElseMs && w.hasDecimalPoint ? 's' : '#';
    if (kind == 'i') kind = w.hasDecimalPoint ? '+' : '#';  // Q5. is 5 mm, Q5000 is 5000 increments
    switch (kind) {
      case '.': checkReal(w, false); break;
      case '+': {
        // S (rpm, m/min or ft/min) keeps one range in both units.
        const bool unitless = w.letter == 'S';
        const double min = unitless ? profile_.minPositiveMm : minPositive();
        if (!(w.value >= min))
          emit(codes::kNotPositive, w, {wordText(w), std::string(1, w.letter), limitText(min),
                                        limitText(unitless ? profile_.maxAbsMm : maxAbs())});
        else checkReal(w, true, unitless);
        break;
      }
      case '#':
        if (wholeNumber(w) < 0) emit(codes::kNotWholeNumber, w, {wordText(w), std::string(1, w.letter)});
        break;
      case 's':  // seconds (Haas G04 P3.)
        if (w.value < 0) emit(codes::kNegativeDwell, w, {wordText(w)});
        else checkReal(w, false);
        break;
      case 'T': checkTool(w); break;
      default: break;
    }
  }

  double maxAbs() const { return inch_ ? profile_.maxAbsInch : profile_.maxAbsMm; }
  double minPositive() const { return inch_ ? profile_.minPositiveInch : profile_.minPositiveMm; }

  void checkReal(const Word& w, bool positive, bool unitless = false) {
    const double max = unitless ? profile_.maxAbsMm : maxAbs();
    const double min = positive ? (unitless ? profile_.minPositiveMm : minPositive()) : -max;
    if (!(w.value >= min && w.value <= max)) {
      emit(codes::kOutOfRange, w, {wordText(w), limitText(min), limitText(max)});
      return;
    }
    const int maxDecimals = incrementDecimals(profile_, units());
    if (w.decimals <= maxDecimals) return;
    if (profile_.extraDecimals == ExtraDecimals::Error) {
      emit(codes::kTooManyDecimals, w, {wordText(w), std::to_string(maxDecimals)});
    } else {
      const double rounded = roundToIncrement(w.value, profile_, units());
      emit(codes::kRoundedToIncrement, w,
           {wordText(w), std::string(1, w.letter) + formatFixed(rounded, maxDecimals), std::to_string(maxDecimals)},
           Severity::Warning);
    }
  }

  void checkTool(const Word& w) {
    const int tool = toolStation(w, profile_, options_.turretStations);
    const int maxTool = profile_.maxToolStation > 0 ? profile_.maxToolStation : options_.turretStations;
    if (tool < 0) {
      if (profile_.minToolDigits < 4)
        emit(codes::kBadToolWordFanuc, w, {wordText(w), twoDigits(maxTool), twoDigits(profile_.maxOffset)});
      else
        emit(codes::kBadToolWord, w, {wordText(w)});
      return;
    }
    if (options_.toolsWithBitmap && tool > 0) {
      const auto& tools = *options_.toolsWithBitmap;
      if (std::find(tools.begin(), tools.end(), tool) == tools.end())
        emit(codes::kToolWithoutBitmap, w, {wordText(w), twoDigits(tool)});
    }
  }

  void checkDwell(const Block& block, const Word& g04, const Word* seconds, const Word* millis) {
    if (!seconds && !millis) {
      emit(codes::kDwellWithoutTime, g04, {});
    } else {
      if (seconds && seconds->value < 0) emit(codes::kNegativeDwell, *seconds, {wordText(*seconds)});
      if (seconds && millis) {
        const bool pFirst = millis->range.column < seconds->range.column;
        const Word& a = pFirst ? *millis : *seconds;
        const Word& b = pFirst ? *seconds : *millis;
        emit(codes::kDwellTwice, b, {wordText(a), wordText(b)});
      }
    }
    for (const Word& w : block.words)
      if (w.letter == 'Z' || w.letter == 'W' || w.letter == 'I' || w.letter == 'K' || w.letter == 'R' ||
          w.letter == 'C' || w.letter == 'H')
        emit(codes::kDwellWithAxis, w, {wordText(w)});
  }
};

}  // namespace

std::vector<Diagnostic> checkToolBitmaps(const Program& program, const CheckOptions& options) {
  std::vector<Diagnostic> out;
  if (!options.toolsWithBitmap) return out;
  const MachineProfile& profile = machineProfile(options.dialect);
  if (profile.letters.find('T') == std::string_view::npos) return out;
  const std::vector<int>& tools = *options.toolsWithBitmap;
  for (const Block& b : program.blocks) {
    if (b.statement.kind != StatementKind::None || !b.has('T')) continue;  // (most blocks: one pass, no T)
    // As check(): a macro call's letters are its arguments, T too.
    const bool macroCall = profile.flow.macroB && std::any_of(b.words.begin(), b.words.end(), [](const Word& w) {
      return w.letter == 'G' && w.expr < 0 && !w.hasDecimalPoint && (w.value == 65.0 || w.value == 66.0);
    });
    if (macroCall) continue;
    for (const Word& w : b.words) {
      if (w.letter != 'T' || w.comma || w.expr >= 0) continue;
      const int tool = toolStation(w, profile, options.turretStations);
      if (tool > 0 && std::find(tools.begin(), tools.end(), tool) == tools.end())
        out.push_back(Diagnostic{Severity::Error, codes::kToolWithoutBitmap, w.range, {w.text(), twoDigits(tool)}});
      if (out.size() >= codes::kMaxDiagnostics) return out;
    }
  }
  return out;
}

std::vector<Diagnostic> check(const Program& program, const CheckOptions& options) {
  std::vector<Diagnostic> out = program.lexicalDiagnostics;
  const MachineProfile& profile = machineProfile(options.dialect);
  if (!profile.commentToLineEnd || !profile.blanksInWords) {
    // The profile's strict reading of comments and blanks (the 1999 rules).
    for (Diagnostic& d : out)
      if (d.code == codes::kCommentToLineEnd && !profile.commentToLineEnd) {
        d.code = codes::kUnclosedComment;
        d.severity = Severity::Error;
      }
    for (const Block& block : program.blocks)
      for (const Word& w : block.words)
        if (w.blanks && !profile.blanksInWords)
          out.push_back(Diagnostic{Severity::Error, codes::kBlanksInWord, w.range, {w.text()}});
  }
  Checker checker(options, out);
  if (options.stopAtFirstError && hasErrors(out)) return out;
  std::size_t seen = out.size();  // diagnostics already looked at for stopAtFirstError
  bool first = true;
  int file = 0;
  for (const Block& block : program.blocks) {
    // Each subprogram file starts with its own O block.
    if (block.file != file) {
      file = block.file;
      first = true;
    }
    checker.checkBlock(block, first);
    first = false;
    if (checker.full()) break;
    if (options.stopAtFirstError) {
      for (; seen < out.size(); ++seen)
        if (isError(out[seen].severity)) return out;
    }
  }
  if (!checker.full()) checkFlow(program, options, out);
  if (options.modalRules && !checker.full() && !options.stopAtFirstError) checkModalState(program, options, out);
  // Blocks come in line order, so this only reorders within a line.
  std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.range.file != b.range.file) return a.range.file < b.range.file;
    if (a.range.line != b.range.line) return a.range.line < b.range.line;
    return a.range.column < b.range.column;
  });
  return out;
}

}  // namespace klueng::core::gcode
