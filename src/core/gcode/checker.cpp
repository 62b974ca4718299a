// The grammar checker (SPEC 4-5, 13 and the "ext" rules): one pass over the
// blocks, every diagnostic reported, driven by the code table.
#include "klueng/core/gcode/checker.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <string>

#include "code_index.h"
#include "diagnostic_codes.h"
#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/parser.h"
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
  const auto [tool, offset] = splitToolNumber(n);
  const int maxTool = profile.maxToolStation > 0 ? profile.maxToolStation : turretStations;
  // T0000: the turret stays and the offset is cancelled (an offset for tool 00, T0017, is refused).
  // Homing lines write it as T0 or T00 as often (`G53 G00 X100 Z150 T00`): zero in any number of digits.
  const bool keepTurret = profile.toolZeroKeepsTurret && tool == 0 && offset == 0;
  const bool shapeOk = n >= 0 && (digits >= profile.minToolDigits || (keepTurret && digits >= 1)) && digits <= 4;
  return !shapeOk || (tool < 1 && !keepTurret) || tool > maxTool || offset > profile.maxOffset ? -1 : tool;
}

// G65 / G66: the block's letters are the macro's arguments (G67 takes none).
// An error of the classic rules that no manual of this control makes a stop: a warning here
// (machine file key error_codes_as_warnings, docs/dialects.md §10).
bool isErrorAsWarning(const MachineProfile& profile, const char* code) {
  if (profile.errorsAsWarnings.empty() || code[0] != 'E') return false;
  int number = 0;
  const char* end = code + std::char_traits<char>::length(code);
  if (std::from_chars(code + 1, end, number).ptr != end) return false;
  return std::find(profile.errorsAsWarnings.begin(), profile.errorsAsWarnings.end(), number) !=
         profile.errorsAsWarnings.end();
}

bool isMacroCallBlock(const Block& block, Dialect dialect) {
  const CodeInfo* row = nullptr;
  return macroCallWord(block, dialect, &row) && row->action != CodeAction::MacroModalCancel;
}

// A block with a canned or single cycle code (its words are the cycle's, A too).
bool hasCycleCode(const Block& block) {
  for (const Word* g : block.all('G')) {
    if (g->expr >= 0 || g->hasDecimalPoint) continue;
    if (g->code() >= 70 && g->code() <= 94 && g->code() != 80) return true;
  }
  return false;
}

bool isRuleFourGroup(ModalGroup g) {
  return g == ModalGroup::MSpindle || g == ModalGroup::MCoolant || g == ModalGroup::MCAxis || g == ModalGroup::MBrake ||
         g == ModalGroup::MGear || g == ModalGroup::MSubprogram || g == ModalGroup::MChuck ||
         g == ModalGroup::MAirBlast || g == ModalGroup::MTailstock || g == ModalGroup::MThreadChamfer ||
         g == ModalGroup::MConveyor || g == ModalGroup::MPartsCatcher || g == ModalGroup::MDoor ||
         g == ModalGroup::MHighPressureCoolant;
}

constexpr int kGroupCount = static_cast<int>(ModalGroup::MOther) + 1;
static_assert(kGroupCount <= 64, "group masks are 64-bit");

class Checker {
 public:
  Checker(const CheckOptions& options, std::vector<Diagnostic>& out)
      : options_(options),
        profile_(machineProfile(options.dialect)),
        codes_(detail::codeIndexOf(options.dialect)),
        out_(out),
        letters_(spaced(profile_.letters)),
        allowedLetters_(letterMask(profile_.letters)),
        inch_(options.powerOnUnits.value_or(profile_.powerOnUnits) == InputUnits::Inch) {}

  bool full() const { return full_; }

