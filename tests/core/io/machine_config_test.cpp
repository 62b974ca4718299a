// machine.cfg keys added for issue 8: spindle_bore and turret_stations.
#include <gtest/gtest.h>

#include "klueng/core/io/macro_variables.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/messages.h"

namespace klueng::core::io {
namespace {

TEST(MachineConfigKeys, DefaultsAndShippedFile) {
  const MachineConfig m;
  EXPECT_DOUBLE_EQ(m.spindleBore, 40.0);
  EXPECT_EQ(m.turretStations, 12);
  const auto shipped = readMachineConfig(std::string(KLUENG_SOURCE_DIR) + "/machine.cfg");
  ASSERT_TRUE(shipped.ok());
  EXPECT_DOUBLE_EQ(shipped.value->spindleBore, 40.0);
  EXPECT_EQ(shipped.value->turretStations, 12);
}

TEST(MachineConfigKeys, ReadAndWritten) {
  const auto r = parseMachineConfig("spindle_bore = 52\nturret_stations = 8\n", "m.cfg");
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(r.value->spindleBore, 52.0);
  EXPECT_EQ(r.value->turretStations, 8);
  const std::string text = formatMachineConfig(*r.value);
  EXPECT_NE(text.find("spindle_bore = 52\n"), std::string::npos);
  EXPECT_NE(text.find("turret_stations = 8\n"), std::string::npos);
  EXPECT_EQ(parseMachineConfig(text, "m.cfg").value->turretStations, 8);
  EXPECT_DOUBLE_EQ(parseMachineConfig("spindle_bore = 0\n", "m.cfg").value->spindleBore, 0.0);
}

TEST(MachineConfigKeys, AnEmptyFileSaysTheDefaultsApply) {
  for (const char* text : {"", "\n\n", "# only a comment\n   \n"}) {
    const auto r = parseMachineConfig(text, "m.cfg");
    ASSERT_TRUE(r.ok()) << text;  // the defaults are still a machine
    ASSERT_EQ(r.diagnostics.size(), 1u) << text;
    EXPECT_EQ(r.diagnostics[0].code, "F137");
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
              "m.cfg: sets no machine parameter: every parameter keeps its default (SPEC 1)");
    EXPECT_DOUBLE_EQ(r.value->rapidX, MachineConfig{}.rapidX);
  }
  EXPECT_TRUE(parseMachineConfig("rapid_x = 3000\n", "m.cfg").diagnostics.empty());
}

TEST(MachineConfigKeys, BadValues) {
  const auto neg = parseMachineConfig("spindle_bore = -1\n", "m.cfg");
  ASSERT_EQ(neg.diagnostics.size(), 1u);
  EXPECT_EQ(neg.diagnostics[0].code, "F144");
  for (const char* v : {"0", "25", "12.5", "-3"}) {
    const auto r = parseMachineConfig(std::string("turret_stations = ") + v + "\n", "m.cfg");
    ASSERT_EQ(r.diagnostics.size(), 1u) << v;
    EXPECT_EQ(r.diagnostics[0].code, "F147") << v;
    EXPECT_EQ(r.value->turretStations, 12) << v;
  }
  const auto r = parseMachineConfig("turret_stations = 25\n", "m.cfg");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            "m.cfg: turret_stations must be a whole number from 1 to 24, not 25");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::Th), "m.cfg: turret_stations ต้องเป็นจำนวนเต็มตั้งแต่ 1 ถึง 24 ไม่ใช่ 25");
}

}  // namespace
}  // namespace klueng::core::io

namespace klueng::core::io {
namespace {

// Issue 9: the endless-loop limits of program flow.
TEST(MachineConfigLoopLimits, ReadTheirKeysAndRefuseNonsense) {
  auto r = parseMachineConfig("max_blocks = 5000\nmax_run_time = 600\n", "machine.cfg");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value->maxBlocks, 5000);
  EXPECT_DOUBLE_EQ(r.value->maxRunTime, 600.0);
  r = parseMachineConfig("max_blocks = 0\nmax_run_time = -1\nmax_blocks = 2.5\n", "machine.cfg");
  ASSERT_EQ(r.diagnostics.size(), 3u);
  EXPECT_EQ(r.diagnostics[0].code, "F147");
  EXPECT_EQ(r.diagnostics[0].range.line, 1);
  EXPECT_EQ(r.diagnostics[1].code, "F143");
  EXPECT_EQ(r.diagnostics[2].code, "F147");
  EXPECT_EQ(r.value->maxBlocks, MachineConfig{}.maxBlocks);
  // The shipped machine.cfg writes the defaults back unchanged.
  const MachineConfig d;
  const auto again = parseMachineConfig(formatMachineConfig(d), "machine.cfg");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again.value->maxBlocks, 200000);
  EXPECT_DOUBLE_EQ(again.value->maxRunTime, 36000.0);
}

}  // namespace
}  // namespace klueng::core::io

