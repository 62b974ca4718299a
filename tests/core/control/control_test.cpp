// The operator panel's machine (issue 31): power-on, zero return, jog limits,
// collisions, handwheel touch-off, MDI, overrides.
#include "klueng/core/control/control.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "klueng/core/cut/part_check.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/kinematics.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

namespace klueng::core::control {
namespace {

namespace kc = core::codes;

const machine::MachineSetup& shippedSetup() {
  static const machine::LoadedSetup loaded = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  return loaded.setup;
}

io::JobHeader bar50x100() {
  io::JobHeader h;
  h.diameter = 50.0;
  h.length = 100.0;
  return h;
}

// Power-on and both zero returns, the turret at the reference point, T01, JOG.
void referenceBoth(Control& c) {
  c.setMode(Mode::ZeroReturn);
  ASSERT_FALSE(c.zeroReturn(Axis::X).stop);
  ASSERT_FALSE(c.zeroReturn(Axis::Z).stop);
  c.setMode(Mode::Jog);
}

// Rapid the tip of the tool at the turret to (X Ø, Z) in the bar's frame, Z first when moving away.
void rapidTipTo(Control& c, double x, double z) {
  c.setMode(Mode::Jog);
  ASSERT_FALSE(c.jog(Axis::Z, z - c.tip().z, true).stop);
  ASSERT_FALSE(c.jog(Axis::X, x - c.tip().x, true).stop);
}

// Touch the face with the handwheel at ×1 from Z+0.1 until the first chip; returns the clicks.
int touchFace(Control& c) {
  rapidTipTo(c, 40.0, 0.1);
  c.setMode(Mode::Handle);
  c.setHandleAxis(Axis::Z);
  c.setHandleStep(1);
  for (int click = 1; click <= 200; ++click) {
    const MotionResult r = c.handle(-1);
    EXPECT_FALSE(r.stop) << formatMessage(*r.stop, Lang::En);
    if (r.cut) return click;
  }
  return -1;
}

// Skim Ø49 over 10 mm from the face, back off in Z only; returns the micrometer reading.
double skimDiameter(Control& c, double diameter) {
  rapidTipTo(c, 52.0, 2.0);
  c.setMode(Mode::Jog);
  EXPECT_FALSE(c.jog(Axis::X, diameter - c.tip().x, false).stop);
  EXPECT_TRUE(c.jog(Axis::Z, -12.0, false).cut);
  EXPECT_FALSE(c.jog(Axis::Z, 14.0, false).stop);
  c.setSpindle(machine::SpindleDir::Stopped);
  return c.micrometer(-5.0);
}

TEST(Control, CycleStartIsRefusedUntilBothAxesReturnedToTheReference) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  auto refusal = c.cycleStartRefusal();
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->code, kc::kNotReferenced);
  EXPECT_EQ(refusal->severity, Severity::Alarm);
  EXPECT_EQ(refusal->args, (std::vector<std::string>{"PS0224 ZERO RETURN NOT FINISHED", "X Z"}));
  c.setMode(Mode::Mdi);
  const auto mdi = c.runMdi("G00 X60 Z5");
  ASSERT_EQ(mdi.size(), 1u);
  EXPECT_EQ(mdi[0].code, kc::kNotReferenced);
  EXPECT_TRUE(c.moves().moves.empty());

  // The axis keys only return in ZERO RETURN mode.
  c.setMode(Mode::Jog);
  const MotionResult wrongMode = c.zeroReturn(Axis::X);
  ASSERT_TRUE(wrongMode.stop);
  EXPECT_EQ(wrongMode.stop->code, kc::kKeyNotInMode);
  EXPECT_EQ(wrongMode.stop->args[1], "ZERO RETURN");

  c.setMode(Mode::ZeroReturn);
  EXPECT_TRUE(c.zeroReturn(Axis::X).moved);
  EXPECT_TRUE(c.referenced(Axis::X));
  EXPECT_EQ(c.machinePosition().x, 0.0);
  EXPECT_EQ(c.cycleStartRefusal()->args[1], "Z");
  c.zeroReturn(Axis::Z);
  EXPECT_EQ(c.machinePosition(), (AxisValues{0.0, 0.0}));
  EXPECT_FALSE(c.cycleStartRefusal());
  EXPECT_EQ(c.moves().moves.back().kind, machine::MoveKind::Rapid);