  // One block, rule group by rule group (as rs274ngc's check_g_codes,
  // check_m_codes and check_other_codes): the words one by one, then their
  // values, then the rules that need the whole block.
  void checkBlock(const Block& block, bool firstBlock) {
    if (block.statement().kind != StatementKind::None) {
      checkStatement(block);
      return;
    }
    // A macro call's block: its letters are arguments (A -> #1 ...), not addresses.
    const bool macroCall = profile_.flow.macroB && isMacroCall(block);
    noteUnits(block);
    BlockCodes seen;
    readWords(block, firstBlock, macroCall, seen);
    if (full_) return;
    // Values, once the block's codes are known: a word's kind may depend on
    // its code (Haas G83 Q0.1 is a length, Fanuc G83 Q5000 least increments).
    if (macroCall) return;  // the arguments are the macro's to judge
    for (const Word& w : block.words) {
      if (full_) return;
      if (allowed(w.letter) && w.expr < 0 && !w.comma) checkValue(w, seen.wordRow);
    }
    checkCodeRules(seen);
    checkOtherRules(block, seen);
    // The motion group is modal, so "X20 Z-5 R2" after a G02 is an arc too.
    if (seen.motion) motion_ = seen.motion->action;
    checkCornerWords(block, seen);
    checkArc(seen);
  }

 private:
  // What the first pass over a block's words found. Slots are valid only where
  // the mask bit is set: no per-block clearing of the arrays (this runs for
  // every block of a 100,000-block program).
  struct BlockCodes {
    std::uint32_t letterMask = 0;
    std::uint64_t groupMask = 0, mGroupMask = 0;
    std::array<const Word*, 26> firstOfLetter;
    std::array<const Word*, kGroupCount> firstOfGroup;
    std::array<const Word*, kGroupCount> firstMOfGroup;
    const Word* standAlone[4] = {};
    int standAloneCount = 0;
    const Word* motionWord = nullptr;   // last valid group-01 G word
    const CodeInfo* motion = nullptr;   // its row
    const Word* oneShotWord = nullptr;  // first group-00 G word
    const CodeInfo* oneShot = nullptr;
    const CodeInfo* wordRow = nullptr;  // the code whose word list sets the kinds of this block's words
    const Word* dwell = nullptr;        // G04
    const Word* reference = nullptr;    // G28
    const Word* singleCycle = nullptr;  // G90/G92/G94 (system A), G77/G78/G79 (B)
    CodeAction singleCycleAction = CodeAction::None;
    const Word* compWord = nullptr;  // G40 G41 G42
    const CodeInfo* comp = nullptr;
    bool cannedCycle = false;
    int nonNWords = 0;

    const Word* has(char l) const {
      const auto index = static_cast<std::size_t>(l - 'A');
      return (letterMask >> index) & 1u ? firstOfLetter[index] : nullptr;
    }
    bool axisWords() const { return has('X') || has('Z') || has('U') || has('W'); }
  };

  static const Word* later(const Word* a, const Word* b) { return a->range.column > b->range.column ? a : b; }

  // A macro statement: its N word and the dialect (expressions are checked by the reader).
  void checkStatement(const Block& block) {
    for (const Word& w : block.words)
      if (w.letter == 'N' && w.expr < 0) checkSequenceNumber(w);
    if (!profile_.flow.macroB) emit(codes::kMacroNotInDialect, block.statement().range, {"#"});
  }

  // The row of a G or M code number in this machine's code index (as findCode, without
  // asking the registry for every word of a 100,000-block program).
  const CodeInfo* row(char letter, long long n) const {
    return n >= 0 && n < kCodeNumbers ? codes_.rows[letter == 'G' ? 0 : 1][static_cast<std::size_t>(n)] : nullptr;
  }

  // G65 / G66 (as gcode::macroCallWord; G67 takes no arguments).
  bool isMacroCall(const Block& block) const {
    if (!block.mayHave('G')) return false;
    for (const Word& w : block.words) {
      if (w.letter != 'G' || w.expr >= 0 || w.hasDecimalPoint) continue;
      const CodeInfo* r = row('G', w.code());
      if (r && (r->action == CodeAction::MacroCall || r->action == CodeAction::MacroModalCall ||
                r->action == CodeAction::MacroModalCancel))
        return r->action != CodeAction::MacroModalCancel;
    }
    return false;
  }

