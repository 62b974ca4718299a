// The shared samples through the whole core pipeline (file -> parse -> check
// -> interpret) with the shipped tools.cfg / offset.cfg / machine.cfg.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

MachineSetup shippedSetup() {
  const std::string dir = KLUENG_SOURCE_DIR;
  MachineSetup s;
  auto tools = io::readToolTable(dir + "/tools.cfg");
  auto offsets = io::readOffsetTable(dir + "/offset.cfg");
  auto machine = io::readMachineConfig(dir + "/machine.cfg");
  EXPECT_TRUE(tools.ok() && offsets.ok() && machine.ok());
  if (tools.value) s.tools = *tools.value;
  if (offsets.value) s.offsets = *offsets.value;
  if (machine.value) s.machine = *machine.value;
  return s;
}

Timeline runSample(const char* name) {
  const auto file = io::readProgramFile(std::string(KLUENG_SAMPLES_DIR) + "/" + name);
  EXPECT_TRUE(file.ok()) << name;
  if (!file.value) return {};
  const gcode::Program program = gcode::parse(file.value->gcode, file.value->gcodeFirstLine);
  EXPECT_FALSE(hasErrors(gcode::check(program))) << name;
  return interpret(program, shippedSetup());
}

// Machining time by hand, with the shipped machine: rapids X 4000 mm/min
// (radius), Z 8000 mm/min, each axis on its own (the longer one decides).
double rapid(double x0, double z0, double x1, double z1) {
  return std::max(std::abs(x1 - x0) / 2.0 / 4000.0, std::abs(z1 - z0) / 8000.0) * 60.0;
}