  Control haas(shippedSetup(), bar50x100(), gcode::Dialect::Haas);
  EXPECT_EQ(haas.layout(), Layout::Haas);
  EXPECT_EQ(haas.cycleStartRefusal()->args[0], "ZERO RETURN REQUIRED");
  // A Haas jogs an axis only after its zero return (the handle too); nothing moves, no RESET needed.
  const AxisValues before = haas.machinePosition();
  const MotionResult notHomed = haas.jog(Axis::Z, -5.0, false);
  ASSERT_TRUE(notHomed.stop);
  EXPECT_EQ(notHomed.stop->code, kc::kNotReferenced);
  EXPECT_EQ(notHomed.stop->args, (std::vector<std::string>{"ZERO RETURN REQUIRED", "Z"}));
  haas.setMode(Mode::Handle);
  haas.setHandleAxis(Axis::X);
  EXPECT_EQ(haas.handle(10).stop->args[1], "X");
  EXPECT_EQ(haas.machinePosition(), before);
  EXPECT_FALSE(haas.alarm());
  haas.setMode(Mode::ZeroReturn);
  haas.zeroReturn(Axis::Z);
  haas.setMode(Mode::Jog);
  EXPECT_TRUE(haas.jog(Axis::Z, -5.0, false).moved);
  EXPECT_EQ(haas.jog(Axis::X, -5.0, false).stop->args[1], "X");
}

TEST(Control, JogStopsAtTheSoftLimitsWithTheControlsOvertravelAlarm) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  // Before the zero return the soft limits do not hold (the control does not know where it is).
  const double x0 = c.machinePosition().x;
  EXPECT_FALSE(c.jog(Axis::X, 5.0, true).stop);
  EXPECT_DOUBLE_EQ(c.machinePosition().x, x0 + 5.0);
  referenceBoth(c);

  MotionResult up = c.jog(Axis::X, 5.0, true);
  ASSERT_TRUE(up.stop);
  EXPECT_EQ(up.stop->code, kc::kOvertravel);
  EXPECT_EQ(up.stop->args, (std::vector<std::string>{"OT0500 + OVERTRAVEL (SOFT 1)", "X", "0.000"}));
  EXPECT_EQ(c.machinePosition().x, 0.0);
  // Nothing moves until RESET.
  EXPECT_EQ(c.jog(Axis::Z, -1.0, true).stop->code, kc::kResetFirst);
  c.reset();

  // machine.cfg travel_z_min -1000 with the reference at Z300: the limit is machine Z-1300.
  const MotionResult far = c.jog(Axis::Z, -2000.0, true);
  ASSERT_TRUE(far.stop);
  EXPECT_EQ(far.stop->args, (std::vector<std::string>{"OT0501 - OVERTRAVEL (SOFT 1)", "Z", "-1300.000"}));
  EXPECT_EQ(c.machinePosition().z, -1300.0);
  EXPECT_EQ(c.travelMin().z, -1300.0);
}

TEST(Control, JoggingIntoTheBarOrTheChuckIsTheRunsCrashUntilReset) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  referenceBoth(c);
  c.setSpindle(machine::SpindleDir::Cw);
  rapidTipTo(c, 40.0, 5.0);
  // A rapid into the face: the cut's A301, the turret stopped at the face.
  const MotionResult crash = c.jog(Axis::Z, -10.0, true);
  ASSERT_TRUE(crash.stop);
  EXPECT_EQ(crash.stop->code, kc::kRapidIntoStock);
  EXPECT_NEAR(c.tip().z, 0.0, 0.01);
  EXPECT_GT(c.tip().z, 0.0);
  EXPECT_EQ(c.cycleStartRefusal()->code, kc::kResetFirst);
  c.reset();
  EXPECT_FALSE(c.cycleStartRefusal());

  // Over the bar at Ø60 towards the jaws (they hold 15 mm of the 100 mm bar): A304 at Z-85.
  rapidTipTo(c, 60.0, 5.0);
  const MotionResult jaws = c.jog(Axis::Z, -120.0, false);
  ASSERT_TRUE(jaws.stop);
  EXPECT_EQ(jaws.stop->code, kc::kToolHitsChuck);
  EXPECT_FALSE(jaws.cut);
  EXPECT_GT(c.tip().z, -85.0);
  EXPECT_LT(c.tip().z, -84.0);
  c.reset();
  EXPECT_FALSE(c.jog(Axis::Z, 10.0, false).stop);
}