  // Units apply to the whole block they appear in, then stay modal.
  void noteUnits(const Block& block) {
    if (!block.mayHave('G')) return;
    for (const Word& w : block.words) {
      if (w.letter != 'G') continue;
      const CodeInfo* r = row('G', wholeNumber(w));
      if (!r) continue;
      if (r->action == CodeAction::Inch)
        inch_ = true;
      else if (r->action == CodeAction::Metric)
        inch_ = false;
    }
  }

  // The first pass: letters (rules 1, 2, 9), N and O words, and the G and M codes.
  void readWords(const Block& block, bool firstBlock, bool macroCall, BlockCodes& seen) {
    const int wordCount = static_cast<int>(block.words.size());
    for (int i = 0; i < wordCount && !full_; ++i) {
      const Word& w = block.words[static_cast<std::size_t>(i)];
      const char l = w.letter;
      if (l != 'N') ++seen.nonNWords;
      if (w.comma) continue;  // ,C ,R ,A: checked with the corner rules
      if (w.expr >= 0) {
        // X#1: the value is known when the block runs; only the letter is checked here.
        if (!profile_.flow.macroB)
          emit(codes::kMacroNotInDialect, w, {wordText(w)});
        else if (!allowed(l) && !macroCall)
          emit(codes::kLetterNotAllowed, w, {wordText(w), std::string(1, l), letters_});
        continue;
      }
      if (macroCall && l != 'G' && l != 'N' && l != 'O') {
        if (seen.letterMask & (1u << static_cast<std::size_t>(l - 'A')))
          emit(codes::kLetterTwice, w, {std::string(1, l)});
        seen.letterMask |= 1u << static_cast<std::size_t>(l - 'A');
        continue;  // an argument: any value
      }
      if (!allowed(l)) {
        checkUnknownLetter(block, i);
        continue;
      }
      const auto letterIndex = static_cast<std::size_t>(l - 'A');
      const std::uint32_t letterBit = 1u << letterIndex;
      if (seen.letterMask & letterBit) {
        // A second N is reported once, by rule 9 (N only first).
        if (onceOnly(l) && l != 'N') emit(codes::kLetterTwice, w, {std::string(1, l)});
      } else {
        seen.letterMask |= letterBit;
        seen.firstOfLetter[letterIndex] = &w;
      }
      switch (l) {
        case 'N':
          checkSequenceNumber(w);
          if (i != 0) emit(codes::kNNotFirst, w, {wordText(w)});
          break;
        case 'O': checkProgramNumber(w, i == 0 && wordCount == 1, firstBlock); break;
        case 'G':
        case 'M': readCode(w, seen); break;
        default: break;
      }
    }
  }

  // The motion a block moves with: its own group-01 code, else the modal one.
  CodeAction motionOf(const Block& block) const {
    for (const Word* g : block.all('G')) {
      if (g->expr >= 0 || g->hasDecimalPoint) continue;
      if (const CodeInfo* row = findCode('G', g->code(), options_.dialect); row && row->group == ModalGroup::Motion)
        return row->action;
    }
    return motion_;
  }

  // A letter the profile has not. X1e9, Z2.5E-3: a number written with an
  // exponent reads as two words; say so.
  void checkUnknownLetter(const Block& block, int i) {
    const Word& w = block.words[static_cast<std::size_t>(i)];
    const Word* before = i > 0 ? &block.words[static_cast<std::size_t>(i - 1)] : nullptr;
    if (w.letter == 'E' && before && before->expr < 0 && !before->comma && before->range.line == w.range.line &&
        before->range.column + before->range.length == w.range.column && !before->number.empty() &&
        (std::isdigit(static_cast<unsigned char>(before->number.back())) != 0 || before->number.back() == '.')) {
      SourceRange both = before->range;
      both.length = before->range.length + w.range.length;
      emit(codes::kExponentNumber, both, {wordText(*before), wordText(w)});
      return;
    }
    emit(codes::kLetterNotAllowed, w, {wordText(w), std::string(1, w.letter), letters_});
    // `G01 X40. A-45.`: a Fanuc 0-T's angle (parameter 3405#4); offered, not assumed.
    if (w.letter == 'A' && profile_.family == Dialect::Fanuc && motionOf(block) == CodeAction::Line &&
        !hasCycleCode(block))
      emit(codes::kAngleWithoutComma, w, {wordText(w), "," + wordText(w)}, Severity::Note);
  }

