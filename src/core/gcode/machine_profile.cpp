// The machine profile table (SPEC 13): one row per dialect. Sources of the
// Fanuc and Haas values are in docs/dialects.md.
#include "klueng/core/gcode/machine_profile.h"

#include <array>

namespace klueng::core::gcode {

namespace {

constexpr std::array<int, 0> kNoOneShots{};
constexpr std::array<int, 3> kG28G30G53{28, 30, 53};

// Haas NGC lathe settings at their factory values (Haas lathe operator's
// manual, Settings: 22 Can Cycle Delta Z .050 in, 72 Canned Cycle Cut Depth
// .100 in, 73 Canned Cycle Retraction .050 in, 86 Thread Finish Allowance 0,
// 95 Thread Chamfer Size 1 thread, 99 Thread Minimum Cut .001 in); the mm
// values are the same lengths as the control shows them in metric.
constexpr CycleSettings kHaasCycles{
    .roughDepthInch = 0.1, .roughDepthMm = 2.54,
    .roughRetractInch = 0.05, .roughRetractMm = 1.27,
    .peckClearInch = 0.05, .peckClearMm = 1.27,
    .threadMinCutInch = 0.001, .threadMinCutMm = 0.0254,
    .threadFinishInch = 0.0, .threadFinishMm = 0.0,
    .threadChamferLeads = 1.0,
    .drillR = DrillR::Plane,
    .profileTailBeyondStart = true,
    .profileFirstBlockNeedsG00G01 = false,
};
// Fanuc 0i-TF: the two-block cycles carry their own values; only the G83
// clearance d (parameter 5115, set by the machine builder) is used: 1 mm / .04 in.
constexpr CycleSettings kFanucCycles{
    .roughDepthInch = 0.1, .roughDepthMm = 2.54,
    .roughRetractInch = 0.05, .roughRetractMm = 1.27,
    .peckClearInch = 0.04, .peckClearMm = 1.0,
    .threadMinCutInch = 0.001, .threadMinCutMm = 0.0254,
    .threadFinishInch = 0.0, .threadFinishMm = 0.0,
    .threadChamferLeads = 0.0,
    .drillR = DrillR::FromInitialLevel,
    .profileTailBeyondStart = false,
    .profileFirstBlockNeedsG00G01 = true,
};

constexpr MachineProfile kProfiles[] = {
    {
        .dialect = Dialect::Fanuc,
        .id = "fanuc",
        .nameEn = "Fanuc 0i-TF",
        .nameTh = "ฟานัค 0i-TF",
        .letters = "CFGHIKLMNOPQRSTUWXZ",
        .programNumberMax = 99999999,
        .colonProgramNumber = true,
        .sequenceNumberMax = 99999,
        .decimalsMm = 3,
        .decimalsInch = 4,
        .maxAbsMm = 9999.999,
        .maxAbsInch = 999.9999,
        .minPositiveMm = 0.001,
        .minPositiveInch = 0.0001,
        .extraDecimals = ExtraDecimals::RoundWithWarning,
        .powerOnUnits = InputUnits::Millimetre,
        .minToolDigits = 3,
        .maxToolStation = 0,
        .maxOffset = 64,
        .toolZeroKeepsTurret = true,
        .dwellP = DwellPUnit::Milliseconds,
        .bareG28 = BareG28::NoMotion,
        .threadUnderCssIsAlarm = false,
        .oneShotsWithMotion = kG28G30G53,
        .cycleForm = CycleForm::TwoBlock,
        .unknownMIsWarning = true,
        .highMIsWarning = true,
        .blanksInWords = true,
        .commentToLineEnd = true,
        .cycles = kFanucCycles,
        // Fanuc 0i-TF manual: subprograms nest 10 deep, macro calls 5; M98 P packs the repeats.
        .flow = {.macroB = true, .packedRepeats = true, .maxSubprogramNesting = 10, .maxMacroNesting = 5, .programsInOneFile = true,
                  .dwellBeforeCornerMove = false, .chamferWithIOrK = false},
    },
    {
        .dialect = Dialect::Haas,
        .id = "haas",
        .nameEn = "Haas ST (NGC)",
        .nameTh = "ฮาส ST (NGC)",
        .letters = "ACDEFGHIJKLMNOPQRSTUWXZ",
        .programNumberMax = 99999,
        .colonProgramNumber = false,
        .sequenceNumberMax = 99999,
        .decimalsMm = 3,
        .decimalsInch = 4,
        .maxAbsMm = 9999.999,
        .maxAbsInch = 999.9999,
        .minPositiveMm = 0.001,
        .minPositiveInch = 0.0001,
        .extraDecimals = ExtraDecimals::RoundWithWarning,
        .powerOnUnits = InputUnits::Inch,
        .minToolDigits = 3,
        .maxToolStation = 0,
        .maxOffset = 64,
        .toolZeroKeepsTurret = true,
        .dwellP = DwellPUnit::SecondsWithPointElseMs,
        .bareG28 = BareG28::HomeAllAxes,
        .threadUnderCssIsAlarm = false,
        .oneShotsWithMotion = kG28G30G53,
        .cycleForm = CycleForm::OneBlock,
        .unknownMIsWarning = false,
        .highMIsWarning = true,
        .blanksInWords = true,
        .commentToLineEnd = true,
        .cycles = kHaasCycles,
        // Haas lathe manual: 5-digit O numbers, so P is the program and L the repeats.
        .flow = {.macroB = true, .packedRepeats = false, .maxSubprogramNesting = 10, .maxMacroNesting = 5, .programsInOneFile = true,
                  .dwellBeforeCornerMove = true, .chamferWithIOrK = true},
    },
    {
        .dialect = Dialect::Classic,
        .id = "classic",
        .nameEn = "Rook classic (1999 rules)",
        .nameTh = "รุก คลาสสิก (กฎปี 2542)",
        .letters = "CFGHIKMNOPQRSTUWXZ",
        .programNumberMax = 9999,
        .colonProgramNumber = false,
        .sequenceNumberMax = 9999,
        .decimalsMm = 3,
        .decimalsInch = 4,
        .maxAbsMm = 9999.999,
        .maxAbsInch = 9999.999,  // the seed keeps the mm range after G20
        .minPositiveMm = 0.001,
        .minPositiveInch = 0.001,
        .extraDecimals = ExtraDecimals::Error,
        .powerOnUnits = InputUnits::Millimetre,
        .minToolDigits = 4,
        .maxToolStation = 8,
        .maxOffset = 16,
        .toolZeroKeepsTurret = false,
        .dwellP = DwellPUnit::Milliseconds,
        .bareG28 = BareG28::Error,
        .threadUnderCssIsAlarm = true,
        .oneShotsWithMotion = kNoOneShots,
        .cycleForm = CycleForm::TwoBlock,
        .unknownMIsWarning = false,
        .highMIsWarning = false,
        .blanksInWords = false,
        .commentToLineEnd = false,
        .cycles = kFanucCycles,
        // The 1999 rules: M98/M99 only, no macros.
        .flow = {.macroB = false, .packedRepeats = true, .maxSubprogramNesting = 10, .maxMacroNesting = 0, .programsInOneFile = false,
                  .dwellBeforeCornerMove = false, .chamferWithIOrK = false},
    },
};

}  // namespace

const MachineProfile& machineProfile(Dialect dialect) {
  for (const MachineProfile& p : kProfiles)
    if (p.dialect == dialect) return p;
  return kProfiles[0];
}

std::span<const MachineProfile> machineProfiles() { return kProfiles; }

bool parseDialectId(std::string_view id, Dialect& out) {
  for (const MachineProfile& p : kProfiles)
    if (p.id == id) {
      out = p.dialect;
      return true;
    }
  return false;
}

}  // namespace klueng::core::gcode