TEST(Control, AHandwheelTouchOffGivesTheToolsGeometryToOneClick) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  c.forgetGeometry();
  referenceBoth(c);
  c.setSpindleSpeed(800.0);
  c.setSpindle(machine::SpindleDir::Cw);
  const int clicks = touchFace(c);
  // From Z+0.100 the 101st click of 0.001 mm is the first into the face.
  EXPECT_EQ(clicks, 101);
  EXPECT_NEAR(c.tip().z, -0.001, 1e-9);
  EXPECT_FALSE(c.measure(1, Axis::Z, 0.0));
  EXPECT_DOUBLE_EQ(c.row(1).geometry.z, c.machinePosition().z);
  EXPECT_NEAR(c.row(1).geometry.z - c.trueGeometry(1).z, -0.001, 1e-9);

  c.setSpindle(machine::SpindleDir::Cw);
  const double measured = skimDiameter(c, 49.0);
  EXPECT_DOUBLE_EQ(measured, 49.0);
  EXPECT_FALSE(c.measure(1, Axis::X, measured));
  EXPECT_NEAR(c.row(1).geometry.x, c.trueGeometry(1).x, 1e-9);
  // The offset row the run applies: 0 in X, the click's depth in Z.
  const io::Offset run = c.runSetup().offsets.at(1);
  EXPECT_NEAR(run.x, 0.0, 1e-9);
  EXPECT_NEAR(run.z, -0.001, 1e-9);
  EXPECT_EQ(run.r, shippedSetup().offsets.at(1).r);
  EXPECT_FALSE(c.cycleStartRefusal({1}));
  EXPECT_EQ(c.cycleStartRefusal({1, 2})->args[0], "T02");
  // The exercise's comparison: tool 1 right to the click, tool 2 never touched off (geometry 0).
  EXPECT_EQ(c.touchOffError(1), (AxisValues{0.0, -0.001}));
  const auto compared = c.compareTouchOff({1, 2});
  ASSERT_TRUE(compared);
  EXPECT_EQ(compared->code, kc::kOffsetsCompared);
  EXPECT_EQ(compared->args, (std::vector<std::string>{"02", fmt::format("{:.3f}", c.trueTip(2).x),
                                                      fmt::format("{:.3f}", c.trueTip(2).z)}));
  EXPECT_EQ(c.compareTouchOff({1})->args, (std::vector<std::string>{"01", "0.000", "-0.001"}));
}

std::shared_ptr<const job::Job> compile(const std::string& gcode, const machine::MachineSetup& setup) {
  io::ProgramFile f;
  f.header = bar50x100();
  f.plainGcode = true;
  f.gcodeFirstLine = 1;
  f.gcode = gcode;
  job::JobInput input;
  input.file = f;
  input.setup = setup;
  input.inferTools = false;
  input.folder = std::string();
  return job::makeJob(std::move(input));
}

constexpr const char* kTurnTo40 = "G21 G99\nT0101\nG97 S800 M03\nG00 X52 Z2\nX40\nG01 Z-30 F0.2\nG00 X52\nZ2\nM30\n";

TEST(Control, AMisreadDiameterShowsInThePartCheckAsAnOversizeDiameter) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  c.forgetGeometry();
  referenceBoth(c);
  c.setSpindleSpeed(800.0);
  c.setSpindle(machine::SpindleDir::Cw);
  touchFace(c);
  c.measure(1, Axis::Z, 0.0);
  c.setSpindle(machine::SpindleDir::Cw);
  const double measured = skimDiameter(c, 49.0);
  // The student reads 48.8 on the micrometer instead of 49.0.
  c.measure(1, Axis::X, measured - 0.2);
  EXPECT_NEAR(c.runSetup().offsets.at(1).x, 0.2, 1e-9);

  const auto ideal = compile(kTurnTo40, shippedSetup());
  const auto student = compile(kTurnTo40, c.runSetup());
  ASSERT_TRUE(ideal->timeline() && student->timeline());
  const cut::CutSetup cs = cut::CutSetup::from(bar50x100(), c.runSetup());
  const cut::PartCheck wrong = cut::checkPart(*student->timeline(), *ideal->timeline(), cs);
  ASSERT_FALSE(wrong.defects.empty());
  const cut::PartDefect& d = wrong.defects.front();
  EXPECT_EQ(d.kind, cut::DefectKind::Leftover);
  EXPECT_NEAR(d.depth, 0.1, 0.002);  // radial: Ø40.2 instead of Ø40
  EXPECT_NEAR(d.diameter, 40.0, 1e-6);
  EXPECT_EQ(d.line, 6);

  // The right reading: the same check finds nothing.
  c.measure(1, Axis::X, measured);
  const auto right = compile(kTurnTo40, c.runSetup());
  EXPECT_TRUE(cut::checkPart(*right->timeline(), *ideal->timeline(), cut::CutSetup::from(bar50x100(), c.runSetup()))
                  .defects.empty());
}