  void checkSequenceNumber(const Word& w) {
    const long long n = wholeNumber(w);
    if (n < 1 || n > profile_.sequenceNumberMax)
      emit(codes::kBadSequenceNumber, w, {wordText(w), "N", std::to_string(profile_.sequenceNumberMax)});
  }

  void checkProgramNumber(const Word& w, bool alone, bool firstBlock) {
    if (w.colon && !profile_.colonProgramNumber) {
      // ':' is not an address of this control: the seed's E104, naming ':'.
      emit(codes::kUnknownCharacter, SourceRange{w.range.line, w.range.column, 1}, {":"});
      return;
    }
    const long long n = wholeNumber(w);
    if (n == 0 && !profile_.programNumberZeroIsError)
      emit(codes::kProgramNumberZero, w, {wordText(w)}, Severity::Warning);
    else if (n < 1 || n > profile_.programNumberMax)
      emit(codes::kBadSequenceNumber, w, {wordText(w), "O", std::to_string(profile_.programNumberMax)});
    if (!(alone && (firstBlock || profile_.flow.programsInOneFile))) emit(codes::kMisplacedO, w, {wordText(w)});
  }

  // A G or M word: known to the dialect, and one per modal group (rules 4 and 5).
  void readCode(const Word& w, BlockCodes& seen) {
    if (w.hasDecimalPoint) {
      // G12.1, G05.1 ...: a code of the control with a point in its number (its own table).
      if (const DecimalCode* d = w.letter == 'G' ? findDecimalCode(w.value, profile_.dialect) : nullptr) {
        if (d->changesPath) emit(codes::kCodeNotSimulated, w, {wordText(w)}, Severity::Warning);
        return;
      }
      emit(codes::kCodeNotInteger, w, {wordText(w)});
      return;
    }
    const long long n = wholeNumber(w);
    const CodeInfo* found = row(w.letter, n);
    if (found && found->action == CodeAction::NotSimulated)
      emit(codes::kCodeNotSimulated, w, {wordText(w)}, Severity::Warning);
    if (!found) {
      if (w.letter == 'G')
        emit(codes::kUnknownGCode, w, {wordText(w)});
      else if (n > 99 ? profile_.highMIsWarning : profile_.unknownMIsWarning)
        emit(codes::kMachineSpecificM, w, {wordText(w)}, Severity::Warning);
      else
        emit(codes::kUnknownMCode, w, {wordText(w)});
      return;
    }
    if (found->mustStandAlone() && seen.standAloneCount < 4) seen.standAlone[seen.standAloneCount++] = &w;
    if (w.letter == 'G')
      readGCode(w, *found, seen);
    else
      readMCode(w, *found, seen);
  }

