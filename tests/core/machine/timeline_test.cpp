// The sink chain and the Timeline as a whole: canonical calls, continuity of
// the path and of time, positionAt/moveAt.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../../../bench/program_generator.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/trace.h"
#include "test_support.h"

namespace klueng::core::machine {
namespace {

using testing::runText;
using testing::testSetup;

// Records the canonical calls as text lines, like a printing sink would.
class RecordingSink final : public MachineSink {
 public:
  std::vector<std::string> calls;
  void motion(const MotionCall& m) override {
    calls.push_back(std::string(moveKindName(m.kind)) + " " + std::to_string(m.line) + " X" +
                    std::to_string(static_cast<int>(std::lround(20.0 * m.path.end.y()))) + "/10 Z" +
                    std::to_string(static_cast<int>(std::lround(10.0 * m.path.end.x()))) + "/10");
  }
  void dwell(const DwellCall& d) override { calls.push_back("DWELL " + std::to_string(d.line)); }
  void setPosition(const Vec2&) override { calls.push_back("SET"); }
  void compensation(NoseCompMode mode, double radius, int tip) override {
    calls.push_back(std::string("COMP ") +
                    (mode == NoseCompMode::Right  ? "R"
                     : mode == NoseCompMode::Left ? "L"
                                                  : "OFF") +
                    " " + std::to_string(static_cast<int>(std::lround(radius * 10))) + " " + std::to_string(tip));
  }
  void blockDone(const StateSnapshot& s) override { calls.push_back("DONE " + std::to_string(s.line)); }
  void alarm(const Diagnostic& d) override { calls.push_back("ALARM " + d.code); }
  void end() override { calls.push_back("END"); }
  bool halted() const override { return false; }
};

TEST(Sink, InterpreterEmitsCanonicalCallsWithProgrammedPaths) {
  const gcode::Program program =
      gcode::parse("G98 T0101\nG42 G00 X20. Z2.\nG01 Z-10. F100.\nG04 P100\nG40 G00 X50. Z10.\n", 1);
  RecordingSink sink;
  run(program, testSetup(), {}, sink);
  const std::vector<std::string> expected = {"SET",
                                             "DONE 1",
                                             "COMP R 8 3",
                                             "RAPID 2 X200/10 Z20/10",
                                             "DONE 2",
                                             "LINE 3 X200/10 Z-100/10",
                                             "DONE 3",
                                             "DWELL 4",
                                             "DONE 4",
                                             "COMP OFF 8 3",
                                             "RAPID 5 X500/10 Z100/10",
                                             "DONE 5",
                                             "END"};
  EXPECT_EQ(sink.calls, expected);
}

TEST(Sink, CompensationStageCanBeChainedInFrontOfAnySink) {
  const gcode::Program program =
      gcode::parse("G98 T0101\nG42 G00 X20. Z2.\nG01 Z-10. F100.\nX30.\nG40 G00 X50. Z10.\n", 1);
  RecordingSink sink;
  auto comp = makeCompensationStage(sink);
  run(program, testSetup(), {}, *comp);
  // Start-up ends at the tip X20 Z1.2, the face's end at X28.4 (see the golden case
  // g42_nose_comp_right); block 2's DONE comes after its (delayed) move.
  const std::vector<std::string> expected = {"SET",
                                             "DONE 1",
                                             "RAPID 2 X200/10 Z12/10",
                                             "DONE 2",
                                             "LINE 3 X200/10 Z-100/10",
                                             "DONE 3",
                                             "LINE 4 X284/10 Z-100/10",
                                             "DONE 4",
                                             "RAPID 5 X500/10 Z100/10",
                                             "DONE 5",
                                             "END"};
  EXPECT_EQ(sink.calls, expected);
}

void expectContinuous(const Timeline& t) {
  for (std::size_t i = 1; i < t.moves.size(); ++i) {
    const Move& a = t.moves[i - 1];
    const Move& b = t.moves[i];
    ASSERT_DOUBLE_EQ(a.tEnd, b.tStart) << "move " << i;
    ASSERT_LE(b.tStart, b.tEnd) << "move " << i;
    ASSERT_TRUE(std::isfinite(b.tEnd)) << "move " << i;
    ASSERT_LT((a.path.end - b.path.start).norm(), 1e-6) << "move " << i << " line " << b.line;
  }
  for (std::size_t i = 1; i < t.snapshots.size(); ++i) {
    ASSERT_LE(t.snapshots[i - 1].time, t.snapshots[i].time);
    ASSERT_LE(t.snapshots[i - 1].moveEnd, t.snapshots[i].moveEnd);
  }
}

TEST(Timeline, GeneratedProgramIsContinuousInSpaceAndTime) {
  const auto file = io::parseProgramFile(klueng::bench::ProgramGenerator::generate(20000));
  ASSERT_TRUE(file.value);
  const gcode::Program program = gcode::parse(file.value->gcode, file.value->gcodeFirstLine);
  const Timeline t = interpret(program, testSetup());
  ASSERT_FALSE(t.alarm) << t.alarm->code << " line " << t.alarm->range.line;
  EXPECT_EQ(t.snapshots.size(), program.blocks.size());
  expectContinuous(t);
  std::size_t compensated = 0;
  for (const Move& m : t.moves) compensated += m.compensated ? 1 : 0;
  EXPECT_GT(compensated, 1000u);  // the last tenth runs under G42
  EXPECT_TRUE(t.snapshots.back().stopped);
}

TEST(Timeline, PositionAtAndMoveAtFollowTheMoves) {
  const Timeline t = runText("G00 X100. Z100.\n");  // legs end at 0.75 s (X100 Z200) and 1.5 s
  EXPECT_EQ(t.moveAt(-1.0), -1);
  EXPECT_EQ(t.moveAt(0.5), 0);
  EXPECT_EQ(t.moveAt(1.0), 1);
  EXPECT_POINT(t.positionAt(0.375), 50.0, 250.0);
  EXPECT_POINT(t.positionAt(1.125), 100.0, 150.0);
  EXPECT_POINT(t.positionAt(99.0), 100.0, 100.0);
}

TEST(Timeline, TraceCsvHasTheExactHeaderAndOneRowPerMove) {
  const Timeline t = runText("G98 G00 X20. Z0.\nG02 X30. Z-5. R5. F100.\nG04 P500\n");
  const std::string csv = formatTraceCsv(t);
  const std::string header =
      "kind,line,t_start,t_end,x_start,z_start,x_end,z_end,i,k,dir,feed_mm_min,rpm,level,program\n";
  ASSERT_EQ(csv.rfind(header, 0), 0u);
  EXPECT_NE(csv.find("\nARC,2,2.2500,6.9624,20.0000,0.0000,30.0000,-5.0000,5.0000,0.0000,CW,100.0000,0.0000,0,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nDWELL,3,6.9624,7.4624,30.0000,-5.0000,30.0000,-5.0000,0.0000,0.0000,,0.0000,0.0000,0,\n"),
            std::string::npos)
      << csv;
  std::size_t rows = 0;
  for (char c : csv) rows += c == '\n';
  EXPECT_EQ(rows, t.moves.size() + 1);
}

TEST(Robustness, OddProgramsNeverCrashAndKeepFiniteTimes) {
  // Blocks a checker would reject or that are merely strange: the interpreter
  // must still stop cleanly or run with finite, continuous times.
  const char* programs[] = {
      "G02 X10. Z300.\n",                        // arc without feed
      "G98 G02 X0. Z300. R5. F100\n",            // zero-chord arc by R
      "G98 G03 X0. Z300. I-5. F100\n",           // full circle by I/K
      "G98 G02 X10. Z290. F100\n",               // arc without R or I/K
      "G98 G01 X9999.999 F100\n",                // far away (travel limit)
      "G96 S9999 M03\nG98 G01 X0. Z0. F9999\n",  // huge G96 speed, through X0
      "G04 P-5\n",                               // negative dwell
      "G50 X-10. Z-10.\nG28 U0. W0.\n",          // G50 then the reference point
      "G42\nG40\nG42 G41 G01 X5.\n",             // comp toggles without moves
      "M03 M04 M05\nM86 M87\n",                  // conflicting M codes in one block
      "T9999\n",                                 // tool 99, offset 99
      "G20 G96 S100 M03\nG01 X1. F0.01\n",       // inch surface speed
  };
  for (const char* text : programs) {
    SCOPED_TRACE(text);
    const Timeline t = runText(text);
    expectContinuous(t);
    EXPECT_TRUE(std::isfinite(t.cycleTime()));
  }
}

}  // namespace
}  // namespace klueng::core::machine