TEST(Control, TheWrongStationAndATouchWithTheSpindleStoppedAreTheStudentsErrors) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  c.forgetGeometry();
  referenceBoth(c);
  c.setSpindle(machine::SpindleDir::Cw);
  touchFace(c);
  // T01 at the turret, the cursor on row 02: T0202 then runs tool 2 with tool 1's length.
  c.measure(2, Axis::Z, 0.0);
  EXPECT_NEAR(c.runSetup().offsets.at(2).z, c.trueTip(2).z - c.trueTip(1).z - 0.001, 1e-9);
  EXPECT_GT(std::abs(c.trueTip(1).z - c.trueTip(2).z), 1.0);

  // Spindle stopped: the jog stops where the tool meets the face, with a warning.
  rapidTipTo(c, 40.0, 1.0);
  c.setSpindle(machine::SpindleDir::Stopped);
  const MotionResult touch = c.jog(Axis::Z, -3.0, false);
  ASSERT_TRUE(touch.stop);
  EXPECT_EQ(touch.stop->code, kc::kTouchedSpindleStopped);
  EXPECT_EQ(touch.stop->severity, Severity::Warning);
  EXPECT_EQ(touch.stop->args[0], "01");
  EXPECT_FALSE(c.alarm());
  EXPECT_NEAR(c.tip().z, 0.0, 0.01);
  const auto warned = c.measure(1, Axis::Z, 0.0);
  ASSERT_TRUE(warned);
  EXPECT_EQ(warned->code, kc::kMeasuredAfterStoppedTouch);
  EXPECT_EQ(warned->args[0], "01");
  // No tool at station 12 of the shipped turret.
  ASSERT_FALSE(c.indexTurret(12));
  EXPECT_EQ(c.measure(12, Axis::Z, 0.0)->code, kc::kMeasureWithoutTool);
}

TEST(Control, MdiBlocksRunOneAtATimeThroughTheCheckerInterpreterAndCut) {
  Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
  referenceBoth(c);
  c.setMode(Mode::Mdi);
  EXPECT_TRUE(c.runMdi("G00 X60 Z5").empty());
  EXPECT_NEAR(c.tip().x, 60.0, 1e-9);
  EXPECT_NEAR(c.tip().z, 5.0, 1e-9);
  EXPECT_NEAR(c.absolutePosition().x, 60.0, 1e-9);
  EXPECT_NEAR(c.absolutePosition().z, 5.0, 1e-9);
  EXPECT_TRUE(c.runMdi("G97 S800 M03").empty());
  EXPECT_EQ(c.spindle(), machine::SpindleDir::Cw);
  EXPECT_EQ(c.spindleSpeed(), 800.0);
  EXPECT_TRUE(c.runMdi("G00 X40").empty());
  EXPECT_TRUE(c.runMdi("G01 Z-10 F0.2").empty());
  // The next block keeps G01, F and the spindle, as the control does.
  EXPECT_TRUE(c.runMdi("X44").empty());
  EXPECT_EQ(c.moves().moves.back().kind, machine::MoveKind::Line);
  const auto back = c.runMdi("G00 Z5");
  EXPECT_TRUE(back.empty()) << formatMessage(back.front(), Lang::En) << " line " << back.front().range.line;
  EXPECT_DOUBLE_EQ(c.micrometer(-5.0), 40.0);
  EXPECT_DOUBLE_EQ(c.micrometer(-20.0), 50.0);

  // A wrong block: the checker's error at its own line and column, nothing moves.
  const std::size_t before = c.moves().moves.size();
  const auto bad = c.runMdi("G00 X60\nG01 Z-5 F0.2 X");
  ASSERT_FALSE(bad.empty());
  EXPECT_TRUE(hasErrors(bad));
  EXPECT_EQ(bad.front().range.line, 2) << formatMessage(bad.front(), Lang::En);
  EXPECT_EQ(c.moves().moves.size(), before);
  // G99 feed with the spindle stopped: the interpreter's alarm.
  EXPECT_TRUE(c.runMdi("M05").empty());
  const auto stopped = c.runMdi("G01 X50 F0.2");
  ASSERT_FALSE(stopped.empty());
  EXPECT_EQ(stopped.back().code, kc::kFeedPerRevSpindleStopped);
  EXPECT_TRUE(c.alarm());
}