  void readGCode(const Word& w, const CodeInfo& row, BlockCodes& seen) {
    const auto group = static_cast<std::size_t>(row.group);
    const std::uint64_t groupBit = std::uint64_t{1} << group;
    if (seen.groupMask & groupBit) {
      // Fanuc: "only the last G code specified is valid" (docs/dialects.md §2); group 00 is no mode.
      const bool lastWins = profile_.sameGroupLastWins && row.group != ModalGroup::NonModal;
      emit(lastWins ? codes::kSameGroupLastWins : codes::kSameModalGroup, w,
           {wordText(*seen.firstOfGroup[group]), wordText(w), std::string(modalGroupNumber(row.group))},
           lastWins ? Severity::Warning : Severity::Error);
    } else {
      seen.groupMask |= groupBit;
      seen.firstOfGroup[group] = &w;
    }
    if (row.group == ModalGroup::Motion) {
      seen.motionWord = &w;
      seen.motion = &row;
    } else if (row.group == ModalGroup::NonModal && !seen.oneShotWord) {
      seen.oneShotWord = &w;
      seen.oneShot = &row;
    } else if (row.group == ModalGroup::NoseComp) {
      seen.compWord = &w;
      seen.comp = &row;
    } else if (row.group == ModalGroup::CannedCycle) {
      seen.cannedCycle = true;
    }
    if (row.words.any() && !seen.wordRow) seen.wordRow = &row;
    if (row.action == CodeAction::Dwell) seen.dwell = &w;
    if (row.action == CodeAction::ReferenceReturn) seen.reference = &w;
    if (row.action == CodeAction::BoxTurning || row.action == CodeAction::BoxThreading ||
        row.action == CodeAction::BoxFacing) {
      seen.singleCycle = &w;
      seen.singleCycleAction = row.action;
    }
  }

  void readMCode(const Word& w, const CodeInfo& row, BlockCodes& seen) {
    if (!isRuleFourGroup(row.group)) return;
    const auto group = static_cast<std::size_t>(row.group);
    const std::uint64_t groupBit = std::uint64_t{1} << group;
    if (seen.mGroupMask & groupBit) {
      emit(codes::kConflictingMCodes, w, {wordText(*seen.firstMOfGroup[group]), wordText(w)});
    } else {
      seen.mGroupMask |= groupBit;
      seen.firstMOfGroup[group] = &w;
    }
  }

  // Rules 3 and 7 (stand-alone codes; N may come before them) and rule 6 (a
  // one-shot G with a motion G).
  void checkCodeRules(const BlockCodes& seen) {
    for (int k = 0; k < seen.standAloneCount; ++k) {
      if (seen.nonNWords <= 1) continue;
      const Word& w = *seen.standAlone[k];
      if (w.letter == 'M' && !profile_.stopCodesAloneIsError)
        emit(codes::kStopCodeWithOtherWords, w, {wordText(w)}, Severity::Warning);
      else
        emit(w.letter == 'G' ? codes::kFeedModeNotAlone : codes::kMustStandAlone, w, {wordText(w)});
    }
    const auto& withMotion = profile_.oneShotsWithMotion;
    if (seen.oneShotWord && seen.motionWord &&
        std::find(withMotion.begin(), withMotion.end(), seen.oneShot->number) == withMotion.end()) {
      const Word* second = later(seen.oneShotWord, seen.motionWord);
      emit(codes::kOneShotWithMotion, *second, {wordText(*seen.oneShotWord), wordText(*seen.motionWord)});
    }
  }

  // Rule 10 (absolute and incremental words of one axis), rule 11 with the
  // dwell's own rules, and a G28 without axis words (it moves nothing).
  void checkOtherRules(const Block& block, const BlockCodes& seen) {
    static constexpr std::array<std::pair<char, char>, 3> kPairs{{{'X', 'U'}, {'Z', 'W'}, {'C', 'H'}}};
    for (const auto& [abs, inc] : kPairs)
      if (seen.has(abs) && seen.has(inc))
        emit(codes::kAbsoluteAndIncremental, *later(seen.has(abs), seen.has(inc)),
             {std::string(1, abs), std::string(1, inc)});
    if (seen.dwell) checkDwell(block, *seen.dwell, seen.has('U') ? seen.has('U') : seen.has('X'), seen.has('P'));
    // A single cycle code without its end point only selects the mode: the control moves nothing
    // (the safety line `G18 G20 G40 G80 G90 G99`). `G92 S3000` (system B's clamp read in system A)
    // sets 3000 rpm: a warning, and suggestDialect offers the system-B machine.
    if (seen.singleCycle && !seen.axisWords()) {
      if (const Word* s = block.find('S'); s && seen.singleCycleAction == CodeAction::BoxThreading)
        emit(codes::kClampOfAnotherSystem, *seen.singleCycle, {wordText(*seen.singleCycle), wordText(*s)},
             Severity::Warning);
      else
        emit(codes::kSingleCycleWithoutEnd, *seen.singleCycle, {wordText(*seen.singleCycle)}, Severity::Warning);
    }
    if (seen.reference && !seen.axisWords()) {
      if (profile_.bareG28 == BareG28::NoMotion)
        emit(codes::kG28NoMotion, *seen.reference, {}, Severity::Warning);
      else if (profile_.bareG28 == BareG28::Error)
        emit(codes::kG28WithoutAxes, *seen.reference, {});
    }
  }

