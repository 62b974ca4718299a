#pragma once
// Stable diagnostic codes of the gcode module (texts in
// src/core/base/messages_gcode.cpp). One constant per code so the parser, the
// checker and the tests cannot drift apart.
#include <cstddef>

namespace klueng::core::gcode::codes {

// E1xx lexical errors and word formats (SPEC 3-4)
inline constexpr const char* kLoneLetter = "E101";        // {0}=letter
inline constexpr const char* kLoneNumber = "E102";        // {0}=number
inline constexpr const char* kMalformedNumber = "E103";   // {0}=word as written
inline constexpr const char* kUnknownCharacter = "E104";  // {0}=character
inline constexpr const char* kUnclosedComment = "E105";
inline constexpr const char* kMisplacedBlockSkip = "E106";
inline constexpr const char* kMisplacedTapeMark = "E107";
inline constexpr const char* kTextAfterTapeMark = "E108";  // {0}=word
inline constexpr const char* kTooManyLexicalErrors = "E109";
inline constexpr const char* kOutOfRange = "E110";            // {0}=word {1}=min {2}=max
inline constexpr const char* kTooManyDecimals = "E111";       // {0}=word {1}=max decimals
inline constexpr const char* kNotPositive = "E112";           // {0}=word {1}=letter {2}=min {3}=max
inline constexpr const char* kCodeNotInteger = "E113";        // {0}=word
inline constexpr const char* kUnknownGCode = "E114";          // {0}=word
inline constexpr const char* kSpindleSpeedZero = "E143";      // {0}=the S word (S0; SPEC 4: S from 0.001)
inline constexpr const char* kUnknownMCode = "E115";          // {0}=word
inline constexpr const char* kBadSequenceNumber = "E116";     // {0}=word {1}=letter {2}=max
inline constexpr const char* kBadToolWord = "E117";           // {0}=word
inline constexpr const char* kBadToolWordFanuc = "E118";      // {0}=word {1}=max tool {2}=max offset (2 digits)
inline constexpr const char* kNotWholeNumber = "E119";        // {0}=word {1}=letter
inline constexpr const char* kBlockTooLong = "E120";          // {0}=limit
inline constexpr const char* kMacroUnclosedBracket = "E121";  // '[' without ']'
inline constexpr const char* kMacroExpectedValue = "E122";    // {0}=what was found instead
inline constexpr const char* kMacroUnknownWord = "E123";      // {0}=word
inline constexpr const char* kMacroExpectedBracket = "E124";  // {0}=function
inline constexpr const char* kMacroBadVariable = "E125";      // {0}=text
inline constexpr const char* kMacroTooDeep = "E126";          // {0}=limit
inline constexpr const char* kStatementNotAlone = "E127";     // {0}=word
inline constexpr const char* kIfWithoutGotoThen = "E128";
inline constexpr const char* kWhileWithoutDo = "E129";
inline constexpr const char* kBadLoopNumber = "E130";        // {0}=number
inline constexpr const char* kExpectedAssignment = "E131";   // {0}=text
inline constexpr const char* kCornerNotOnG01 = "E132";       // {0}=word
inline constexpr const char* kChamferAndCorner = "E133";     // {0}=first {1}=second
inline constexpr const char* kExponentNumber = "E134";       // {0}=the word before {1}=the E word
inline constexpr const char* kExponentInMacro = "E139";      // {0}=the number as written (1e300)
inline constexpr const char* kBlanksInWord = "E135";         // {0}=the word without blanks (classic)
inline constexpr const char* kLetterOForZero = "E136";       // {0}=word as written {1}=the word meant
inline constexpr const char* kCommaForPoint = "E137";        // {0}=word as written {1}=the word meant
inline constexpr const char* kTextLine = "E138";             // {0}=the text (at most 20 characters)
inline constexpr const char* kTextAfterEndOfBlock = "E141";  // {0}=the text after ';' (at most 20 characters)
inline constexpr const char* kTextAfterComment = "E142";     // {0}=the text after the comment's first ')'
inline constexpr const char* kTooManyDiagnostics = "E199";   // {0}=limit

// E2nn block rule nn of SPEC 5 (E213, stock size, belongs to the io module)
inline constexpr const char* kLetterNotAllowed = "E201";        // {0}=word {1}=letter {2}=allowed letters
inline constexpr const char* kLetterTwice = "E202";             // {0}=letter
inline constexpr const char* kMustStandAlone = "E203";          // {0}=code
inline constexpr const char* kConflictingMCodes = "E204";       // {0}=first {1}=second
inline constexpr const char* kSameModalGroup = "E205";          // {0}=first {1}=second {2}=group
inline constexpr const char* kOneShotWithMotion = "E206";       // {0}=group-00 code {1}=group-01 code
inline constexpr const char* kFeedModeNotAlone = "E207";        // {0}=code
inline constexpr const char* kMisplacedO = "E208";              // {0}=word
inline constexpr const char* kNNotFirst = "E209";               // {0}=word
inline constexpr const char* kAbsoluteAndIncremental = "E210";  // {0}=absolute letter {1}=incremental
inline constexpr const char* kDwellWithoutTime = "E211";

// E3xx "ext" block rules
inline constexpr const char* kArcWithoutEndPoint = "E301";  // {0}=code
inline constexpr const char* kArcRadiusAndCentre = "E302";  // {0}=code
inline constexpr const char* kCompStartOnArc = "E303";      // {0}=comp code {1}=arc code
inline constexpr const char* kCompEndOnArc = "E304";        // {0}=arc code
inline constexpr const char* kToolWithoutBitmap = "E305";   // {0}=word {1}=tool number
inline constexpr const char* kNegativeDwell = "E306";       // {0}=word
inline constexpr const char* kDwellTwice = "E307";          // {0}=first {1}=second
inline constexpr const char* kDwellWithAxis = "E308";       // {0}=word
inline constexpr const char* kG28WithoutAxes = "E309";
inline constexpr const char* kArcWithoutRadius = "E310";  // {0}=code

// E4xx program flow (subprograms and macro B), checked before the run
inline constexpr const char* kDoWithoutEnd = "E401";                // {0}=loop number
inline constexpr const char* kEndWithoutDo = "E402";                // {0}=loop number
inline constexpr const char* kGotoNowhere = "E403";                 // {0}=word {1}=N number
inline constexpr const char* kProgramNotFound = "E404";             // {0}=word {1}=O number
inline constexpr const char* kLocalTargetMissing = "E405";          // {0}=word {1}=N number
inline constexpr const char* kBadMacroArgument = "E406";            // {0}=word {1}=letter
inline constexpr const char* kMacroNotInDialect = "E407";           // {0}=word
inline constexpr const char* kLoopsTooDeep = "E408";                // {0}=loop number
inline constexpr const char* kLoopsCross = "E409";                  // {0}=END word {1}=DO line
inline constexpr const char* kReadOnlyVariable = "E410";            // {0}=variable
inline constexpr const char* kCallsTooDeep = "E411";                // {0}=word {1}=limit
inline constexpr const char* kSubprogramFileErrors = "E412";        // {0}=file {1}=line {2}=column {3}=code
inline constexpr const char* kProfileBlockMissing = "E413";         // {0}=cycle and word {1}=N number
inline constexpr const char* kProfileEndsBeforeStart = "E415";      // {0}=cycle and Q word {1}=N of Q {2}=N of P
inline constexpr const char* kProfileStartsWithoutMotion = "E414";  // {0}=cycle and P word {1}=N number
inline constexpr const char* kProfileHoldsItsCycle = "E417";        // {0}=cycle with P and Q {1}=N of P {2}=N of Q
inline constexpr const char* kRoughingWithoutFeed = "E418";         // {0}=the cycle's G word
inline constexpr const char* kCallWithoutP = "E419";  // {0}=G65/G66: no P (was E404 "program O?"; Fanuc alarm 076)
// The called program's file name is in the folder, but as a folder (or a pipe, a device): Program::notProgramFiles.
inline constexpr const char* kProgramFileNotAFile =
    "E416";  // {0}=word {1}=O number {2}=name {3}=what (en) {4}=what (th)

// W1xx warnings
inline constexpr const char* kMachineSpecificM = "W101";  // {0}=word
inline constexpr const char* kG28NoMotion = "W102";
inline constexpr const char* kRoundedToIncrement = "W103";  // {0}=word {1}=rounded word {2}=decimals
// Modal rules (modal_check.cpp): a run-time alarm known while typing.
inline constexpr const char* kFeedMoveWithoutFeed = "W104";  // {0}=G01/G02/G03/G32
inline constexpr const char* kConstantSurfaceWithoutClamp = "W105";
inline constexpr const char* kArcRadiusCannotJoin = "W106";     // {0}=R word {1}=half the chord
inline constexpr const char* kCornerWordWithoutComma = "W107";  // {0}=the word, {1}=",C" or ",R"
// Comments and blanks as people write them (issue 26), from the parser.
inline constexpr const char* kCommentToLineEnd = "W108";  // '(' not closed: the comment runs to the line end
                                                          // (E105 in a profile where that is an error)
inline constexpr const char* kBlanksInNumber = "W109";    // {0}=word as written {1}=as read ("X20 30" = X2030)
// Decimal point input (decimal_point.h): a word whose other reading is clearly meant.
inline constexpr const char* kPointlessLengthInIncrements =
    "W110";                                                   // {0}=word {1}=as read {2}=word with a point {3}=whole
inline constexpr const char* kPointlessLengthWhole = "W111";  // {0}=word {1}=as read {2}=in increments {3}=that word
// A single cycle code (G90/G92/G94, system B G77/G78/G79) with no X/U or Z/W: a modal code in a block
// without motion moves nothing on a Fanuc (was E140, which no manual supports: docs/dialects.md §10).
inline constexpr const char* kSingleCycleWithoutEnd = "W112";  // {0}=the cycle's G word
// `G92 S2500` read in system A: the threading cycle's code with only S sets the spindle speed; in
// system B it is the clamp. A warning, and suggestDialect offers a system-B machine.
inline constexpr const char* kClampOfAnotherSystem = "W115";    // {0}=the G word {1}=the S word
inline constexpr const char* kSameGroupLastWins = "W116";       // {0}=first {1}=second (used) {2}=group
inline constexpr const char* kProgramNumberZero = "W117";       // {0}=word
inline constexpr const char* kStopCodeWithOtherWords = "W118";  // {0}=word (M00 M01 M02 M30)
// A code of the control that Klueng does not simulate (G68 double turret, G12.1 polar interpolation):
// the check reads on, a run stops there with A117 (was E113/E114, a false "not a code of this lathe").
inline constexpr const char* kCodeNotSimulated = "W119";       // {0}=word
inline constexpr const char* kLoneCloseAfterComment = "W113";  // {0}=what follows a comment's first ')' (no letter)
inline constexpr const char* kWordsAfterEndOfBlock = "W114";   // {0}=the words after ';'

// I1xx notes
inline constexpr const char* kDialectFits = "I102";        // {0}=blocks {1}=dialect name {2}=dialect id
inline constexpr const char* kAngleWithoutComma = "I106";  // {0}=the A word {1}=with its comma
inline constexpr const char* kTrailerSkipped = "I163";     // {0}=first {1}=last line after the closing '%'
inline constexpr const char* kLeaderSkipped = "I105";      // {0}=the last line of the leader before the first '%'

// Every code above, for the catalog completeness test.
inline constexpr const char* kAll[] = {
    kLoneLetter,
    kLoneNumber,
    kMalformedNumber,
    kUnknownCharacter,
    kUnclosedComment,
    kMisplacedBlockSkip,
    kMisplacedTapeMark,
    kTextAfterTapeMark,
    kTooManyLexicalErrors,
    kMacroUnclosedBracket,
    kMacroExpectedValue,
    kMacroUnknownWord,
    kMacroExpectedBracket,
    kMacroBadVariable,
    kMacroTooDeep,
    kStatementNotAlone,
    kIfWithoutGotoThen,
    kWhileWithoutDo,
    kBadLoopNumber,
    kExpectedAssignment,
    kCornerNotOnG01,
    kChamferAndCorner,
    kExponentNumber,
    kExponentInMacro,
    kBlanksInWord,
    kLetterOForZero,
    kCommaForPoint,
    kTextLine,
    kDoWithoutEnd,
    kEndWithoutDo,
    kGotoNowhere,
    kProgramNotFound,
    kLocalTargetMissing,
    kBadMacroArgument,
    kMacroNotInDialect,
    kLoopsTooDeep,
    kLoopsCross,
    kReadOnlyVariable,
    kCallsTooDeep,
    kSubprogramFileErrors,
    kProfileBlockMissing,
    kProfileEndsBeforeStart,
    kProfileStartsWithoutMotion,
    kProfileHoldsItsCycle,
    kRoughingWithoutFeed,
    kCallWithoutP,
    kProgramFileNotAFile,
    kOutOfRange,
    kTooManyDecimals,
    kNotPositive,
    kCodeNotInteger,
    kUnknownGCode,
    kSpindleSpeedZero,
    kUnknownMCode,
    kBadSequenceNumber,
    kBadToolWord,
    kBadToolWordFanuc,
    kNotWholeNumber,
    kBlockTooLong,
    kTooManyDiagnostics,
    kLetterNotAllowed,
    kLetterTwice,
    kMustStandAlone,
    kConflictingMCodes,
    kSameModalGroup,
    kOneShotWithMotion,
    kFeedModeNotAlone,
    kMisplacedO,
    kNNotFirst,
    kAbsoluteAndIncremental,
    kDwellWithoutTime,
    kArcWithoutEndPoint,
    kArcRadiusAndCentre,
    kCompStartOnArc,
    kCompEndOnArc,
    kToolWithoutBitmap,
    kNegativeDwell,
    kDwellTwice,
    kDwellWithAxis,
    kG28WithoutAxes,
    kArcWithoutRadius,
    kMachineSpecificM,
    kG28NoMotion,
    kRoundedToIncrement,
    kCommentToLineEnd,
    kBlanksInNumber,
    kDialectFits,
    kLeaderSkipped,
    kTrailerSkipped,
    kAngleWithoutComma,
    kPointlessLengthInIncrements,
    kPointlessLengthWhole,
    kSingleCycleWithoutEnd,
    kTextAfterEndOfBlock,
    kTextAfterComment,
    kLoneCloseAfterComment,
    kWordsAfterEndOfBlock,
    kClampOfAnotherSystem,
    kSameGroupLastWins,
};

// Beyond these, a hostile input only repeats itself; the report ends with
// E109 / E199 instead of growing without bound.
inline constexpr std::size_t kMaxLexicalDiagnostics = 2000;
inline constexpr std::size_t kMaxDiagnostics = 10000;
// A real block has a handful of words; past this the line is junk and the
// rest of it is not read (bounds memory on a 10 MB single line).
inline constexpr std::size_t kMaxWordsPerBlock = 1000;

}  // namespace klueng::core::gcode::codes