TEST(Control, OverridesChangeTheCycleTimeAsTheControlWould) {
  EXPECT_EQ(stepFeedOverride(100, 6), 150);
  EXPECT_EQ(stepFeedOverride(10, -3), 0);
  EXPECT_EQ(stepRapidOverride(100, -1), 50);
  EXPECT_EQ(stepRapidOverride(25, -1), 0);
  EXPECT_EQ(stepRapidOverride(0, 5), 100);
  EXPECT_EQ(stepSpindleOverride(100, 3), 120);
  EXPECT_EQ(stepSpindleOverride(60, -3), 50);

  const char* program =
      "G21 G99\nT0101\nG97 S800 M03\nG00 X40 Z2\nG01 Z-30 F0.2\nG98 G01 X50 F100\nG04 X1.0\nG00 X60 Z5\n"
      "G99 G00 X30 Z5\nG32 Z-20 F1.5\nG00 X60\nM30\n";
  const auto job = compile(program, shippedSetup());
  ASSERT_TRUE(job->timeline()) << (job->diagnostics().empty() ? ""
                                                              : formatMessage(job->diagnostics().front(), Lang::En));
  const machine::Timeline& t = *job->timeline();
  double rapid = 0, perRev = 0, perMin = 0, dwell = 0, thread = 0;
  for (const machine::Move& m : t.moves) {
    const double d = m.tEnd - m.tStart;
    switch (m.kind) {
      case machine::MoveKind::Rapid: rapid += d; break;
      case machine::MoveKind::Dwell: dwell += d; break;
      case machine::MoveKind::Thread: thread += d; break;
      default: (m.line == 6 ? perMin : perRev) += d;
    }
  }
  ASSERT_GT(rapid * perRev * perMin * dwell * thread, 0.0);
  EXPECT_NEAR(dwell, 1.0, 1e-9);

  Overrides o;
  o.feed = 50;
  o.rapid = 25;
  o.spindle = 120;
  const machine::Timeline slow = withOverrides(t, o, shippedSetup().machine);
  EXPECT_NEAR(slow.cycleTime(), rapid * 4 + perRev / (0.5 * 1.2) + perMin / 0.5 + dwell + thread / 1.2, 1e-9);
  EXPECT_NEAR(slow.snapshots.back().time, slow.cycleTime(), 1e-9);
  // 100 % everywhere: the program's own time.
  EXPECT_NEAR(withOverrides(t, Overrides{}, shippedSetup().machine).cycleTime(), t.cycleTime(), 1e-9);

  // Rapid F0: every rapid at 400 mm/min on both axes.
  Overrides f0;
  f0.rapid = 0;
  double rapidF0 = 0;
  for (const machine::Move& m : t.moves)
    if (m.kind == machine::MoveKind::Rapid) rapidF0 += machine::rapidSeconds(m.path, kRapidF0Rate, kRapidF0Rate);
  EXPECT_NEAR(withOverrides(t, f0, shippedSetup().machine).cycleTime(), t.cycleTime() - rapid + rapidF0, 1e-9);

  // Feed hold at 0 %: the first feed move never ends.
  Overrides hold;
  hold.feed = 0;
  EXPECT_TRUE(std::isinf(withOverrides(t, hold, shippedSetup().machine).cycleTime()));
}