TEST(Samples, StepShaftRunsWithoutAlarmAndItsCycleTimeMatchesAHandCalculation) {
  const Timeline t = runSample("01-step-shaft.txt");
  ASSERT_FALSE(t.alarm) << t.alarm->code << " line " << t.alarm->range.line;

  // G96 S180 m/min, G50 S2500: rpm(x) = C / x (x = radius), C = 1000*180/(2 pi)
  // = 28647.9 rpm*mm, clamped to 2500 below x_c = C / 2500 = 11.459 mm.
  // A G99 move at F mm/rev takes (60 / F) * integral ds / rpm(x(s)) seconds.
  const double c = 1000.0 * 180.0 / (2.0 * std::numbers::pi);
  const double xc = c / 2500.0;
  // Where x >= x_c all along a line: integral x ds / C = L * (x0 + x1) / 2 / C.
  auto cut = [&](double x0d, double z0, double x1d, double z1, double f) {
    const double x0 = x0d / 2.0, x1 = x1d / 2.0;
    EXPECT_GE(std::min(x0, x1), xc);
    const double len = std::hypot(x1 - x0, z1 - z0);
    return 60.0 / (f * c) * len * (x0 + x1) / 2.0;
  };

  double total = 0.0;
  total += rapid(0, 300, 54, 2);  // N50 dog-leg: Z decides, 298 / 8000 min = 2.235 s
  total += rapid(54, 2, 54, 0);   // N60
  // N70 facing X54 -> X-1.6 at F0.2: x from 27 down to x_c with rpm = C/x,
  // integral x dx / C = (27^2 - x_c^2) / (2C); then x_c down to -0.8 at 2500 rpm,
  // (x_c + 0.8) / 2500. Total 4.6006 s.
  const double facing = 60.0 / 0.2 * ((27.0 * 27.0 - xc * xc) / (2.0 * c) + (xc + 0.8) / 2500.0);
  EXPECT_NEAR(facing, 4.6006, 1e-4);
  total += facing;
  total += rapid(-1.6, 0, -1.6, 2);  // N80
  total += rapid(-1.6, 2, 47, 2);    // N90
  // Roughing at F0.25: {diameter, end Z, diameter after the step up}.
  const double passes[6][3] = {{47, -59.8, 50}, {44, -39.8, 47}, {41, -39.8, 44},
                               {37, -19.8, 41}, {33, -19.8, 37}, {31, -19.8, 33}};
  for (int i = 0; i < 6; ++i) {
    const double x = passes[i][0], z = passes[i][1], up = passes[i][2];
    if (i > 0) total += rapid(passes[i - 1][2], 2, x, 2);  // G00 X down to the next pass
    total += cut(x, 2, x, z, 0.25) + cut(x, z, up, z, 0.25);
    if (i < 5) total += rapid(up, z, up, 2);  // G00 Z2.
  }
  total += rapid(33, -19.8, 100, 100);  // N320
  // Finishing under G42 with offset 01 (R0.8, tip 3), F0.1. The imaginary tip
  // stays on the programmed diameters and faces; on 45-degree chamfers the
  // corners move by k = 0.8 * (2 - sqrt 2) = 0.4686 mm, the R2 corner becomes a
  // quarter circle of radius 2.8 around Z-22.8 X34.4.
  const double k = 0.8 * (2.0 - std::sqrt(2.0));
  total += rapid(100, 100, 24, 2 - 0.8);  // start-up: the nose stops R before Z0's start
  total += cut(24, 1.2, 24, -k, 0.1);
  total += cut(24, -k, 30, -3 - k, 0.1);
  total += cut(30, -3 - k, 30, -20, 0.1);
  total += cut(30, -20, 34.4, -20, 0.1);
  // Arc: x = 17.2 + 2.8 sin(phi), ds = 2.8 dphi, phi 0..pi/2:
  // integral x ds = 2.8 * (17.2 * pi/2 + 2.8).
  total += 60.0 / (0.1 * c) * 2.8 * (17.2 * std::numbers::pi / 2.0 + 2.8);
  total += cut(40, -22.8, 40, -40, 0.1);
  total += cut(40, -40, 44 - 2 * k, -40, 0.1);
  total += cut(44 - 2 * k, -40, 46, -41 - k, 0.1);
  total += cut(46, -41 - k, 46, -60, 0.1);
  total += cut(46, -60, 50.4, -60, 0.1);
  total += rapid(50.4, -60, 100, 100);  // cancel move N440
  EXPECT_NEAR(t.cycleTime(), total, 1e-6);
  EXPECT_NEAR(t.cycleTime(), 77.7980, 1e-4);

  // The finishing pass's points, as derived above.
  std::vector<Move> finish;
  for (const Move& m : t.moves)
    if (m.compensated && m.kind != MoveKind::Rapid) finish.push_back(m);
  ASSERT_EQ(finish.size(), 10u);
  EXPECT_POINT(finish[0].path.start, 24.0, 1.2);
  EXPECT_POINT(finish[1].path.start, 24.0, -k);
  EXPECT_POINT(finish[2].path.start, 30.0, -3 - k);
  EXPECT_EQ(finish[4].kind, MoveKind::Arc);
  EXPECT_POINT(finish[4].path.centre, 34.4, -22.8);
  EXPECT_POINT(finish[7].path.start, 44 - 2 * k, -40.0);
  EXPECT_POINT(finish[9].path.end, 50.4, -60.0);
  EXPECT_POINT(t.moves.back().path.end, 100.0, 100.0);
  EXPECT_TRUE(t.snapshots.back().stopped);  // M30
}

TEST(Samples, ThreadRunsWithoutAlarmAndThreadsAtLeadTimesRpm) {
  const Timeline t = runSample("02-thread.txt");
  ASSERT_FALSE(t.alarm) << t.alarm->code << " line " << t.alarm->range.line;
  int threads = 0;
  for (const Move& m : t.moves) {
    if (m.kind != MoveKind::Thread) continue;
    ++threads;
    EXPECT_DOUBLE_EQ(m.rpm, 800.0);
    EXPECT_DOUBLE_EQ(m.feed, 1.5 * 800.0);
    EXPECT_NEAR(m.tEnd - m.tStart, 35.0 / 1200.0 * 60.0, 1e-9);  // Z5 -> Z-30
    EXPECT_NEAR(m.path.end.x(), m.path.start.x() - 35.0, 1e-9);
  }
  EXPECT_EQ(threads, 4);
}

TEST(Samples, RuntimeAlarmsStopsOnN40) {
  const Timeline t = runSample("05-runtime-alarms.txt");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "A104");
  EXPECT_EQ(t.alarm->range.line, 12);   // N40
  EXPECT_EQ(t.alarm->range.column, 5);  // its G01
}

}  // namespace
}  // namespace klueng::core::machine
