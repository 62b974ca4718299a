// Machine files (issue 27): the shipped files, a bad file's located errors, and
// G-code systems B and C as renamed rows of the same code table.
#include <gtest/gtest.h>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/machine_file.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

TEST(MachineFile, ShippedFilesReadCleanInMenuOrder) {
  const auto files = shippedMachineFiles();
  ASSERT_GE(files.size(), 4u);
  EXPECT_EQ(files[0].name, "fanuc.machine");
  EXPECT_EQ(files[1].name, "haas.machine");
  EXPECT_EQ(files[2].name, "classic.machine");
  for (const ShippedMachineFile& f : files) {
    const MachineFileRead read = parseMachineFile(f.text, std::string(f.name));
    EXPECT_TRUE(read.diagnostics.empty())
        << f.name << ": " << (read.diagnostics.empty() ? "" : read.diagnostics[0].code);
    ASSERT_TRUE(read.machine.has_value()) << f.name;
    EXPECT_TRUE(read.machine->otherKeys.empty()) << f.name << " holds a machine.cfg key";
  }
  EXPECT_EQ(machineProfile(Dialect::Fanuc).id, "fanuc");
  EXPECT_EQ(machineProfile(Dialect::Haas).id, "haas");
  EXPECT_EQ(machineProfile(Dialect::Classic).id, "classic");
}

// The values the C++ rows held before the move (issue 27 item 1).
TEST(MachineFile, ShippedProfilesHoldTheFormerRows) {
  const MachineProfile& f = machineProfile(Dialect::Fanuc);
  EXPECT_EQ(f.family, Dialect::Fanuc);
  EXPECT_EQ(f.system, GcodeSystem::A);
  EXPECT_EQ(f.nameEn, "Fanuc 0i-TF");
  EXPECT_EQ(f.letters, "CFGHIKLMNOPQRSTUWXZ");
  EXPECT_EQ(f.programNumberMax, 99999999);
  EXPECT_TRUE(f.colonProgramNumber);
  EXPECT_DOUBLE_EQ(f.maxAbsInch, 999.9999);
  EXPECT_EQ(f.bareG28, BareG28::NoMotion);
  EXPECT_EQ(std::vector<int>(f.oneShotsWithMotion.begin(), f.oneShotsWithMotion.end()), (std::vector<int>{28, 30, 53}));
  EXPECT_DOUBLE_EQ(f.cycles.peckClearMm, 1.0);
  EXPECT_EQ(f.flow.maxMacroNesting, 5);
  const MachineProfile& h = machineProfile(Dialect::Haas);
  EXPECT_EQ(h.powerOnUnits, InputUnits::Inch);
  EXPECT_EQ(h.dwellP, DwellPUnit::SecondsWithPointElseMs);
  EXPECT_EQ(h.cycleForm, CycleForm::OneBlock);
  EXPECT_DOUBLE_EQ(h.cycles.threadChamferLeads, 1.0);
  EXPECT_TRUE(h.flow.chamferWithIOrK);
  EXPECT_FALSE(h.unknownMIsWarning);
  const MachineProfile& c = machineProfile(Dialect::Classic);
  EXPECT_EQ(c.maxToolStation, 8);
  EXPECT_EQ(c.maxOffset, 16);
  EXPECT_TRUE(c.oneShotsWithMotion.empty());
  EXPECT_FALSE(c.flow.macroB);
  EXPECT_EQ(c.extraDecimals, ExtraDecimals::Error);
  // Every M row of each family is in its list: the lists change nothing.
  for (Dialect d : {Dialect::Fanuc, Dialect::Haas, Dialect::Classic})
    for (const CodeInfo& row : codeTable())
      if (row.letter == 'M' && row.in(d)) {
        EXPECT_NE(findCode('M', row.number, d), nullptr) << "M" << row.number;
      }
}