TEST(Control, TheRunsClockPlaysEachMoveAtTheOverriddenSpeed) {
  const auto job = compile(kTurnTo40, shippedSetup());
  ASSERT_TRUE(job->timeline());
  const machine::Timeline& t = *job->timeline();
  int feed = -1, rapid = -1;
  for (int i = 0; i < static_cast<int>(t.moves.size()); ++i) {
    const machine::Move& m = t.moves[static_cast<std::size_t>(i)];
    if (m.tEnd <= m.tStart) continue;
    if (feed < 0 && m.kind == machine::MoveKind::Line) feed = i;
    if (rapid < 0 && m.kind == machine::MoveKind::Rapid) rapid = i;
  }
  ASSERT_GE(feed, 0);
  ASSERT_GE(rapid, 0);
  const machine::Move& f = t.moves[static_cast<std::size_t>(feed)];
  const machine::Move& r = t.moves[static_cast<std::size_t>(rapid)];
  const double fd = f.tEnd - f.tStart, rd = r.tEnd - r.tStart;
  // G01 Z-30 F0.2 at 800 rpm: 30 / (0.2 x 800) min = 11.25 s at full feed, and the ramps.
  EXPECT_GT(fd, 11.25);
  EXPECT_LT(fd, 13.0);

  Overrides half;
  half.feed = 50;
  const OverrideClock clock(t, half, shippedSetup().machine);
  EXPECT_DOUBLE_EQ(clock.rate(feed), 0.5);
  EXPECT_DOUBLE_EQ(clock.rate(rapid), 1.0);
  // 11.25 s of the machine's time get the feed move half way, 22.5 s to its end; the rapid keeps its time.
  EXPECT_NEAR(clock.advance(f.tStart, fd), f.tStart + fd / 2.0, 1e-9);
  EXPECT_NEAR(clock.advance(f.tStart, 2.0 * fd), f.tEnd, 1e-9);
  EXPECT_NEAR(clock.advance(r.tStart, rd), r.tEnd, 1e-9);
  // The whole run: the cycle time withOverrides gives brings the clock to the timeline's end.
  const double slow = withOverrides(t, half, shippedSetup().machine).cycleTime();
  EXPECT_NEAR(slow, t.cycleTime() + fd, 1e-9);
  EXPECT_NEAR(clock.advance(0.0, slow), t.cycleTime(), 1e-9);
  // Spindle 120 %: a feed per revolution is 1.2 times as fast; at 100 % everything as programmed.
  Overrides fast;
  fast.spindle = 120;
  EXPECT_NEAR(OverrideClock(t, fast, shippedSetup().machine).rate(feed), 1.2, 1e-12);
  EXPECT_NEAR(OverrideClock(t, Overrides{}, shippedSetup().machine).advance(1.0, 7.5), 8.5, 1e-12);

  // Feed override 0: the run reaches the feed move and stands there, however long the clock runs.
  Overrides stand;
  stand.feed = 0;
  const OverrideClock held(t, stand, shippedSetup().machine);
  EXPECT_DOUBLE_EQ(held.rate(feed), 0.0);
  EXPECT_NEAR(held.advance(0.0, 1000.0), f.tStart, 1e-9);
}