  // Chamfer and corner words (Fanuc 0i-TF ",C" ",R" ",A"): on a G01 only, one corner kind.
  void checkCornerWords(const Block& block, const BlockCodes& seen) {
    const bool onLine = motion_ == CodeAction::Line && !seen.cannedCycle && !seen.oneShotWord;
    const Word* chamfer = nullptr;
    const Word* corner = nullptr;
    for (const Word& w : block.words) {
      if (!w.comma) continue;
      const bool known = w.letter == 'C' || w.letter == 'R' || w.letter == 'A';
      if (!known || !onLine) {
        emit(codes::kCornerNotOnG01, w, {"," + wordText(w)});
        continue;
      }
      if (w.letter == 'C') chamfer = &w;
      if (w.letter == 'R') corner = &w;
      if (w.expr < 0) checkValue(w, nullptr);
    }
    if (chamfer && corner)
      emit(codes::kChamferAndCorner, *later(chamfer, corner), {"," + wordText(*chamfer), "," + wordText(*corner)});
    // The forms "X30. K-2." / "Z-20. R3." (a 90-degree chamfer or round without the comma):
    // read where the machine file says its control reads them, else said, not left sharp unsaid.
    if (!onLine) return;
    for (const char letter : {'I', 'K', 'R'})
      if (const Word* w = seen.has(letter);
          w && !w->comma && w->expr < 0 &&
          !(letter == 'R' ? profile_.flow.cornerRWithoutComma : profile_.flow.chamferWithIOrK)) {
        std::string size(w->number.view());
        if (!size.empty() && (size[0] == '-' || size[0] == '+')) size.erase(0, 1);
        emit(codes::kCornerWordWithoutComma, *w, {wordText(*w), (letter == 'R' ? ",R" : ",C") + size},
             Severity::Warning);
      }
  }