namespace klueng::core::io {
namespace {

// Issue 13: values no lathe has are refused with file, line and column.
TEST(MachineConfigRanges, ImplausibleValuesAreRefused) {
  const auto r = parseMachineConfig("rapid_x = 1e-300\nmax_spindle_rpm = 1e308\nstart_z = 300\n", "machine.cfg");
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].code, "F148");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{1, 11, 6}));
  EXPECT_EQ(r.diagnostics[1].code, "F148");
  EXPECT_EQ(r.diagnostics[1].range.line, 2);
  EXPECT_DOUBLE_EQ(r.value->rapidX, MachineConfig{}.rapidX);
  EXPECT_DOUBLE_EQ(r.value->maxSpindleRpm, MachineConfig{}.maxSpindleRpm);
  EXPECT_EQ(formatMessage(r.diagnostics[1], Lang::En),
            "machine.cfg: max_spindle_rpm = 1e308 is outside what a lathe can have (1 to 100000); the default is used");
  const auto o = parseOffsetTable("0 0 0.8 3\n1e308 0 0.4 2\n0 0 1e300 3\n", "offset.cfg");
  int f136 = 0;
  for (const Diagnostic& d : o.diagnostics) f136 += d.code == "F136";
  EXPECT_EQ(f136, 2);
  EXPECT_DOUBLE_EQ(o.value->offsets[1].x, 0.0);
  EXPECT_DOUBLE_EQ(o.value->offsets[2].r, 0.0);
  // The tool may not start outside its travel.
  const auto s = parseMachineConfig("travel_z_min = -200\ntravel_z_max = 250\nstart_z = 300\n", "machine.cfg");
  ASSERT_EQ(s.diagnostics.size(), 1u);
  EXPECT_EQ(s.diagnostics[0].code, "F149");
  EXPECT_EQ(s.diagnostics[0].range.line, 3);
  EXPECT_EQ(formatMessage(s.diagnostics[0], Lang::En),
            "machine.cfg: the tool start start_z = 300 is outside the travel limits -200 to 250");
}

// Issue 42 item 6: accel_x = 1e-320 made every move last for ever (a cycle time of inf, and
// JSON that is not JSON); 0 still turns acceleration off, and the message names the range.
TEST(MachineConfigRanges, AccelerationIsZeroOrAtLeastOne) {
  const auto r = parseMachineConfig("accel_x = 1e-320\naccel_z = 0.5\n", "machine.cfg");
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].code, "F148");
  EXPECT_EQ(r.diagnostics[0].range.line, 1);
  EXPECT_EQ(r.diagnostics[1].range.line, 2);
  EXPECT_DOUBLE_EQ(r.value->accelX, MachineConfig{}.accelX);
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            "machine.cfg: accel_x = 1e-320 is outside what a lathe can have (0 (off) or 1 to 100000); the default is "
            "used");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::Th),
            "machine.cfg: accel_x = 1e-320 อยู่นอกช่วงที่เครื่องกลึงจะมีได้ (0 (ปิด) หรือ 1 ถึง 100000) จึงใช้ค่าเริ่มต้นแทน");
  const auto off = parseMachineConfig("accel_x = 0\naccel_z = 2500\n", "machine.cfg");
  EXPECT_TRUE(off.diagnostics.empty());
  EXPECT_DOUBLE_EQ(off.value->accelX, 0.0);
  EXPECT_DOUBLE_EQ(off.value->accelZ, 2500.0);
}

// Issue 29 item 10: a setup file's problems are capped as a program's are (E199):
// 100 of them, then F129 at the line where reading stopped.
TEST(ConfigProblemCap, AHostileMachineCfgReportsAHundredProblemsThenStops) {
  std::string text;
  for (int i = 0; i < 100000; ++i) text += "bogus_" + std::to_string(i) + " = 1\n";
  const auto r = parseMachineConfig(text, "machine.cfg");
  ASSERT_EQ(r.diagnostics.size(), 101u);
  EXPECT_EQ(r.diagnostics[99].code, "F141");
  EXPECT_EQ(r.diagnostics[99].range.line, 100);
  const Diagnostic& last = r.diagnostics.back();
  EXPECT_EQ(last.code, "F129");
  EXPECT_EQ(last.severity, Severity::Error);
  EXPECT_EQ(last.range.line, 101);
  EXPECT_EQ(formatMessage(last, Lang::En), "machine.cfg: more than 100 problems; the rest of the file is not read");
  EXPECT_EQ(formatMessage(last, Lang::Th), "machine.cfg: พบปัญหามากกว่า 100 รายการ จึงไม่อ่านส่วนที่เหลือของไฟล์");
  // A file with 100 problems is reported in full.
  text.clear();
  for (int i = 0; i < 100; ++i) text += "bogus_" + std::to_string(i) + " = 1\n";
  const auto hundred = parseMachineConfig(text, "machine.cfg");
  EXPECT_EQ(hundred.diagnostics.size(), 100u);
  EXPECT_EQ(hundred.diagnostics.back().code, "F141");
}

TEST(ConfigProblemCap, MacroVariablesAndTheToolLibraryStopToo) {
  std::string junk;
  for (int i = 0; i < 50000; ++i) junk += "junk " + std::to_string(i) + "\n";
  const auto vars = parseMacroVariables(junk, "macro_variables.cfg");
  ASSERT_EQ(vars.diagnostics.size(), 101u);
  EXPECT_EQ(vars.diagnostics.back().code, "F129");
  EXPECT_EQ(vars.diagnostics.back().severity, Severity::Warning);  // the lines are warnings: so is the cap
  EXPECT_EQ(vars.diagnostics.back().range.line, 101);
  const auto library = parseToolLibrary(junk, "/lib", "library.cfg");
  ASSERT_EQ(library.diagnostics.size(), 101u);
  EXPECT_EQ(library.diagnostics.back().code, "F129");
  EXPECT_EQ(library.diagnostics.back().severity, Severity::Error);
}

}  // namespace
}  // namespace klueng::core::io