// The setup exercise graded in a class (issue 31 item 5): each student touches off T01 at the
// panel, the touch-off is saved beside the program, and klueng-cli class compares it.
TEST(Control, AClassIsGradedOnTheOffsetsItsStudentsTouchedOff) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("klueng_touchoff_class_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  const std::string head = "Setup exercise\nShaft\nAluminium\n150\n1100\nTeacher\n";
  const auto write = [](const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; };
  write(dir / "reference.nc", head + kTurnTo40);
  for (const char* name : {"a.nc", "b.nc", "c.nc"})
    write(dir / "class" / name, head + "(OFFSETS: UNKNOWN)\n" + kTurnTo40);
  // Student a touches off right (Z one click into the face), student b types the radius for X.
  for (const auto& [name, reading] : {std::pair{"a", 0.0}, std::pair{"b", 24.5}}) {
    Control c(shippedSetup(), bar50x100(), gcode::Dialect::Fanuc);
    c.forgetGeometry();
    referenceBoth(c);
    c.setSpindleSpeed(800.0);
    c.setSpindle(machine::SpindleDir::Cw);
    touchFace(c);
    c.measure(1, Axis::Z, 0.0);
    c.setSpindle(machine::SpindleDir::Cw);
    const double measured = skimDiameter(c, 49.0);
    c.measure(1, Axis::X, reading > 0.0 ? reading : measured);
    EXPECT_FALSE(c.cycleStartRefusal({1}));
    const std::string program = (dir / "class" / (std::string(name) + ".nc")).string();
    EXPECT_EQ(job::touchOffFilePath(program), (dir / "class" / (std::string(name) + ".offset.cfg")).string());
    write(job::touchOffFilePath(program), io::formatOffsetTable(c.runSetup().offsets));
  }
  // Student c never saved a touch-off.

  job::JobInput base;
  base.setup = shippedSetup();
  base.run.dialect = gcode::Dialect::Fanuc;
  const job::GradedProgram reference = job::gradeProgram((dir / "reference.nc").string(), base);
  ASSERT_TRUE(reference.part) << reference.firstError << reference.alarm;
  const std::vector<job::ClassRow> rows =
      job::gradeClass((dir / "class").string(), (dir / "reference.nc").string(), *reference.part, base, 0.05);
  ASSERT_EQ(rows.size(), 3u);

  const job::ClassRow& a = rows[0];
  EXPECT_EQ(a.file, "a.nc");
  EXPECT_TRUE(a.touchOff.asked && a.touchOff.saved);
  ASSERT_EQ(a.touchOff.tools.size(), 1u);
  EXPECT_EQ(a.touchOff.tools[0].station, 1);
  EXPECT_NEAR(a.touchOff.tools[0].enteredX, 0.0, 1e-9);
  EXPECT_NEAR(a.touchOff.tools[0].enteredZ, -0.001, 1e-9);
  EXPECT_EQ(a.touchOff.tools[0].trueX, shippedSetup().offsets.at(1).x);
  EXPECT_EQ(a.touchOff.tools[0].trueZ, shippedSetup().offsets.at(1).z);
  EXPECT_TRUE(a.touchOff.tools[0].within);
  EXPECT_TRUE(a.pass);
  EXPECT_EQ(job::touchOffSummary(a.touchOff), "T01 X0.000/0.000 Z-0.001/0.000 in");
  EXPECT_EQ(job::touchOffText(a.touchOff, 0.05, Lang::En),
            "T01 touched off at X0.000 Z-0.001, true X0.000 Z0.000: within 0.050 mm");
  EXPECT_EQ(job::touchOffText(a.touchOff, 0.05, Lang::Th),
            "T01 ตั้งศูนย์ได้ X0.000 Z-0.001 ค่าจริง X0.000 Z0.000: อยู่ในพิกัด 0.050 มม.");

  // The radius typed for the diameter: 24.5 mm out, and the run on those offsets cuts nothing of the Ø40.
  const job::ClassRow& b = rows[1];
  ASSERT_EQ(b.touchOff.tools.size(), 1u);
  EXPECT_NEAR(b.touchOff.tools[0].enteredX, 24.5, 1e-9);
  EXPECT_FALSE(b.touchOff.tools[0].within);
  EXPECT_FALSE(b.pass);
  EXPECT_TRUE(b.compared);
  EXPECT_NEAR(b.deviation.leftover, 10.0, 0.01);  // on the diameter: the bar's Ø50 left where Ø40 was turned
  EXPECT_EQ(job::touchOffSummary(b.touchOff), "T01 X24.500/0.000 Z-0.001/0.000 out");

  const job::ClassRow& c = rows[2];
  EXPECT_TRUE(c.touchOff.asked);
  EXPECT_FALSE(c.touchOff.saved);
  EXPECT_FALSE(c.pass);
  EXPECT_TRUE(c.compared);  // its part is right (the true offsets), the exercise is not done
  EXPECT_EQ(job::touchOffText(c.touchOff, 0.05, Lang::En),
            "the offsets are unknown but c.offset.cfg was not found: touch off at the Operator panel, then MEM + "
            "CYCLE START saves it");

  const std::string csv = job::classCsv(rows);
  EXPECT_NE(csv.find("gouge_mm,gouge_z,cutting_data,touch_off\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",T01 X0.000/0.000 Z-0.001/0.000 in\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",not saved (c.offset.cfg)\n"), std::string::npos) << csv;
  fs::remove_all(dir);
}

TEST(Control, TheOffsetPageReadsAnAxisAndAValue) {
  EXPECT_EQ(parseMeasureInput("X49.6")->axis, Axis::X);
  EXPECT_DOUBLE_EQ(parseMeasureInput("X49.6")->value, 49.6);
  EXPECT_DOUBLE_EQ(parseMeasureInput(" z0 ")->value, 0.0);
  EXPECT_DOUBLE_EQ(parseMeasureInput("Z -0.5")->value, -0.5);
  EXPECT_FALSE(parseMeasureInput("X"));
  EXPECT_FALSE(parseMeasureInput("Y3"));
  EXPECT_FALSE(parseMeasureInput("X4a"));
  EXPECT_FALSE(parseMeasureInput("49.6"));
}

}  // namespace
}  // namespace klueng::core::control