  // Arcs: an end point, a radius or a centre (not both), and no compensation
  // starting or ending on one.
  void checkArc(const BlockCodes& seen) {
    if (motion_ != CodeAction::ArcCw && motion_ != CodeAction::ArcCcw) return;
    const CodeInfo* arcRow = findAction('G', motion_, options_.dialect);
    const std::string arcCode = arcRow ? codeWord(*arcRow) : std::string();
    const bool axisWords = seen.axisWords();
    if (seen.motionWord && !axisWords) emit(codes::kArcWithoutEndPoint, *seen.motionWord, {wordText(*seen.motionWord)});
    if (!seen.cannedCycle && seen.has('R') && (seen.has('I') || seen.has('K')))
      emit(codes::kArcRadiusAndCentre, *seen.has('R'), {arcCode});
    // No R, I or K: "not on one circle (radius 0)" at run time said nothing useful.
    if (!seen.cannedCycle && axisWords && !seen.has('R') && !seen.has('I') && !seen.has('K')) {
      const Word* at = seen.motionWord;
      for (const char axis : {'X', 'Z', 'U', 'W'})
        if (!at) at = seen.has(axis);
      emit(codes::kArcWithoutRadius, *at, {arcCode});
    }
    if (seen.compWord && (seen.motionWord || axisWords)) {
      if (seen.comp->action == CodeAction::CompOff)
        emit(codes::kCompEndOnArc, *seen.compWord, {arcCode});
      else
        emit(codes::kCompStartOnArc, *seen.compWord, {wordText(*seen.compWord), arcCode});
    }
  }
  const CheckOptions& options_;
  const MachineProfile& profile_;
  const detail::CodeIndex& codes_;
  std::vector<Diagnostic>& out_;
  std::string letters_;                    // the profile's letters, spaced, for E201
  std::uint32_t allowedLetters_;           // the profile's letters, one bit each (Block::letterBit)
  bool inch_;                              // inch in force: G20 seen last, or inch at power-on
  CodeAction motion_ = CodeAction::Rapid;  // group 01 code in force (G00 at start)
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
  void emit(const char* code, SourceRange range, std::vector<std::string> args, Severity severity = Severity::Error) {
    if (full_) return;
    if (out_.size() + 1 >= codes::kMaxDiagnostics) {
      out_.push_back(Diagnostic{Severity::Error,
                                codes::kTooManyDiagnostics,
                                {range.line, range.column, 0},
                                {std::to_string(codes::kMaxDiagnostics)}});
      full_ = true;
      return;
    }
    if (severity == Severity::Error && isErrorAsWarning(profile_, code)) severity = Severity::Warning;
    out_.push_back(Diagnostic{severity, code, range, std::move(args)});
  }

  InputUnits units() const { return inch_ ? InputUnits::Inch : InputUnits::Millimetre; }

  // How a word's value is checked: its code's word kind resolved for this word.
  enum class ValueRule { None, Real, Positive, Whole, Seconds, Tool };

  // SPEC 4's rule for a letter, unless the block's code lists it otherwise.
  static ValueRule defaultRule(char l) {
    switch (l) {
      case 'F':
      case 'S': return ValueRule::Positive;
      case 'P':
      case 'Q': return ValueRule::Whole;
      case 'T': return ValueRule::Tool;
      case 'G':
      case 'M':
      case 'N':
      case 'O': return ValueRule::None;  // checked with the codes
      default: return ValueRule::Real;
    }
  }

  ValueRule ruleOf(const Word& w, const CodeInfo* row) const {
    switch (row ? row->words.of(w.letter) : WordKind::Default) {
      case WordKind::Default: return defaultRule(w.letter);
      case WordKind::Length: return ValueRule::Real;
      case WordKind::Positive: return ValueRule::Positive;
      case WordKind::Whole: return ValueRule::Whole;
      // A dwell time: the profile says how P is read.
      case WordKind::Dwell:
        return profile_.dwellP == DwellPUnit::SecondsWithPointElseMs && w.hasDecimalPoint ? ValueRule::Seconds
                                                                                          : ValueRule::Whole;
      // Q5. is 5 mm, Q5000 is 5000 increments.
      case WordKind::Increment: return w.hasDecimalPoint ? ValueRule::Positive : ValueRule::Whole;
    }
    return defaultRule(w.letter);
  }