TEST(MachineFile, BadValueIsLocatedInBothLanguages) {
  const std::string text =
      "base = fanuc\n"
      "id = teacher\n"
      "# a comment\n"
      "gcode_system =  D\n"
      "family = fanuk   # a typo\n";
  const MachineFileRead read = parseMachineFile(text, "teacher.machine");
  EXPECT_FALSE(read.machine.has_value());
  ASSERT_EQ(read.diagnostics.size(), 2u);
  const Diagnostic& d = read.diagnostics[0];
  EXPECT_EQ(d.code, core::codes::kMachineValueBad);
  EXPECT_EQ(d.range.line, 4);
  EXPECT_EQ(d.range.column, 17);
  EXPECT_EQ(formatMessage(d, Lang::En), "teacher.machine: gcode_system = 'D': must be one of: A B C");
  EXPECT_EQ(formatMessage(d, Lang::Th), "teacher.machine: gcode_system = 'D': ต้องเป็นค่าใดค่าหนึ่งต่อไปนี้: A B C");
  EXPECT_EQ(read.diagnostics[1].range.line, 5);
  EXPECT_EQ(read.diagnostics[1].range.column, 10);
  EXPECT_EQ(read.diagnostics[1].range.length, 5);
}

TEST(MachineFile, MissingKeysWithoutBaseAndUnknownBase) {
  const MachineFileRead bare = parseMachineFile("id = x\nname_en = X\n", "x.machine");
  EXPECT_FALSE(bare.machine.has_value());
  ASSERT_FALSE(bare.diagnostics.empty());
  EXPECT_EQ(bare.diagnostics[0].code, core::codes::kMachineKeyMissing);
  EXPECT_EQ(bare.diagnostics[0].args[1], "name_th");

  const MachineFileRead base = parseMachineFile("id = x\nbase = fanucc\n", "x.machine");
  ASSERT_EQ(base.diagnostics.size(), 1u);
  EXPECT_EQ(base.diagnostics[0].code, core::codes::kMachineUnknownBase);
  EXPECT_EQ(base.diagnostics[0].range.line, 2);
  EXPECT_EQ(formatMessage(base.diagnostics[0], Lang::En).substr(0, 50),
            "x.machine: base 'fanucc' is no machine; the machin");

  const MachineFileRead noEquals = parseMachineFile("base = fanuc\nid = x\nrapid_x 4000\n", "x.machine");
  ASSERT_EQ(noEquals.diagnostics.size(), 1u);
  EXPECT_EQ(noEquals.diagnostics[0].code, core::codes::kNotKeyValue);
  EXPECT_EQ(noEquals.diagnostics[0].range.line, 3);
}

TEST(MachineFile, BaseAndOtherKeysAreKept) {
  const MachineFileRead read = parseMachineFile(
      "base = haas\nid = shop\npower_on_units = mm\nrapid_x = 6000\nm_codes = 3 4 5\n", "shop.machine");
  ASSERT_TRUE(read.machine.has_value());
  EXPECT_EQ(read.machine->profile.powerOnUnits, InputUnits::Millimetre);
  EXPECT_EQ(read.machine->profile.cycleForm, CycleForm::OneBlock);  // from haas
  ASSERT_EQ(read.machine->otherKeys.size(), 1u);
  EXPECT_EQ(read.machine->otherKeys[0].key, "rapid_x");
  EXPECT_EQ(read.machine->otherKeys[0].line, 4);
  const Dialect d = registerMachine(*read.machine);
  EXPECT_GE(static_cast<int>(d), 3);
  EXPECT_EQ(machineProfile(d).id, "shop");
  EXPECT_NE(findCode('M', 3, d), nullptr);
  EXPECT_EQ(findCode('M', 8, d), nullptr);  // not in its list
  Dialect again{};
  ASSERT_TRUE(parseDialectId("shop", again));
  EXPECT_EQ(again, d);
}

