#pragma once
// Every diagnostic code outside the gcode module (which has gcode/diagnostic_codes.h)
// as a named constant: the catalog (src/core/base/messages_*.cpp) and the code that
// reports it use the same name, so a code cannot drift from its text (issue 12).
// The code strings themselves are stable: tests and users match on them.

#include <cstddef>

namespace klueng::core::codes {

// A setup file (machine.cfg, tools.cfg, offset.cfg, macro_variables.cfg, a
// tool library) reports at most this many problems, then F129: a hostile file
// only repeats itself, as a program's diagnostics end with E199.
inline constexpr std::size_t kMaxConfigDiagnostics = 100;

// File formats (io; texts in messages_io.cpp)
inline constexpr const char* kStockSizeNotPositive = "E213";
inline constexpr const char* kNoSuchFile = "F101";
inline constexpr const char* kCannotReadFile = "F102";
inline constexpr const char* kFileTooLarge = "F103";  // {0} file, {1} bytes read, {2} the limit ("64 MB")
inline constexpr const char* kBinaryFile = "F104";
inline constexpr const char* kEmptyFile = "F105";
inline constexpr const char* kLineTooLong = "F106";
inline constexpr const char* kLinesIgnored = "F107";
inline constexpr const char* kCannotWriteFile = "F108";  // {0} file, {1} why (English), {2} why (Thai)
inline constexpr const char* kNoSpaceToWrite = "F109";
inline constexpr const char* kHeaderTooShort = "F110";
inline constexpr const char* kDiameterUnitDigit = "F111";
inline constexpr const char* kDiameterNotNumber = "F112";
inline constexpr const char* kLengthUnitDigit = "F113";
inline constexpr const char* kLengthNotNumber = "F114";
inline constexpr const char* kDiameterMissing = "F115";
inline constexpr const char* kLengthMissing = "F116";
inline constexpr const char* kPlainGcodeFile = "F117";
inline constexpr const char* kBadBore = "F118";
inline constexpr const char* kFileReadOnly = "F119";
inline constexpr const char* kToolTableShort = "F120";
inline constexpr const char* kBitmapMissing = "F121";
inline constexpr const char* kNotBitmapName = "F122";
inline constexpr const char* kNotInToolLibrary = "F123";
inline constexpr const char* kBitmapIsFolder = "F124";
// A tool bitmap that is a loop of links, a device, a pipe or a socket.
inline constexpr const char* kBitmapNotAFile = "F138";  // {0} file, {1} tool, {2} name, {3} what (en), {4} what (th)
// A tool bitmap larger than a tool can be (500 mm each way at its resolution).
inline constexpr const char* kToolBitmapTooLarge =
    "F139";  // {0} file, {1} tool, {2} name, {3} w, {4} h, {5} limit, {6} px/mm
// Writing files (io/file_write.h), codes left free between the readers'.
inline constexpr const char* kFolderNotWritable = "F125";
inline constexpr const char* kOutputIsInput = "F126";
inline constexpr const char* kOutputIsFolder = "F127";
inline constexpr const char* kStockSizeTooLarge = "F128";  // {0} file {1} size as written {2} the largest
// A setup file with more problems than kMaxConfigDiagnostics: the rest is not read.
inline constexpr const char* kTooManyConfigProblems = "F129";  // {0} file, {1} the limit
inline constexpr const char* kOffsetTableShort = "F130";
inline constexpr const char* kOffsetEmpty = "F131";
inline constexpr const char* kOffsetFieldCount = "F132";
inline constexpr const char* kOffsetNotNumber = "F133";
inline constexpr const char* kNegativeNoseRadius = "F134";
inline constexpr const char* kBadTipNumber = "F135";
inline constexpr const char* kOffsetBeyondLathe = "F136";
inline constexpr const char* kNoMachineParameters = "F137";
inline constexpr const char* kNotKeyValue = "F140";
inline constexpr const char* kUnknownParameter = "F141";
inline constexpr const char* kParameterNotNumber = "F142";
inline constexpr const char* kParameterNotPositive = "F143";
inline constexpr const char* kParameterNegative = "F144";
inline constexpr const char* kParameterTwice = "F145";
inline constexpr const char* kTravelLimitsReversed = "F146";
inline constexpr const char* kParameterNotWhole = "F147";
inline constexpr const char* kParameterOutOfRange =
    "F148";  // {0} file, {1} key, {2} value, {3} min (en), {4} max, {5} min (th)
inline constexpr const char* kStartOutsideTravel = "F149";
// Machine files (gcode/machine_file.h, machine/machine_files.h; texts in messages_io.cpp).
inline constexpr const char* kMachineValueBad =
    "F200";  // {0} file, {1} key, {2} value, {3} what it must be (en), {4} (th)
inline constexpr const char* kMachineKeyMissing = "F201";      // {0} file, {1} key
inline constexpr const char* kMachineUnknownBase = "F202";     // {0} file, {1} base, {2} the machines
inline constexpr const char* kUnknownMachine = "F203";         // {0} name or file, {1} the machines
inline constexpr const char* kNotAMachineFile = "F204";        // {0} file
inline constexpr const char* kProgramMachineUnknown = "F205";  // {0} the machine the program names, {1} the machines
inline constexpr const char* kNotAnImage = "F150";
inline constexpr const char* kImageTruncated = "F151";
inline constexpr const char* kImageSizeRefused = "F152";
inline constexpr const char* kUnsupportedBmp = "F153";
inline constexpr const char* kBmpHeaderDamaged = "F154";
inline constexpr const char* kPngDamaged = "F155";
inline constexpr const char* kColourOutsidePalette = "F156";
// A path that is there but is no ordinary file (a pipe, a device, a socket): reading it can wait for ever.
inline constexpr const char* kNotAnOrdinaryFile = "F157";  // {0} file, {1} what (en), {2} what (th)
// A folder run (check DIR, class DIR) reads only what lies in the folder, and says what it will not quote (issue 42).
inline constexpr const char* kOutsideFolder = "F158";  // {0} file: a link that leaves the folder, never read
// A path the system cannot open as it is written (ENAMETOOLONG), rather than "no such file" (issue 42 item 6).
inline constexpr const char* kPathTooLong = "F176";  // {0} file, {1} its length in characters
inline constexpr const char* kNotAProgram = "F159";  // {0} file, {1} why (en), {2} why (th); its text is not shown
inline constexpr const char* kLibraryLineFields = "F160";
inline constexpr const char* kBadToolId = "F161";
inline constexpr const char* kDuplicateToolId = "F162";
inline constexpr const char* kBadToolKind = "F163";
inline constexpr const char* kBadPixelsPerMm = "F164";
inline constexpr const char* kLibraryNumberNegative = "F165";
inline constexpr const char* kLibraryBadTip = "F166";
inline constexpr const char* kLibraryNotBitmapName = "F167";
inline constexpr const char* kToolNeedsNames = "F168";
inline constexpr const char* kLibraryBitmapMissing = "F169";
inline constexpr const char* kNotVariableLine = "F170";
inline constexpr const char* kVariableNotKept = "F171";
inline constexpr const char* kLibraryBadOption = "F172";    // {0} file, {1} the word (library.cfg's 10th field)
inline constexpr const char* kMaterialLineFields = "F173";  // {0} file, {1} fields found (materials.cfg)
inline constexpr const char* kMaterialBadNumber = "F174";   // {0} file, {1} what, {2} the text
inline constexpr const char* kToolLineBadOption = "F175";   // {0} file, {1} station, {2} the option (tools.cfg)
// Part designs and the cutting-speed table (design; texts in messages_design.cpp)
inline constexpr const char* kPartFileNotJson = "F180";   // {0} file, {1} why (en), {2} why (th)
inline constexpr const char* kPartFieldMissing = "F181";  // {0} file, {1} field
inline constexpr const char* kPartFieldBad = "F182";      // {0} file, {1} field, {2} what it must be (en), {3} (th)
inline constexpr const char* kSpeedsLineBad = "F183";     // {0} file, {1} line text
// DXF drawings (design/dxf_import; texts in messages_design.cpp). Places are the drawing's own X Y.
inline constexpr const char* kDxfEmpty = "F184";              // {0} file
inline constexpr const char* kDxfNotDxf = "F185";             // {0} file, {1} why (English), {2} why (Thai)
inline constexpr const char* kDxfNothingOnLayer = "F186";     // {0} file, {1} layer, {2} layers with lines
inline constexpr const char* kDxfPickLayer = "F187";          // {0} file, {1} layers
inline constexpr const char* kDxfUnsupportedEntity = "F188";  // {0} file, {1} entity, {2} layer, {3} X, {4} Y
inline constexpr const char* kDxfOpenContour = "F189";        // {0} file, {1} X, {2} Y, {3} the gap (en), {4} (th)
inline constexpr const char* kDxfArcApart = "F190";         // {0} file, {1} R, {2} X, {3} Y, {4} the gap (en), {5} (th)
inline constexpr const char* kDxfUnits = "F191";            // {0} file, {1} $INSUNITS value
inline constexpr const char* kDxfSize = "F192";             // {0} file, {1} Ø, {2} length, {3} units (en), {4} (th)
inline constexpr const char* kDxfBranch = "F193";           // {0} file, {1} X, {2} Y, {3} how many
inline constexpr const char* kDxfTurnsBack = "F194";        // {0} file, {1} X, {2} Y
inline constexpr const char* kDxfSeveralOutlines = "F195";  // {0} file, {1} how many, {2} layer
inline constexpr const char* kDxfReachesAxis = "F196";      // {0} file, {1} X, {2} Y
inline constexpr const char* kDxfArcTooFlat = "F197";       // {0} file, {1} R, {2} X, {3} Y
inline constexpr const char* kDxfArcInBore = "F198";        // {0} file, {1} R, {2} X, {3} Y
inline constexpr const char* kDxfInches = "I180";
inline constexpr const char* kNotAsDrawn = "W530";  // {0} drawing feature, {1} Z from, {2} Z to, {3} what the cut part
                                                    // has             // {0} file, {1} factor, {2} unit name
inline constexpr const char* kPartUndercut = "E501";       // {0} step, {1} Ø, {2} Ø before it
inline constexpr const char* kPartEdgeTooLarge = "E502";   // {0} step, {1} size, {2} largest
inline constexpr const char* kPartLongerThanBar = "E503";  // {0} part length, {1} bar length less the grip
inline constexpr const char* kPartWiderThanBar = "E504";   // {0} step, {1} Ø, {2} bar Ø
inline constexpr const char* kUnknownMaterial = "E505";    // {0} material, {1} the table's materials
inline constexpr const char* kPartHasNoSteps = "E506";
inline constexpr const char* kGrooveNarrow = "E507";        // {0} groove, {1} width, {2} blade width
inline constexpr const char* kGrooveOffCylinder = "E508";   // {0} groove, {1} Z from, {2} Z to
inline constexpr const char* kGrooveTooDeep = "E509";       // {0} groove, {1} Ø, {2} the cylinder's Ø
inline constexpr const char* kThreadOffCylinder = "E510";   // {0} thread, {1} Z from, {2} Z to
inline constexpr const char* kThreadPitchBad = "E511";      // {0} thread, {1} pitch
inline constexpr const char* kBoreUndercut = "E512";        // {0} bore step, {1} Ø, {2} Ø before it
inline constexpr const char* kBoreEdgeTooLarge = "E513";    // {0} bore step, {1} size, {2} largest
inline constexpr const char* kBoreInSolidBar = "E514";      // {0} Ø of the smallest bore, {1} drill Ø, {2} least bore
inline constexpr const char* kBoreBelowHole = "E515";       // {0} bore step, {1} Ø, {2} the tube's hole
inline constexpr const char* kBoreDeeperThanPart = "E516";  // {0} bore depth, {1} part length
inline constexpr const char* kArcCannotJoin = "E517";       // {0} step, {1} R, {2} Ø from, {3} Ø to, {4} chord
inline constexpr const char* kArcNeedsUndercut = "E518";    // {0} step, {1} R, {2} Ø where it turns back
inline constexpr const char* kProgramTooLong = "E519";  // {0} blocks, {1} largest N, {2} dialect (English), {3} (Thai)
inline constexpr const char* kStockFromCommandLine = "I150";
inline constexpr const char* kStockFromJobDetails = "I151";
inline constexpr const char* kStockFromFirstApproach = "I152";
inline constexpr const char* kStockFromCycleStart = "I153";
inline constexpr const char* kStockFromComment = "I161";  // {0} size, {1} the comment that names the bar
inline constexpr const char* kBoreInferred = "I154";
inline constexpr const char* kStockDefault = "I155";
inline constexpr const char* kStockFromHeader = "I156";
inline constexpr const char* kStockLengthFromDeepestCut = "I157";
inline constexpr const char* kStockInferredFromBore = "I158";
inline constexpr const char* kStockFromLargestTurned = "I159";
// {0} new length, {1} the length from the deepest cut, {2} tool station, {3} how deep the tool reaches
inline constexpr const char* kStockLengthForTools = "I162";
inline constexpr const char* kToolFromComment = "I401";
inline constexpr const char* kToolForThreading = "I402";
inline constexpr const char* kToolForInsideThreading = "I403";
inline constexpr const char* kToolForGrooving = "I404";
inline constexpr const char* kToolForDrilling = "I405";
inline constexpr const char* kToolForBoring = "I406";
inline constexpr const char* kToolForParting = "I407";
inline constexpr const char* kToolForTurning = "I408";
inline constexpr const char* kToolSetForJob = "I409";
inline constexpr const char* kOffsetFromLibrary = "I410";
inline constexpr const char* kOffsetReplacedByLibrary = "I411";
// Which reading of lengths without a decimal point a job got (machine/point_reading.h;
// texts in messages_gcode.cpp beside W110/W111): {0} the deciding word, {1} its line, {2} its length.
inline constexpr const char* kLengthsInIncrements = "I103";
inline constexpr const char* kLengthsWhole = "I104";
// The units of a plain program without G20/G21, from its own sizes (infer/units_reading.h):
// {0} "inch" or "mm", {1} the first word that spoke them.
inline constexpr const char* kUnitsFromProgram = "I107";
inline constexpr const char* kToolsBeyondCentre =
    "I412";  // {0} line of the first cut at X < 0  // a row set for the table's tool, in a plain program
// A guessed tool that touched, replaced by another library tool of its kind that runs clean
// (cut/guess_fit.h): {0} station, {1} the replacement, {2} the first guess, {3} line of the touch.
inline constexpr const char* kGuessReplacedStock = "I413";
inline constexpr const char* kGuessReplacedChuck = "I414";
// A guessed blade set on its right (+Z) corner: on its left one it would cut into what the other
// tools turned beside its plunge. {0} station, {1} the blade's width (mm).
inline constexpr const char* kBladeOnItsRightCorner = "I415";
// The nose radius a tool's comment states, used for its offsets: {0} station, {1} radius (mm).
inline constexpr const char* kNoseRadiusFromComment = "I416";

// Run-time alarms and notes of the interpreter (machine; texts in messages_machine.cpp)
inline constexpr const char* kSpindleAboveMaximum = "A101";
inline constexpr const char* kNoFeed = "A102";
inline constexpr const char* kFeedPerRevWithoutSpeed = "A103";
inline constexpr const char* kFeedPerRevSpindleStopped = "A104";
inline constexpr const char* kSpindleReversedWithoutStop = "A105";
inline constexpr const char* kSpindleStartedWithBrakeOn = "A106";
inline constexpr const char* kBrakeWhileTurning = "A107";
inline constexpr const char* kThreadUnderConstantSurface = "A108";
inline constexpr const char* kCAxisOutsideCAxisMode = "A109";
inline constexpr const char* kCAxisModeWithoutBrake = "A110";
inline constexpr const char* kBrakeReleasedInCAxisMode = "A111";
inline constexpr const char* kBeyondTravelLimit = "A112";
inline constexpr const char* kArcEndsNotOnOneCircle = "A113";
inline constexpr const char* kArcRadiusTooSmall = "A114";
inline constexpr const char* kReferenceCheckFailed = "A115";
inline constexpr const char* kThreadSpindleStopped = "A116";
inline constexpr const char* kNotSupportedYet = "A117";
inline constexpr const char* kNoSuchOffset = "A118";
inline constexpr const char* kThreadWithoutSpeed = "A119";
inline constexpr const char* kNoProfileBlock = "A120";
inline constexpr const char* kProfileNotMonotonic = "A121";
inline constexpr const char* kCycleNeedsPositive = "A122";
inline constexpr const char* kCycleUnderNoseComp = "A123";
inline constexpr const char* kProfileFirstBlockAxis = "A124";
inline constexpr const char* kProfileHasNoMoves = "A125";
inline constexpr const char* kCycleNeedsPAndQ = "A126";
inline constexpr const char* kTooManyPasses = "A127";
inline constexpr const char* kNoSuchStation = "A128";
inline constexpr const char* kProgramAlarm = "A130";
inline constexpr const char* kDivisionByZero = "A131";
// A132 A133 A151: a limit on a long run stopped it (machine.cfg max_blocks, max_run_time);
// A155: the run came back to a state it was in before, the loop is proven endless.
inline constexpr const char* kBlockLimitReached = "A132";  // {0} last jump, {1} blocks run again, {2} max_blocks
inline constexpr const char* kTimeLimitReached = "A133";   // {0} last jump, {1} seconds, {2} max_run_time
inline constexpr const char* kCallsTooDeep = "A134";
inline constexpr const char* kNoSuchProgram = "A135";
inline constexpr const char* kNoSuchSequence = "A136";
inline constexpr const char* kNoSuchVariable = "A137";
inline constexpr const char* kOutsideFunctionDomain = "A138";
inline constexpr const char* kReadOnlyVariable = "A139";
inline constexpr const char* kVacantValueNeeded = "A140";
inline constexpr const char* kUnmatchedLoopEnd = "A141";
inline constexpr const char* kReturnTargetMissing = "A142";
inline constexpr const char* kValueIsNoCode = "A143";
inline constexpr const char* kCornerNeedsNextMove = "A144";
inline constexpr const char* kCornerLongerThanMove = "A145";
inline constexpr const char* kAngleUnreachable = "A146";
inline constexpr const char* kMacroStop = "A147";
inline constexpr const char* kProfileHasMacro = "A148";
inline constexpr const char* kTooManyCycleMoves = "A149";
inline constexpr const char* kProfileCommandNotAllowed = "A150";
inline constexpr const char* kMoveLimitReached = "A151";  // {0} last jump, {1} moves, {2} max_blocks, {3} allowed
inline constexpr const char* kNoCAxisOnThisMachine = "A152";
inline constexpr const char* kProfileStartsWithoutMotion = "A153";  // {0} cycle, {1} N number
// E305 for a station whose named bitmap cannot be used (a 20000 x 20000 picture, a pipe, a
// damaged file): the job says why instead of "has no bitmap" (issue 42 item 6).
inline constexpr const char* kToolBitmapUnusable = "E311";  // {0} T word, {1} tool, {2} why (en), {3} why (th)
inline constexpr const char* kCallWithoutProgram = "A154";  // {0} M98/G65/G66: no P (Fanuc alarm PS0076)
// {0} the backward jump (GOTO10, END1, M99), {1} the line it returns to
inline constexpr const char* kEndlessLoop = "A155";
// The run would keep more than RunOptions::memoryBudgetMb (issue 42 item 3): Klueng's own stop.
inline constexpr const char* kRunMemoryBudget = "A156";  // {0} the budget in MB, {1} the block's line
inline constexpr const char* kSubprogramFileHasErrors = "E412";
inline constexpr const char* kMainProgramRepeats = "I160";
inline constexpr const char* kVacantAddressOmitted = "W130";
inline constexpr const char* kThreadUnderCssWarning = "W131";    // Fanuc/Haas: threading under G96 runs
inline constexpr const char* kSpindleClampedToMaximum = "W132";  // {0} S, {1} maximum: Fanuc/Haas clamp (A101 in C)
inline constexpr const char* kSpindleReversed = "W133";          // {0} the M word: Fanuc/Haas reverse (A105 in C)
// {0} the cycle's word (G71): Fanuc/Haas run it under G41/G42 (A123 in C)
inline constexpr const char* kCycleRunsUncompensated = "W134";

// Nose radius compensation (comp; texts in messages_comp.cpp)
inline constexpr const char* kConcaveArcTooSmall = "A201";
inline constexpr const char* kNoseDoesNotFit = "A202";
inline constexpr const char* kCompStartOrCancelOnArc = "A203";
// A guessed nose radius (a plain program's tool: the shipped offsets or the library's insert) whose
// compensated path does not fit (A201/A202): the run uses the largest common radius that fits
// (issue 38 item 7). {0} station, {1} the guess (mm), {2} line of the interference, {3} the radius used,
// {4} the alarm the guess raised.
inline constexpr const char* kGuessedNoseTooBig = "W205";

// Material removal (cut; texts in messages_cut.cpp)
inline constexpr const char* kRapidIntoStock = "A301";
inline constexpr const char* kCutWithSpindleStopped = "A302";
inline constexpr const char* kHolderHitsStock = "A303";
inline constexpr const char* kToolHitsChuck = "A304";
inline constexpr const char* kBitmapHasNoEdge = "A310";
inline constexpr const char* kBitmapTooLarge = "A311";
// Part check (issue 10): args {0} depth mm, {1} {2} Z from-to, {3} Z and {4} Ø where deepest.
inline constexpr const char* kPartGouge = "W320";
inline constexpr const char* kPartLeftover = "W321";
inline constexpr const char* kBoreGouge = "W322";
inline constexpr const char* kBoreLeftover = "W323";
inline constexpr const char* kGuessHitsStock = "W324";  // {0} station, {1} tool, {2} Z, {3} X, {4} mm deep
inline constexpr const char* kGuessHitsChuck = "W325";
inline constexpr const char* kGuessEdgeBrushesStock = "W326";  // a guessed tool's edge, < 0.2 mm, in a rapid
inline constexpr const char* kPartCheckStopped = "I324";       // {0} the alarm's code
inline constexpr const char* kPartCheckNothingCut = "I325";
// Cutting data (issue 39, cut/cutting_data.h): warnings on the block, never errors.
inline constexpr const char* kCutSpeedHigh =
    "W330";  // {0} Vc, {1} unit, {2} tool material, {3} material, {4} max, {5} fix
inline constexpr const char* kCutSpeedLow =
    "W331";  // {0} Vc, {1} unit, {2} tool material, {3} material, {4} min, {5} fix
inline constexpr const char* kFinishTooRough =
    "W332";  // {0} f, {1} r, {2} Ra, {3} Rz, {4} limit Ra, {5} largest f, {6} unit, {7}/{8} why the limit
inline constexpr const char* kDepthOverEdge = "W333";      // {0} ap, {1} edge, {2} largest ap, {3} unit
inline constexpr const char* kPowerOverSpindle = "W334";   // {0} Pc kW, {1} machine kW, {2} ap, {3} f, {4} unit
inline constexpr const char* kTorqueOverSpindle = "W335";  // {0} torque, {1} machine torque, {2} diameter, {3} unit
inline constexpr const char* kRpmOverChuck = "W336";       // {0} rpm, {1} chuck's limit
inline constexpr const char* kMaterialUnknown = "I330";    // {0} the header's material, {1} the known ones
inline constexpr const char* kMaterialNotNamed = "I331";   // {0} the known ones

// The operator panel (issue 31; control; texts in messages_control.cpp).
inline constexpr const char* kNotReferenced = "A601";          // {0} the control's alarm, {1} axes not referenced
inline constexpr const char* kOvertravel = "A602";             // {0} the control's alarm, {1} axis, {2} limit (machine)
inline constexpr const char* kTouchedSpindleStopped = "W603";  // {0} station, {1} Z, {2} X Ø (bar frame)
inline constexpr const char* kMeasuredAfterStoppedTouch = "W604";  // {0} offset row
inline constexpr const char* kMeasureWithoutTool = "E605";         // {0} station
inline constexpr const char* kKeyNotInMode = "I606";               // {0} key, {1} the mode it needs
inline constexpr const char* kResetFirst = "A607";                 // {0} the alarm's code
inline constexpr const char* kNotMeasureInput = "E608";            // {0} the text typed
inline constexpr const char* kToolsNotTouchedOff = "A609";         // {0} stations ("T01 T03")
inline constexpr const char* kFeedOverrideZero = "I610";
inline constexpr const char* kOffsetsCompared = "I611";  // {0} worst row, {1} X error Ø, {2} Z error (mm)
// Class grading of the setup exercise (job/class_grading.h touchOffText): {0} station, {1} X Ø {2} Z entered,
// {3} X Ø {4} Z true (offset.cfg), {5} the tolerance (mm).
inline constexpr const char* kTouchOffWithin = "I612";
inline constexpr const char* kTouchOffOutside = "W613";
inline constexpr const char* kTouchOffNotSaved = "W614";  // {0} the file looked for, {1} why (empty: not there)

// klueng-cli's own texts (messages_cli.cpp): never diagnostics of a file, so
// the code is not printed; the catalog only gives them their two languages.
inline constexpr const char* kCliUsage = "C001";
inline constexpr const char* kCliCheckUsage = "C002";
inline constexpr const char* kCliSimulateUsage = "C003";
inline constexpr const char* kCliClassUsage = "C004";
inline constexpr const char* kCliPrintUsage = "C005";
inline constexpr const char* kCliGenerateUsage = "C006";
inline constexpr const char* kCliUnknownCommand = "C101";  // {0} command
inline constexpr const char* kCliUnknownOption = "C102";   // {0} option
inline constexpr const char* kCliNeedsValue = "C103";      // {0} option
inline constexpr const char* kCliBadValue = "C105";        // {0} value {1} option {2} allowed
inline constexpr const char* kCliBadValueAnyOf = "C106";   // {0} value {1} option
inline constexpr const char* kCliNoFile = "C107";
inline constexpr const char* kCliOneFile = "C108";         // {0} first {1} second
inline constexpr const char* kCliNotAFolder = "C112";      // {0} path
inline constexpr const char* kCliReferenceFails = "C113";  // {0} file {1} its first error or alarm
inline constexpr const char* kCliClassNeeds = "C114";
inline constexpr const char* kCliClassTotals = "C115";  // {0} programs {1} pass {2} fail
inline constexpr const char* kCliPrintNeeds = "C116";
inline constexpr const char* kCliGenerateNeeds = "C117";
inline constexpr const char* kCliToolForm = "C118";             // {0} value {1} library ids
inline constexpr const char* kCliToolStation = "C119";          // {0} value {1} station {2} last station
inline constexpr const char* kCliToolUnknown = "C120";          // {0} value {1} id {2} library ids
inline constexpr const char* kCliDrawingNoTolerances = "C121";  // {0} drawing
inline constexpr const char* kCliAllowedLang = "C201";
inline constexpr const char* kCliAllowedDialect = "C202";
inline constexpr const char* kCliAllowedStock = "C203";
inline constexpr const char* kCliAllowedUnits = "C204";
inline constexpr const char* kCliAllowedDecimalPoint = "C205";
inline constexpr const char* kCliAllowedSheet = "C206";
inline constexpr const char* kCliAllowedMillimetres = "C207";
inline constexpr const char* kCliAllowedShowUnits = "C208";
inline constexpr const char* kCliAllowedCompare = "C209";
inline constexpr const char* kCliAllowedGeneralTolerance = "C210";
inline constexpr const char* kCliAllowedToolMaterial = "C211";
inline constexpr const char* kCliAllowedTolerance = "C212";
// The picture module as the CLI opens it (png_writer.cpp): the reasons of F108.
inline constexpr const char* kCliNoOwnFolder = "C301";      // {0} the system's reason
inline constexpr const char* kCliModuleNotOpened = "C302";  // {0} dlerror()
inline constexpr const char* kCliModuleMissing = "C303";    // {0} the program's path
inline constexpr const char* kCliModuleNoEntry = "C304";    // {0} entry point
inline constexpr const char* kCliPictureNotDrawn = "C305";
// check --summary's table.
inline constexpr const char* kCliSummaryFile = "C311";
inline constexpr const char* kCliSummaryErrors = "C312";
inline constexpr const char* kCliSummaryWarnings = "C313";
inline constexpr const char* kCliSummaryResult = "C314";
inline constexpr const char* kCliSummaryUnreadable = "C315";
inline constexpr const char* kCliSummaryFail = "C316";
inline constexpr const char* kCliSummaryOk = "C317";

// The printed sheets' own words (render/; messages_render.cpp, SPEC 12 and GLOSSARY.md):
// never diagnostics, the catalog only gives them their two languages.
inline constexpr const char* kReportProgramTitle = "R001";
inline constexpr const char* kReportPage = "R002";  // {0} page number
inline constexpr const char* kReportProject = "R003";
inline constexpr const char* kReportMaterial = "R004";
inline constexpr const char* kReportPart = "R005";
inline constexpr const char* kReportDiameter = "R006";
inline constexpr const char* kReportProgrammer = "R007";
inline constexpr const char* kReportLength = "R008";
inline constexpr const char* kReportDrawingTitle = "R009";
inline constexpr const char* kReportDate = "R010";
inline constexpr const char* kReportFileName = "R011";
inline constexpr const char* kReportVersion = "R012";
inline constexpr const char* kReportScale = "R013";
inline constexpr const char* kReportUntitled = "R014";
inline constexpr const char* kReportCycleTime = "R015";
inline constexpr const char* kReportToAlarm = "R016";
inline constexpr const char* kReportDateLong = "R020";   // {0} day {1} month name {2} year (Thai: Buddhist era)
inline constexpr const char* kReportDateShort = "R021";  // {0} day {1} short month name {2} year
inline constexpr const char* kReportMinutes = "R022";    // {0} minutes {1} seconds
inline constexpr const char* kReportSeconds = "R023";    // {0} seconds
inline constexpr const char* kReportBadStock = "R030";
inline constexpr const char* kReportProgramErrors = "R031";
inline constexpr const char* kReportStoppedOnAlarm = "R032";
inline constexpr const char* kReportInside = "R040";       // {0} a feature's label
inline constexpr const char* kReportNoseCorners = "R041";  // {0} the nose radius
// The roughness the cuts leave on the drawing sheet (issue 39): a heading, a row per surface, the rest.
inline constexpr const char* kReportFinishTitle = "R042";
inline constexpr const char* kReportFinishRow = "R043";   // {0} surface {1} Ra {2} Rz {3} line {4} feed {5} nose R
inline constexpr const char* kReportFinishMore = "R044";  // {0} surfaces not listed
inline constexpr const char* kReportClassTitle = "R050";
inline constexpr const char* kReportAgainstReference = "R051";  // {0} reference {1} tolerance mm {2} date
inline constexpr const char* kReportAlsoDrawing = "R052";       // {0} drawing {1} dimensions
inline constexpr const char* kReportAgainstDrawing = "R053";    // {0} drawing {1} dimensions {2} date
inline constexpr const char* kReportColumnProgram = "R054";
inline constexpr const char* kReportColumnResult = "R055";
inline constexpr const char* kReportColumnErrors = "R056";
inline constexpr const char* kReportColumnAlarm = "R057";
inline constexpr const char* kReportColumnSeconds = "R058";
inline constexpr const char* kReportColumnLeftover = "R059";
inline constexpr const char* kReportColumnGouge = "R060";
inline constexpr const char* kReportColumnInTolerance = "R061";
inline constexpr const char* kReportPass = "R062";
inline constexpr const char* kReportFail = "R063";
inline constexpr const char* kReportInspectionTitle = "R064";  // {0} drawing
inline constexpr const char* kReportInspectionRule = "R065";
inline constexpr const char* kReportColumnDimension = "R066";
inline constexpr const char* kReportColumnTolerance = "R067";
inline constexpr const char* kReportColumnLimits = "R068";
inline constexpr const char* kReportColumnMeasured = "R069";
inline constexpr const char* kReportInCount = "R071";        // {0} in {1} of
inline constexpr const char* kReportColumnCutting = "R072";  // the class table's cutting-data warnings
// Why the picture module drew no PDF (its entry points write the code, the CLI says it).
inline constexpr const char* kReportNothingToWrite = "R080";
inline constexpr const char* kReportNoSheet = "R081";
inline constexpr const char* kReportPdfNotStarted = "R082";
inline constexpr const char* kReportPdfNotFinished = "R083";
inline constexpr const char* kReportPdfEmpty = "R084";

}  // namespace klueng::core::codes