  void checkValue(const Word& w, const CodeInfo* row) {
    switch (ruleOf(w, row)) {
      case ValueRule::Real: checkReal(w, false); break;
      case ValueRule::Positive: {
        // S (rpm, m/min or ft/min) keeps one range in both units.
        const bool unitless = w.letter == 'S';
        const double min = unitless ? profile_.minPositiveMm : minPositive();
        if (unitless && w.value == 0.0)
          emit(codes::kSpindleSpeedZero, w, {wordText(w)});
        else if (!(w.value >= min))
          emit(codes::kNotPositive, w,
               {wordText(w), std::string(1, w.letter), limitText(min),
                limitText(unitless ? profile_.maxAbsMm : maxAbs())});
        else
          checkReal(w, true, unitless);
        break;
      }
      case ValueRule::Whole:
        if (wholeNumber(w) < 0) emit(codes::kNotWholeNumber, w, {wordText(w), std::string(1, w.letter)});
        break;
      case ValueRule::Seconds:  // seconds (Haas G04 P3.)
        if (w.value < 0)
          emit(codes::kNegativeDwell, w, {wordText(w)});
        else
          checkReal(w, false);
        break;
      case ValueRule::Tool: checkTool(w); break;
      case ValueRule::None: break;
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
    const int maxDecimals = inch_ ? profile_.decimalsInch : profile_.decimalsMm;  // incrementDecimals, inline
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
    if (b.statement().kind != StatementKind::None || !b.has('T')) continue;  // (most blocks: one pass, no T)
    // As check(): a macro call's letters are its arguments, T too.
    if (profile.flow.macroB && isMacroCallBlock(b, options.dialect)) continue;
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

namespace {

// At most 20 code points of a tail, blanks trimmed, for a message.
std::string shownTail(std::string_view text) {
  const std::size_t b = text.find_first_not_of(" \t");
  if (b == std::string_view::npos) return {};
  const std::size_t e = text.find_last_not_of(" \t");
  std::string_view t = text.substr(b, e + 1 - b);
  std::size_t n = 0, k = 0;
  while (k < t.size() && n < 20) {
    ++k;
    while (k < t.size() && (static_cast<unsigned char>(t[k]) & 0xC0) == 0x80) ++k;
    ++n;
  }
  return std::string(t.substr(0, k));
}

bool hasLetter(std::string_view text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return std::isalpha(u) || u >= 0x80;
  });
}

// What a Fanuc reads after ';' and after a comment's first ')' (Program::tails): text that is not
// G-code stops the control (E141/E142); words after ';' run as a block Klueng does not run (W114);
// a lone ')' is a warning (W113).
void checkTextTails(const Program& program, const MachineProfile& profile, std::vector<Diagnostic>& out) {
  for (const Program::TextTail& tail : program.tails) {
    if (tail.afterEndOfBlock ? !profile.semicolonEndsBlock : !profile.commentEndsAtFirstParen) continue;
    std::string text = tail.text;
    if (!tail.afterEndOfBlock) std::replace(text.begin(), text.end(), ')', ' ');
    const Program read = parseFragment(text, tail.line, tail.file);
    const bool notGcode = hasErrors(read.lexicalDiagnostics);
    const bool words = !read.blocks.empty();
    SourceRange at{tail.line, tail.column, static_cast<int>(shownTail(tail.text).size()), tail.file};
    if (tail.afterEndOfBlock) {
      if (notGcode)
        out.push_back(Diagnostic{Severity::Error, codes::kTextAfterEndOfBlock, at, {shownTail(tail.text)}});
      else if (words)
        out.push_back(Diagnostic{Severity::Warning, codes::kWordsAfterEndOfBlock, at, {shownTail(tail.text)}});
    } else if ((notGcode || words) && hasLetter(text)) {
      out.push_back(Diagnostic{Severity::Error, codes::kTextAfterComment, at, {shownTail(tail.text)}});
    } else {
      out.push_back(Diagnostic{Severity::Warning, codes::kLoneCloseAfterComment, at, {shownTail(tail.text)}});
    }
    if (out.size() >= codes::kMaxDiagnostics) return;
  }
}

}  // namespace

std::vector<Diagnostic> check(const Program& program, const CheckOptions& options) {
  std::vector<Diagnostic> out = program.lexicalDiagnostics;
  const MachineProfile& profile = machineProfile(options.dialect);
  for (Diagnostic& d : out)
    if (d.severity == Severity::Error && isErrorAsWarning(profile, d.code.c_str())) d.severity = Severity::Warning;
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
  if (profile.semicolonEndsBlock || profile.commentEndsAtFirstParen) checkTextTails(program, profile, out);
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
  sortByPlace(out);
  return out;
}

}  // namespace klueng::core::gcode
