// One row per code (issue 30 item 3): the explain bar and tool inference read a
// code's row by its action, never its number, so a machine in G-code system B
// (the shipped ROMI GL 240M: G33 threads, G78 the threading cycle, G92 S the
// speed clamp, G95 feed per revolution) is explained and its tools inferred as
// system A's G32, G92, G50 and G99 are.
#include <gtest/gtest.h>

#include <iterator>
#include <string>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/help/explain.h"
#include "klueng/core/infer/tool_inference.h"
#include "test_support.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::machine::system_codes_test {
namespace {

gcode::Dialect romi() {
  gcode::Dialect d{};
  EXPECT_TRUE(gcode::parseDialectId("romi-gl240m", d));
  return d;
}

// Outside threading with G32, inside threading with the G92 cycle, a drill on
// centre: written in system A; the system-B program is the same in its numbers.
constexpr std::string_view kThreadsInA =
    "G21 G99\n"               // 1
    "G50 S2000\n"             // 2
    "T1010\n"                 // 3
    "G97 S800 M03\n"          // 4
    "G00 X0 Z3.\n"            // 5
    "G01 Z-25. F0.1\n"        // 6
    "G00 Z3.\n"               // 7
    "T1111\n"                 // 8
    "G00 X18. Z5.\n"          // 9
    "G92 X20.2 Z-15. F1.5\n"  // 10
    "X20.6\n"                 // 11
    "G00 X18. Z5.\n"          // 12
    "X100. Z100.\n"           // 13
    "T0404\n"                 // 14
    "G00 X29.4 Z5.\n"         // 15
    "G32 Z-20. F1.5\n"        // 16
    "Z-22.\n"                 // 17
    "G00 X40.\n"              // 18
    "Z5.\n"                   // 19
    "M30\n";

TEST(SystemCodes, TheSystemBProgramIsTheSameProgramInItsNumbers) {
  const std::string b = gcode::inSystemNumbers(kThreadsInA, romi());
  for (const char* code : {"G95\n", "G92 S2000", "G78 X20.2", "G33 Z-20."})
    EXPECT_NE(b.find(code), std::string::npos) << code << "\n" << b;
  for (const char* code : {"G99", "G50", "G32"}) EXPECT_EQ(b.find(code), std::string::npos) << code << "\n" << b;
}

TEST(SystemCodes, G33AndG78SayWhatG32AndG92Say) {
  const gcode::Dialect b = romi();
  EXPECT_EQ(explainCode('G', 33, b, Lang::En), "cut one pass of a thread, the feed locked to the spindle");
  EXPECT_EQ(explainCode('G', 78, b, Lang::En), "threading cycle: one thread pass and back to the start");
  for (const Lang lang : {Lang::En, Lang::Th}) {
    EXPECT_EQ(explainCode('G', 33, b, lang), explainCode('G', 32, gcode::Dialect::Fanuc, lang));
    EXPECT_EQ(explainCode('G', 78, b, lang), explainCode('G', 92, gcode::Dialect::Fanuc, lang));
    EXPECT_EQ(explainCode('G', 92, b, lang), explainCode('G', 50, gcode::Dialect::Fanuc, lang));
    EXPECT_EQ(explainCode('G', 95, b, lang), explainCode('G', 99, gcode::Dialect::Fanuc, lang));
  }
  // System B's G92 is not system A's threading cycle.
  EXPECT_NE(explainCode('G', 92, b, Lang::En), explainCode('G', 92, gcode::Dialect::Fanuc, Lang::En));

  // Block by block, run on each machine: the same sentences, the codes in the machine's numbers.
  RunOptions optionsA;
  optionsA.dialect = gcode::Dialect::Fanuc;
  RunOptions optionsB;
  optionsB.dialect = b;
  const std::string textB = gcode::inSystemNumbers(kThreadsInA, b);
  const gcode::Program programA = gcode::parse(kThreadsInA, 1);
  const gcode::Program programB = gcode::parse(textB, 1);
  const Timeline runA = testing::runText(kThreadsInA, optionsA);
  const Timeline runB = testing::runText(textB, optionsB);
  ASSERT_FALSE(runA.alarm.has_value()) << formatMessage(*runA.alarm, Lang::En);
  ASSERT_FALSE(runB.alarm.has_value()) << formatMessage(*runB.alarm, Lang::En);
  ASSERT_EQ(runA.snapshots.size(), runB.snapshots.size());
  ASSERT_EQ(programA.blocks.size(), programB.blocks.size());
  for (std::size_t i = 0; i < runA.snapshots.size(); ++i) {
    const StateSnapshot& a = runA.snapshots[i];
    const StateSnapshot& sb = runB.snapshots[i];
    ASSERT_EQ(a.blockIndex, sb.blockIndex);
    const gcode::Block& blockA = programA.blocks[static_cast<std::size_t>(a.blockIndex)];
    const gcode::Block& blockB = programB.blocks[static_cast<std::size_t>(sb.blockIndex)];
    for (const Lang lang : {Lang::En, Lang::Th})
      EXPECT_EQ(explainBlock(blockB, sb, b, lang),
                gcode::inSystemNumbers(explainBlock(blockA, a, gcode::Dialect::Fanuc, lang), b))
          << "line " << a.line;
  }
  // The thread and its modal continuation, said in full.
  EXPECT_EQ(explainLineText("G33 Z-20. F1.5", 16, nullptr, b, Lang::En),
            "G33 Z-20. F1.5: cut one pass of a thread, the feed locked to the spindle to Z-20, lead 1.5 mm");
  StateSnapshot threading;
  threading.modal.motion = MotionMode::Thread;
  EXPECT_EQ(explainLineText("Z-22.", 17, &threading, b, Lang::En),
            "Z-22.: cut one pass of a thread, the feed locked to the spindle to Z-22");
}

MachineSetup shippedSetup() {
  MachineSetup s;
  s.tools = *io::readToolTable(std::string(KLUENG_SOURCE_DIR) + "/tools.cfg").value;
  s.offsets = *io::readOffsetTable(std::string(KLUENG_SOURCE_DIR) + "/offset.cfg").value;
  return s;
}

ToolInference inferOn(std::string_view text, gcode::Dialect dialect) {
  InferenceContext context;
  context.run.dialect = dialect;
  return inferTools(gcode::parse(text, 1), text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
}

TEST(SystemCodes, G33AndG78InferTheToolsG32AndG92Do) {
  const gcode::Dialect b = romi();
  const ToolInference a = inferOn(kThreadsInA, gcode::Dialect::Fanuc);
  const ToolInference inB = inferOn(gcode::inSystemNumbers(kThreadsInA, b), b);
  // System A, as tool_inference_test asserts it for these habits.
  struct Expected {
    int station;
    const char* id;
    ToolReason reason;
    int line;
    const char* detailA;
    const char* detailB;
  };
  const Expected expected[] = {
      {4, "threading-60", ToolReason::Threading, 16, "G32", "G33"},
      {10, "drill-6mm", ToolReason::Drilling, 6, "G01 X0", "G01 X0"},
      {11, "threading-60-id", ToolReason::ThreadingInside, 10, "G92", "G78"},
  };
  ASSERT_EQ(a.choices.size(), std::size(expected));
  ASSERT_EQ(inB.choices.size(), std::size(expected));
  for (const Expected& e : expected) {
    const ToolChoice* ca = a.choiceFor(e.station);
    const ToolChoice* cb = inB.choiceFor(e.station);
    ASSERT_NE(ca, nullptr) << "T" << e.station;
    ASSERT_NE(cb, nullptr) << "T" << e.station;
    for (const ToolChoice* c : {ca, cb}) {
      EXPECT_EQ(c->libraryId, e.id) << "T" << e.station;
      EXPECT_EQ(c->reason, e.reason) << "T" << e.station;
      EXPECT_EQ(c->line, e.line) << "T" << e.station;
    }
    EXPECT_EQ(ca->detail, e.detailA);
    EXPECT_EQ(cb->detail, e.detailB);
  }
}

}  // namespace
}  // namespace klueng::core::machine::system_codes_test