TEST(GcodeSystems, SystemBRenamesRowsOntoTheSameActions) {
  Dialect b{};
  ASSERT_TRUE(parseDialectId("romi-gl240m", b));
  EXPECT_EQ(machineProfile(b).system, GcodeSystem::B);
  EXPECT_EQ(machineProfile(b).family, Dialect::Fanuc);
  const auto action = [&](int g) {
    const CodeInfo* r = findCode('G', g, b);
    return r ? r->action : CodeAction::None;
  };
  EXPECT_EQ(action(33), CodeAction::Thread);
  EXPECT_EQ(action(92), CodeAction::CoordinateSet);
  EXPECT_EQ(action(77), CodeAction::BoxTurning);
  EXPECT_EQ(action(78), CodeAction::BoxThreading);
  EXPECT_EQ(action(79), CodeAction::BoxFacing);
  EXPECT_EQ(action(94), CodeAction::FeedPerMinute);
  EXPECT_EQ(action(95), CodeAction::FeedPerRev);
  EXPECT_EQ(action(90), CodeAction::Absolute);
  EXPECT_EQ(action(91), CodeAction::Incremental);
  EXPECT_EQ(action(71), CodeAction::TurnRoughing);
  EXPECT_EQ(findCode('G', 32, b), nullptr);
  EXPECT_EQ(findCode('G', 50, b), nullptr);
  // G98/G99 are the drilling cycles' return level in system B (issue 27), no longer the feed modes.
  EXPECT_EQ(action(98), CodeAction::ReturnToInitialLevel);
  EXPECT_EQ(action(99), CodeAction::ReturnToRPoint);
  EXPECT_EQ(findCode('G', 98, b)->group, ModalGroup::ReturnLevel);
  EXPECT_EQ(numberInA('G', 33, b), 32);
  EXPECT_EQ(numberInA('G', 98, b), -1);
  EXPECT_EQ(inSystemNumbers("G50 S2500 (G32 passes) G99 G90 X46. G32.5", b),
            "G92 S2500 (G33 passes) G95 G77 X46. G32.5");
  EXPECT_EQ(findCode('G', 33, b)->number, 33);  // messages say the number as written
  EXPECT_EQ(findCode('G', 90, b)->group, ModalGroup::Distance);
  EXPECT_EQ(numberInSystem('G', 32, b), 33);
  EXPECT_EQ(numberInSystem('G', 90, b), 77);
  EXPECT_EQ(numberInSystem('G', 1, b), 1);
  // System A is untouched.
  EXPECT_EQ(findCode('G', 90, Dialect::Fanuc)->action, CodeAction::BoxTurning);
  EXPECT_EQ(findCode('G', 33, Dialect::Fanuc), nullptr);
}

TEST(GcodeSystems, SystemCMovesTheCyclesUpByTwo) {
  const MachineFileRead read = parseMachineFile("base = fanuc\nid = system-c\ngcode_system = C\n", "c.machine");
  ASSERT_TRUE(read.machine.has_value());
  const Dialect c = registerMachine(*read.machine);
  const auto action = [&](int g) {
    const CodeInfo* r = findCode('G', g, c);
    return r ? r->action : CodeAction::None;
  };
  EXPECT_EQ(action(70), CodeAction::Inch);
  EXPECT_EQ(action(71), CodeAction::Metric);
  EXPECT_EQ(action(72), CodeAction::Finishing);
  EXPECT_EQ(action(73), CodeAction::TurnRoughing);
  EXPECT_EQ(action(76), CodeAction::FacePecking);
  EXPECT_EQ(action(77), CodeAction::Grooving);
  EXPECT_EQ(action(78), CodeAction::ThreadCutting);
  EXPECT_EQ(action(20), CodeAction::BoxTurning);
  EXPECT_EQ(action(21), CodeAction::BoxThreading);
  EXPECT_EQ(action(24), CodeAction::BoxFacing);
  EXPECT_EQ(action(90), CodeAction::Absolute);
  EXPECT_EQ(findCode('G', 79, c), nullptr);
  EXPECT_EQ(numberInSystem('G', 76, c), 78);
}

TEST(GcodeSystems, TheCheckerReadsUnitsByTheCodesAction) {
  // System C: G70 is inch input (4 decimals), G71 metric (3); G20 is a single cycle there.
  const MachineFileRead read = parseMachineFile("base = fanuc\nid = system-c-units\ngcode_system = C\n", "c.machine");
  ASSERT_TRUE(read.machine.has_value());
  const Dialect c = registerMachine(*read.machine);
  CheckOptions options;
  options.dialect = c;
  EXPECT_TRUE(check(parse("G70\nG00 X1.2345 Z0.1"), options).empty());
  const std::vector<Diagnostic> metric = check(parse("G71\nG00 X1.2345 Z0.1"), options);
  ASSERT_EQ(metric.size(), 1u);
  EXPECT_EQ(metric[0].range.line, 2);
  EXPECT_EQ(metric[0].range.column, 5);
  EXPECT_EQ(metric[0].args[0], "X1.2345");
}

}  // namespace
}  // namespace klueng::core::gcode
