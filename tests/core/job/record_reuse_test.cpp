// The tool inference's recorded run becomes the timeline when it is the run
// (issue 29 item 14: a plain program is interpreted once): exact, move by move,
// and never when nose compensation, an alarm, a stand-in feed, another nose or
// the stored #500-#999 would make the run differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/messages.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/machine/trace.h"
#include "../machine/test_support.h"

namespace klueng::core::job {
namespace {

const machine::LoadedSetup& shippedForReuse() {
  static const machine::LoadedSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

JobInput runRequest(const std::string& path) {
  JobInput r;
  r.path = path;
  r.setup = shippedForReuse().setup;
  r.stations = shippedForReuse().setup.tools.stations;
  r.timelineNext = true;  // as klueng-cli simulate asks
  return r;
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The job's timeline and whether it was the recorded run.
struct Asked {
  const machine::Timeline* timeline = nullptr;
  bool reused = false;
};
Asked askTimeline(const Job& job) {
  const long long before = computeLog().reusedRecords;
  Asked a;
  a.timeline = job.timeline();
  a.reused = computeLog().reusedRecords == before + 1;
  return a;
}

// Every field of every move and snapshot, and the flow log's writes and notices.
void expectSameRun(const machine::Timeline& got, const machine::Timeline& want) {
  ASSERT_EQ(got.moves.size(), want.moves.size());
  for (std::size_t i = 0; i < want.moves.size(); ++i) {
    const machine::Move& a = got.moves[i];
    const machine::Move& b = want.moves[i];
    SCOPED_TRACE("move " + std::to_string(i) + " line " + std::to_string(b.line));
    EXPECT_EQ(a.path.start, b.path.start);
    EXPECT_EQ(a.path.end, b.path.end);
    EXPECT_EQ(a.path.centre, b.path.centre);
    EXPECT_EQ(a.path.kind, b.path.kind);
    EXPECT_EQ(a.path.ccw, b.path.ccw);
    EXPECT_EQ(a.noseCentre, b.noseCentre);
    EXPECT_EQ(a.tStart, b.tStart);
    EXPECT_EQ(a.tEnd, b.tEnd);
    EXPECT_EQ(a.feed, b.feed);
    EXPECT_EQ(a.rpm, b.rpm);
    EXPECT_EQ(a.rpmEnd, b.rpmEnd);
    EXPECT_EQ(a.lead, b.lead);
    EXPECT_EQ(a.rampUp, b.rampUp);
    EXPECT_EQ(a.rampDown, b.rampDown);
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.blockIndex, b.blockIndex);
    EXPECT_EQ(a.file, b.file);
    EXPECT_EQ(a.callLevel, b.callLevel);
    EXPECT_EQ(a.program, b.program);
    EXPECT_EQ(a.tool, b.tool);
    EXPECT_EQ(a.offset, b.offset);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.spindle, b.spindle);
    EXPECT_EQ(a.compensated, b.compensated);
  }
  ASSERT_EQ(got.snapshots.size(), want.snapshots.size());
  for (std::size_t i = 0; i < want.snapshots.size(); ++i) {
    const machine::StateSnapshot& a = got.snapshots[i];
    const machine::StateSnapshot& b = want.snapshots[i];
    SCOPED_TRACE("snapshot " + std::to_string(i) + " line " + std::to_string(b.line));
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.blockIndex, b.blockIndex);
    EXPECT_EQ(a.moveEnd, b.moveEnd);
    EXPECT_EQ(a.callStack, b.callStack);
    EXPECT_EQ(a.machine.position, b.machine.position);
    EXPECT_EQ(a.machine.tool, b.machine.tool);
    EXPECT_EQ(a.machine.offset, b.machine.offset);
    EXPECT_EQ(a.machine.spindle, b.machine.spindle);
    EXPECT_EQ(a.modal.motion, b.modal.motion);
    EXPECT_EQ(a.modal.noseComp, b.modal.noseComp);
    EXPECT_EQ(a.stopped, b.stopped);
  }
  EXPECT_EQ(got.alarm.has_value(), want.alarm.has_value());
  EXPECT_EQ(got.flow.writes.size(), want.flow.writes.size());
  EXPECT_EQ(got.flow.notices.size(), want.flow.notices.size());
  EXPECT_EQ(got.flow.stacks.size(), want.flow.stacks.size());
  // The golden traces' own form, as a last word.
  EXPECT_EQ(machine::formatTraceCsv(got), machine::formatTraceCsv(want));
}

// The run a job would make without any record: interpret() with its setup and options.
machine::Timeline freshRun(const Job& job) { return machine::interpret(*job.program(), job.setup(), job.input().run); }

TEST(RecordReuse, ACycleProgramIsInterpretedOnceAndItsRunIsTheFreshRunMoveByMove) {
  // The canned-cycle sample (G71/G70 under G96, G76, two tools) without its G42 finish.
  std::string text = readText(KLUENG_SAMPLES_DIR "/06-canned-cycles.txt");
  const std::size_t g42 = text.find("G42 ");
  ASSERT_NE(g42, std::string::npos);
  text.erase(g42, 4);
  const machine::testing::ScratchFolder folder{"reuse"};
  const auto job = makeJob(runRequest(folder.write("cycles.txt", text)));
  ASSERT_FALSE(job->hasErrors());
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_TRUE(asked.reused);
  ASSERT_GT(asked.timeline->moves.size(), 100u);  // G71 passes, G70, G76 passes
  EXPECT_FALSE(asked.timeline->alarm);
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, AThreadSampleReusedIsTheFreshRun) {
  const auto job = makeJob(runRequest(KLUENG_SAMPLES_DIR "/02-thread.txt"));
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_TRUE(asked.reused);
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, ACompensatedProgramRunsAgainWithItsCompensation) {
  // 01-step-shaft finishes under G42 (line 41): the record followed the programmed path.
  const auto job = makeJob(runRequest(KLUENG_SAMPLES_DIR "/01-step-shaft.txt"));
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  const bool compensated = std::any_of(asked.timeline->moves.begin(), asked.timeline->moves.end(),
                                       [](const machine::Move& m) { return m.compensated; });
  EXPECT_TRUE(compensated);
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, AnAlarmedProgramRunsAgainAndStopsAtItsAlarm) {
  // 05-runtime-alarms: line 12 cuts with the spindle stopped; the record went on through it.
  const auto job = makeJob(runRequest(KLUENG_SAMPLES_DIR "/05-runtime-alarms.txt"));
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  ASSERT_TRUE(asked.timeline->alarm);
  EXPECT_EQ(asked.timeline->alarm->range.line, 12);
  EXPECT_EQ(asked.timeline->snapshots.back().line, 11);  // nothing after the alarmed block ran
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, ACutWithoutSpindleRunsAgainWithoutTheRecordsStandInSpeed) {
  // Feed per minute with the spindle stopped is no alarm, but a record times it at a stand-in speed.
  const machine::testing::ScratchFolder folder{"reuse"};
  const auto job = makeJob(runRequest(folder.write("nospindle.txt",
                                                   "No spindle\nPart\nSteel\n150\n1100\nKlueng\n"
                                                   "O0001\nG21 G98\nT0101\nG00 X52. Z2.\n"
                                                   "G01 X48. F120.\nZ-20.\nG00 X100. Z100.\nM30\n")));
  ASSERT_FALSE(job->hasErrors());
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  EXPECT_FALSE(asked.timeline->alarm);
  const machine::Move* cut = nullptr;
  for (const machine::Move& m : asked.timeline->moves)
    if (m.line == 12) cut = &m;
  ASSERT_TRUE(cut);
  EXPECT_EQ(cut->spindle, machine::SpindleDir::Stopped);
  EXPECT_DOUBLE_EQ(cut->feed, 120.0);
  EXPECT_DOUBLE_EQ(cut->tEnd - cut->tStart, 22.0 / 120.0 * 60.0);  // Z2 to Z-20 at 120 mm/min
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, AGuessedToolsNoseMakesTheRunAgain) {
  // T0909 with offset row 9 empty (0 0 0 0): the library's boring bar brings its nose (I410),
  // which the record (made with the empty row) has not.
  const machine::testing::ScratchFolder folder{"reuse"};
  const auto job = makeJob(runRequest(folder.write("guess.nc",
                                                   "O0100\nG21 G40 G99\nT0909 (BORING BAR)\n"
                                                   "G97 S800 M03\nG00 X20. Z2.\nG01 Z-30. F0.1\n"
                                                   "X18.\nG00 Z2.\nG00 X150. Z150.\nM30\n")));
  ASSERT_FALSE(job->hasErrors());
  ASSERT_EQ(shippedForReuse().setup.offsets.at(9), io::Offset{});  // the shipped row 9 is empty
  ASSERT_GT(job->setup().offsets.at(9).r, 0.0);                    // filled from the library
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  expectSameRun(*asked.timeline, freshRun(*job));
}

TEST(RecordReuse, StoredVariablesAProgramReadsMakeTheRunAgain) {
  const machine::testing::ScratchFolder folder{"reuse"};
  const std::string path = folder.write("count.txt",
                                        "Counter\nPart\nSteel\n150\n1100\nKlueng\n"
                                        "O0001\nG21 G99\nT0101\nG97 S800 M03\n"
                                        "#500=#500+1\nG00 X[40+#500] Z2.\nG00 X100. Z100.\nM30\n");
  std::map<int, double> stored{{500, 2.0}};
  JobInput input = runRequest(path);
  input.run.persistentVariables = &stored;
  const auto job = makeJob(input);
  ASSERT_FALSE(job->hasErrors());
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  EXPECT_DOUBLE_EQ(stored.at(500), 3.0);  // read, counted and kept
  const machine::Move* approach = nullptr;
  for (const machine::Move& m : asked.timeline->moves)
    if (m.line == 12) approach = &m;
  ASSERT_TRUE(approach);
  EXPECT_DOUBLE_EQ(approach->path.end.y(), 43.0 / 2.0);  // X43: the stored 2, plus 1
}

TEST(RecordReuse, StoredVariablesAPlainProgramNeverTouchesLeaveTheRecordTheRun) {
  std::map<int, double> stored{{500, 2.0}, {501, 7.5}};
  JobInput input = runRequest(KLUENG_SAMPLES_DIR "/02-thread.txt");
  input.run.persistentVariables = &stored;
  const auto job = makeJob(input);
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_TRUE(asked.reused);
  EXPECT_EQ(stored, (std::map<int, double>{{500, 2.0}, {501, 7.5}}));
}

TEST(RecordReuse, TheEditorsCheckKeepsNoRecord) {
  JobInput input = runRequest(KLUENG_SAMPLES_DIR "/02-thread.txt");
  input.timelineNext = false;
  const auto job = makeJob(input);
  const Asked asked = askTimeline(*job);
  ASSERT_TRUE(asked.timeline);
  EXPECT_FALSE(asked.reused);
  expectSameRun(*asked.timeline, freshRun(*job));
}

// The check keeps no whole record (issue 40 item 1): its record keeps a mark a block, its moves
// packed and, for the cutting data, each move's feeds and speeds; the cutting-data warnings it
// gives are the whole record's, word for word.
TEST(RecordReuse, TheChecksPackedRecordGivesTheWholeRecordsCuttingData) {
  // Station 1 HSS in S45C: too fast at S1000 (W330 on line 12), a rough finish at F0.5 (W332 on
  // line 15), an arc and a dwell between them; G96 on a taper (line 18: the rpm changes along it).
  const std::string text =
      "Cutting data\nShaft\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S1000 M03\nG00 X60. Z2.\n"
      "X49.4\nG01 Z-20. F0.2\nG02 X53.4 Z-22. R2.\nG00 X60. Z2.\nG01 X48.8 Z-5. F0.5\nG04 X0.2\n"
      "G50 S2000\nG96 S300\nG01 X40. Z-15. F0.3\nG00 X60.\nM30\n";
  const io::ProgramFile file = *io::parseProgramFile(text).value;
  machine::MachineSetup setup = shippedForReuse().setup;
  setup.tools.material[0] = "hss";
  const gcode::Program program = gcode::parse(file.gcode, file.gcodeFirstLine);
  machine::RunOptions whole;
  machine::RunOptions packed;
  packed.blockMarksOnly = true;
  packed.recordSpeeds = true;
  const machine::Timeline a = machine::recordRun(program, setup, whole);
  const machine::Timeline b = machine::recordRun(program, setup, packed);
  ASSERT_TRUE(b.moves.empty() && b.snapshots.empty());
  ASSERT_EQ(b.recordSpeeds.size(), a.moves.size());
  const auto said = [&](const machine::Timeline& record) {
    std::vector<std::string> out;
    for (const Diagnostic& d : cut::checkCuttingData(record, file.header, setup, DisplayUnits::Mm))
      out.push_back(std::to_string(d.range.line) + " " + formatMessage(d, Lang::En));
    return out;
  };
  const std::vector<std::string> fromWhole = said(a);
  EXPECT_EQ(said(b), fromWhole);
  ASSERT_GE(fromWhole.size(), 2u);
  const auto on = [&](const char* line, const char* code) {
    return std::any_of(fromWhole.begin(), fromWhole.end(), [&](const std::string& w) {
      return w.rfind(std::string(line) + " ", 0) == 0 && w.find(code) != std::string::npos;
    });
  };
  EXPECT_TRUE(on("12", "cutting speed")) << fromWhole.front();
  EXPECT_TRUE(on("15", "finishing feed")) << fromWhole.back();
  // A record without its moves' speeds measures nothing rather than something wrong.
  packed.recordSpeeds = false;
  EXPECT_TRUE(said(machine::recordRun(program, setup, packed)).empty());
  // The check itself (no run follows) says the same warnings from its packed record.
  JobInput input;
  input.setup = setup;
  input.stations = setup.tools.stations;
  input.file = file;
  input.folder = std::string();
  const auto job = makeJob(input);
  std::vector<std::string> fromCheck;
  for (const Diagnostic& d : job->diagnostics())
    if (d.code.rfind("W33", 0) == 0)
      fromCheck.push_back(std::to_string(d.range.line) + " " + formatMessage(d, Lang::En));
  EXPECT_EQ(fromCheck, fromWhole);
}

}  // namespace
}  // namespace klueng::core::job
