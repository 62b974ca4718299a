// Tools from the program: programs written in Haas and Fanuc shops' habits,
// each choice and the line of its evidence asserted.
#include "klueng/core/infer/tool_inference.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::machine::tool_inference_test {
namespace {

namespace fs = std::filesystem;
const std::string kTop = KLUENG_SOURCE_DIR;

// The shipped tools.cfg and offset.cfg (stations 1-8: the seed's bitmaps; 9-12 empty).
MachineSetup shippedSetup() {
  MachineSetup s;
  s.tools = *io::readToolTable(kTop + "/tools.cfg").value;
  s.offsets = *io::readOffsetTable(kTop + "/offset.cfg").value;
  return s;
}

ToolInference infer(const std::string& text, const MachineSetup& setup = shippedSetup(),
                    const std::vector<StationOverride>& overrides = {}) {
  const gcode::Program program = gcode::parse(text, 1);
  return inferTools(program, text, 1, setup, io::shippedToolLibrary(), overrides);
}

// The evidence is the program's run on its own control: a Haas program runs as Haas
// (its one-block G71/G76 with D words are not Fanuc's).
ToolInference inferHaas(const std::string& text) {
  const gcode::Program program = gcode::parse(text, 1);
  InferenceContext context;
  context.run.dialect = gcode::Dialect::Haas;
  return inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
}

std::string summary(const ToolInference& r) {
  std::string s;
  for (const Diagnostic& d : r.notes()) s += formatMessage(d, Lang::En) + "\n";
  return s;
}

void expectChoice(const ToolInference& r, int station, const std::string& id, ToolReason reason, int line,
                  const std::string& detail = {}) {
  const ToolChoice* c = r.choiceFor(station);
  ASSERT_NE(c, nullptr) << "T" << station << "\n" << summary(r);
  EXPECT_EQ(c->libraryId, id) << summary(r);
  EXPECT_EQ(c->reason, reason) << summary(r);
  EXPECT_EQ(c->line, line) << summary(r);
  if (!detail.empty()) {
    EXPECT_EQ(c->detail, detail);
  }
  EXPECT_EQ(r.setup.tools.libraryId(station), id);
  EXPECT_TRUE(fs::is_regular_file(r.setup.tools.bitmapPath(station)));
}

// A Haas ST shop program (inch, one-block cycles, N-comment lines, T1212 cut-off).
const char* kHaasShaft =
    "%\n"                                      // 1
    "O20012 (SHAFT 1.5 DIA)\n"                 // 2
    "G20 G40 G80 G99\n"                        // 3
    "N1 (OD ROUGH)\n"                          // 4
    "G28 U0 W0\n"                              // 5
    "T101\n"                                   // 6
    "G50 S3000\n"                              // 7
    "G96 S600 M03\n"                           // 8
    "G00 G54 X1.6 Z0.1 M08\n"                  // 9
    "G71 P10 Q20 U0.02 W0.005 D0.05 F0.012\n"  // 10
    "N10 G00 X0.8\n"                           // 11
    "G01 Z-1.\n"                               // 12
    "X1.2 Z-1.5\n"                             // 13
    "N20 X1.6\n"                               // 14
    "G00 G53 X0\n"                             // 15
    "M01\n"                                    // 16
    "N3 (THREAD 3/4-12)\n"                     // 17
    "T909\n"                                   // 18
    "G97 S800 M03\n"                           // 19
    "G00 X1.0 Z0.2\n"                          // 20
    "G76 X0.7 Z-0.9 K0.0613 D0.01 F0.0833\n"   // 21
    "G00 G53 X0\n"                             // 22
    "M01\n"                                    // 23
    "N12 (CUT OFF)\n"                          // 24
    "T1212\n"                                  // 25
    "G97 S600 M03\n"                           // 26
    "G00 X1.7 Z-2.2\n"                         // 27
    "G01 X-0.02 F0.003\n"                      // 28
    "G00 X1.7\n"                               // 29
    "G28 U0 W0\n"                              // 30
    "M30\n"                                    // 31
    "%\n";

TEST(ToolInference, HaasShaftNamesItsToolsInNLineComments) {
  const ToolInference r = inferHaas(kHaasShaft);
  // T1 has the seed's outside turning tool: it fits "OD ROUGH" and stays.
  EXPECT_EQ(r.choiceFor(1), nullptr) << summary(r);
  EXPECT_EQ(r.setup.tools.bitmap[0], "resources/tools/01-outside-turning.bmp");
  expectChoice(r, 9, "threading-60", ToolReason::Comment, 17, "THREAD 3/4-12");
  expectChoice(r, 12, "parting-3mm", ToolReason::Comment, 24, "CUT OFF");
  EXPECT_EQ(r.choices.size(), 2u) << summary(r);
  // Their empty offset rows get the library tools' nose radius and tip.
  EXPECT_EQ(r.setup.offsets.at(9).tip, 8);
  EXPECT_EQ(r.setup.offsets.at(12).tip, 3);
  EXPECT_EQ(r.setup.offsets.at(12).r, 0.0);
  ASSERT_EQ(r.offsetNotes.size(), 2u);
  EXPECT_EQ(r.offsetNotes[1].code, "I410");
  const Diagnostic note = r.choiceFor(12)->note();
  EXPECT_EQ(note.code, "I401");
  EXPECT_EQ(formatMessage(note, Lang::En), "T12 = parting-3mm (comment \"CUT OFF\" on line 24)");
  EXPECT_EQ(formatMessage(note, Lang::Th), "T12 = parting-3mm (หมายเหตุ \"CUT OFF\" ในบรรทัดที่ 24)");
}

TEST(ToolInference, WithoutCommentsTheCyclesTell) {
  std::string text = kHaasShaft;
  for (const char* c : {"N3 (THREAD 3/4-12)\n", "N12 (CUT OFF)\n"})
    text.replace(text.find(c), std::string(c).size(), "\n");
  const ToolInference r = inferHaas(text);
  expectChoice(r, 9, "threading-60", ToolReason::Threading, 21, "G76");
  expectChoice(r, 12, "parting-3mm", ToolReason::Parting, 28, "X-0.02");
}

// A Fanuc 0i shop program in mm: two-block cycles, Thai comments, tube work.
const char* kFanucFlange =
    "O0100 (FLANGE)\n"                    // 1
    "N1 G21 G40 G99\n"                    // 2
    "N10 T0101 (กลึงปอก หยาบ)\n"           // 3
    "G50 S2000\n"                         // 4
    "G96 S180 M03\n"                      // 5
    "G00 X82. Z2.\n"                      // 6
    "G71 U2. R0.5\n"                      // 7
    "G71 P100 Q200 U0.4 W0.1 F0.25\n"     // 8
    "N100 G00 X60.\n"                     // 9
    "G01 Z-30.\n"                         // 10
    "N200 X82.\n"                         // 11
    "G28 U0.\n"                           // 12
    "(เจาะนำศูนย์)\n"                       // 13
    "N20 T0505\n"                         // 14
    "G97 S1200 M03\n"                     // 15
    "G00 X0 Z5.\n"                        // 16
    "G01 Z-4. F0.08\n"                    // 17
    "G00 Z5.\n"                           // 18
    "N30 T1010 (ดอกสว่าน 16 มม.)\n"        // 19
    "G00 X0 Z5.\n"                        // 20
    "G74 R1.\n"                           // 21
    "G74 Z-40. Q5000 F0.1\n"              // 22
    "N40 T1111\n"                         // 23
    "G00 X14. Z2.\n"                      // 24
    "G71 U1. R0.5\n"                      // 25
    "G71 P300 Q400 U-0.3 W0.1 F0.15\n"    // 26
    "N300 G00 X30.\n"                     // 27
    "G01 Z-20.\n"                         // 28
    "N400 X16.\n"                         // 29
    "N50 T0909\n"                         // 30
    "G00 X84. Z-12.\n"                    // 31
    "G75 R0.5\n"                          // 32
    "G75 X70. Z-15. P1000 Q2500 F0.05\n"  // 33
    "N60 T0808 (ID THREAD M36x1.5)\n"     // 34
    "G00 X32. Z5.\n"                      // 35
    "G76 P010060 Q50 R0.05\n"             // 36
    "G76 X36. Z-15. P920 Q300 F1.5\n"     // 37
    "N70 T0707\n"                         // 38
    "G00 X84. Z-48.\n"                    // 39
    "G01 X-1. F0.05\n"                    // 40
    "G00 X84.\n"                          // 41
    "M30\n";                              // 42

TEST(ToolInference, FanucFlangeThaiCommentsAndCycles) {
  const ToolInference r = infer(kFanucFlange);
  EXPECT_EQ(r.choiceFor(1), nullptr) << summary(r);  // turning tool for กลึงปอก: kept
  // Station 5 holds the seed's boring bar, but the program centre-drills with it.
  expectChoice(r, 5, "centre-drill", ToolReason::Comment, 13, "เจาะนำศูนย์");
  expectChoice(r, 10, "drill-16mm", ToolReason::Comment, 19, "ดอกสว่าน 16 มม.");
  expectChoice(r, 11, "boring-bar-16", ToolReason::Boring, 26, "G71 U-0.3");
  expectChoice(r, 9, "grooving-3mm", ToolReason::Grooving, 33, "G75");
  EXPECT_EQ(r.choiceFor(8), nullptr) << summary(r);  // the seed's inside threading tool fits
  EXPECT_EQ(r.choiceFor(7), nullptr) << summary(r);  // the seed's parting tool fits
  EXPECT_EQ(r.choices.size(), 4u) << summary(r);
  // Offset 05 is the shipped R0.4 tip 2 row: not empty, so kept.
  EXPECT_EQ(r.setup.offsets.at(5).tip, 2);
  EXPECT_EQ(r.setup.offsets.at(11).tip, 2);  // empty row 11: the boring bar's tip
  EXPECT_EQ(r.setup.offsets.at(11).r, 0.4);
}

TEST(ToolInference, InternalThreadingAndDrillingWithoutComments) {
  const std::string text =
      "G21 G99\n"               // 1
      "T1010\n"                 // 2
      "G00 X0 Z3.\n"            // 3
      "G01 Z-25. F0.1\n"        // 4
      "G00 Z3.\n"               // 5
      "T1111\n"                 // 6
      "G00 X18. Z5.\n"          // 7
      "G92 X20.2 Z-15. F1.5\n"  // 8
      "X20.6\n"                 // 9
      "G00 X18. Z5.\n"          // 10
      "M30\n";
  const ToolInference r = infer(text);
  expectChoice(r, 10, "drill-6mm", ToolReason::Drilling, 4, "G01 X0");
  expectChoice(r, 11, "threading-60-id", ToolReason::ThreadingInside, 8, "G92");
}

TEST(ToolInference, AWrongKindIsReplacedOnlyOnStrongEvidence) {
  // Station 4 holds the seed's grooving tool; threading with it is clearly wrong.
  const std::string text = "T0404\nG97 S500 M03\nG00 X32. Z5.\nG92 X29.2 Z-20. F1.5\nM30\n";
  const ToolInference r = infer(text);
  expectChoice(r, 4, "threading-60", ToolReason::Threading, 4, "G92");
  // Plain turning with the boring bar (weak evidence): the user's choice stands.
  const ToolInference kept = infer("T0505\nG00 X40. Z2.\nG01 Z-10. F0.2\nM30\n");
  EXPECT_TRUE(kept.choices.empty()) << summary(kept);
  // A station with no tool gets the everyday turning tool for any cutting.
  const ToolInference filled = infer("T1010\nG00 X40. Z2.\nG01 Z-10. F0.2\nM30\n");
  expectChoice(filled, 10, "cnmg-80-r08", ToolReason::Turning, 3, "G01");
}

TEST(ToolInference, AnOverrideIsNeverReplaced) {
  const ToolInference r = infer(kHaasShaft, shippedSetup(), {{12, "grooving-3mm"}, {3, "threading-60"}});
  expectChoice(r, 12, "grooving-3mm", ToolReason::Override, 0);
  expectChoice(r, 3, "threading-60", ToolReason::Override, 0);
  EXPECT_EQ(formatMessage(r.choiceFor(12)->note(), Lang::En), "T12 = grooving-3mm (set for this job)");
}

TEST(ToolInference, FinishAndInsertNamesPickTheInsert) {
  MachineSetup empty = shippedSetup();
  for (auto& b : empty.tools.bitmap) b.clear();
  const ToolInference r = infer(
      "T0101 (OD FINISH)\nG00 X40. Z2.\nG01 Z-10. F0.1\n(PROFILE VNMG)\nT0202\nG00 X40. Z2.\nG01 Z-10. F0.1\n"
      "T0303 (FACE + ROUGH)\nG00 X40. Z2.\nG01 Z-10. F0.1\nM30\n",
      empty);
  expectChoice(r, 1, "cnmg-80-r04", ToolReason::Comment, 1, "OD FINISH");
  expectChoice(r, 2, "vnmg-35-r02", ToolReason::Comment, 4, "PROFILE VNMG");
  expectChoice(r, 3, "cnmg-80-r08", ToolReason::Comment, 8);
}

TEST(ToolInference, AToolListOnOneLineGivesEachStationItsOwnWords) {
  MachineSetup empty = shippedSetup();
  for (auto& b : empty.tools.bitmap) b.clear();
  const std::string text =
      "O01234 (BOLT)\n"                         // 1
      "(T1 OD TURN, T3 THREAD, T12 CUT OFF)\n"  // 2
      "G20 G99\n"                               // 3
      "T101\n"                                  // 4
      "G00 X1.1 Z0.1\n"                         // 5
      "G01 Z-1. F0.01\n"                        // 6
      "G00 X2. (ROUGH TO T3 SIZE)\n"            // 7
      "T303\n"                                  // 8
      "G00 X1.1 Z0.2\n"                         // 9
      "T1212\n"                                 // 10
      "G00 X1.1 Z-1.5\n"                        // 11
      "M30\n";
  const ToolInference r = infer(text, empty);
  expectChoice(r, 1, "cnmg-80-r08", ToolReason::Comment, 2, "T1 OD TURN");
  expectChoice(r, 3, "threading-60", ToolReason::Comment, 2, "T3 THREAD");
  expectChoice(r, 12, "parting-3mm", ToolReason::Comment, 2, "T12 CUT OFF");
  // A T block's own comment naming only its station is read whole.
  const ToolInference own = infer("T0303 (THREAD OD T0303)\nG00 X30. Z2.\nM30\n", empty);
  expectChoice(own, 3, "threading-60", ToolReason::Comment, 1, "THREAD OD T0303");
}

// Drill sizes as shops write them (issue 26 item 3): inch fractions and inch
// marks, "PHI", a bare ".5 DIA" in an inch program's own units.
TEST(ToolInference, DrillSizesInInchesFractionsAndPhi) {
  const std::string inch =
      "%\nO1230 (PLUG)\nG20 G99\nT0909 (1/2 DRILL)\nG97 S800 M03\nG00 X0. Z0.1\nG83 Z-1. R0.1 Q0.2 F0.004\nG80\n"
      "T1010 (1\" INSERT DRILL)\nG00 X0. Z0.1\nG01 Z-1.2 F0.003\nG00 Z1.\n"
      "T1111 (DRILL .5 DIA)\nG00 X0. Z0.1\nG01 Z-0.8 F0.003\nG00 Z1.\nM30\n%\n";
  const ToolInference r = infer(inch);
  expectChoice(r, 9, "drill-12.7mm", ToolReason::Comment, 4, "1/2 DRILL");
  expectChoice(r, 10, "drill-25.4mm", ToolReason::Comment, 9, "1\" INSERT DRILL");
  expectChoice(r, 11, "drill-12.7mm", ToolReason::Comment, 13, "DRILL .5 DIA");
  const std::string metric =
      "%\nO0050\n(PHASE 50 : PERCAGE PHI22)\nT0909\nG97 S434 M03\nG00 X0. Z2.\n"
      "G83 Z-54. Q4. R2. F0.18\nG80\nM30\n%\n";
  expectChoice(infer(metric), 9, "drill-22mm", ToolReason::Comment, 3, "PHASE 50 : PERCAGE PHI22");
  // A bare number after the drill's word is its size in the program's units.
  const std::string bare =
      "%\nO0400\nG21 G99\nT0505 (DRILL 10)\nG97 S800 M03\nG00 X0 Z5.\nG74 R1.\nG74 Z-30. Q5000 F0.1\nG00 Z10.\n"
      "T1010 (SVERLO 8.0)\nG00 X0 Z2.\nG01 Z-12. F0.05\nG00 Z5.\nM30\n%\n";
  const ToolInference b = infer(bare);
  expectChoice(b, 5, "drill-10mm", ToolReason::Comment, 4, "DRILL 10");
  expectChoice(b, 10, "drill-8mm", ToolReason::Comment, 10, "SVERLO 8.0");
  const std::string inchBare =
      "%\nO1234\nG20 G99\nT0909 (DRILL .5)\nG97 S800 M03\nG00 X0. Z0.1\n"
      "G01 Z-0.8 F0.003\nG00 Z1.\nM30\n%\n";
  expectChoice(infer(inchBare), 9, "drill-12.7mm", ToolReason::Comment, 4, "DRILL .5");
}

// A plain program (no job header): every station from the program's evidence,
// the shipped table only breaking ties (issue 26 item 1), with the motion of
// one recorded run: feeding toward the tailstock keeps the table's left-hand
// tool; T2 feeding toward the chuck gets a right-hand one; a tool that leaves
// its Z feeds inward is a boring bar.
ToolInference inferPlain(const std::string& text) {
  const gcode::Program program = gcode::parse(text, 1);
  InferenceContext context;
  context.fromProgram = true;
  return inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
}

TEST(ToolInference, APlainProgramsMotionDecidesTheHand) {
  const std::string toChuck = "G21 G99\nT0202\nG97 S800 M03\nG00 X42. Z2.\nG01 Z-40. F0.2\nX46.\nG00 Z2.\nM30\n";
  const ToolInference r = inferPlain(toChuck);
  expectChoice(r, 2, "cnmg-80-r08", ToolReason::Turning, 5, "G01");
  EXPECT_TRUE(r.setup.tools.isGuess(2));
  EXPECT_EQ(r.setup.offsets.at(2).tip, 3);  // the library tool's tip, not row 02's tip 4
  EXPECT_DOUBLE_EQ(r.setup.offsets.at(2).r, 0.8);
  // Toward the tailstock: the table's left-hand tool fits and stays (no library tool is left-handed).
  const std::string toTail = "G21 G99\nT0202\nG97 S800 M03\nG00 X42. Z-40.\nG01 Z2. F0.2\nX46.\nM30\n";
  const ToolInference l = inferPlain(toTail);
  EXPECT_EQ(l.choiceFor(2), nullptr) << summary(l);
  EXPECT_EQ(l.setup.tools.bitmap[1], shippedSetup().tools.bitmap[1]);
  EXPECT_EQ(l.setup.offsets.at(2).tip, 4);
  // Without the plain-program context (a file with Klueng's header) nothing changes.
  EXPECT_EQ(infer(toChuck).choiceFor(2), nullptr);
}

TEST(ToolInference, APlainProgramsInwardRetractsAreBoring) {
  const std::string text =
      "G21 G99\nT0101\nG96 S150 M03\nG00 X44. Z2.\nG01 Z-20. F0.15\nX43.\nG00 Z2.\n"
      "X48.\nG01 Z-20.\nX47.\nG00 Z50.\nM30\n";
  const ToolInference r = inferPlain(text);
  expectChoice(r, 1, "boring-bar-16", ToolReason::Boring, 5, "G01 Z-20. F0.15");
  EXPECT_EQ(r.setup.offsets.at(1).tip, 2);
}

// The run sees what a scan of the text cannot: positions from macro variables
// and a subprogram. T05 threads through #101 in O2000; T09 (no tool in the
// table) drills on X#102 = 0.
TEST(ToolInference, APlainProgramsRunSeesThroughMacrosAndSubprograms) {
  const std::string text =
      "O1000\nG21 G99\n#101 = 28.2\n#102 = 0\n"
      "T0505\nG97 S600 M03\nG00 X35. Z5.\nM98 P2000\n"
      "T0909\nG97 S800 M03\nG00 X#102 Z2.\nG01 Z-25. F0.1\nG00 Z5.\nM30\n"
      "O2000\nG00 X#101\nG32 Z-20. F1.5\nG00 X35.\nZ5.\nM99\n";
  const ToolInference r = inferPlain(text);
  expectChoice(r, 5, "threading-60", ToolReason::Threading, 17, "G32");
  expectChoice(r, 9, "drill-6mm", ToolReason::Drilling, 12, "G01 X0");
}

// "ID" in the comment of the thread itself (issue 26 item 3): an inside tool,
// even when the approach does not show it (the tool comes in at the thread's X).
TEST(ToolInference, IdInTheThreadsOwnCommentIsAnInsideTool) {
  const std::string text =
      "%\nO0123\nG21 G99\nT1010\nG97 S500 M03\nG00 X36. Z5.\n"
      "G76 P010060 Q50 R0.05\nG76 X36. Z-20. P1000 Q300 F2. (M36X2 ID THREAD)\nG00 Z50.\nM30\n%\n";
  expectChoice(infer(text), 10, "threading-60-id", ToolReason::ThreadingInside, 8, "G76");
}

// Tools named in the shop's own language (issue 26: programs come from shops in
// many countries). A Spanish tool list and a Polish one: parting (TRONZADO,
// ODCINANIA), grooving (RANURADO, ROWKOW), threading (ROSCA, GWINT), drills
// with Ø written "FI" (WIERTLO FI12), boring bars (MANDRINADO, WYTACZAK) and an
// inside thread (ROSCA INTERIOR, WEWN.).
TEST(ToolInference, ToolsNamedInTheShopsOwnLanguage) {
  const std::string spanish =
      "%\nO0410 (CASQUILLO)\nG21 G99\n"
      "T0303 (HERRAMIENTA DE RANURADO 3MM)\nG00 X44. Z-20.\nG75 R0.5\nG75 X34. Z-22. P1000 Q2000 F0.05\n"
      "T0404 (ROSCA EXTERIOR 60 GRADOS)\nG00 X42. Z5.\nG76 P010060 Q50 R0.05\nG76 X37.4 Z-15. P1300 Q300 F2.\n"
      "T0505 (BROCA 18MM)\nG00 X0. Z2.\nG74 R0.5\nG74 Z-30. Q5000 F0.1\n"
      "T0606 (BARRA DE MANDRINADO)\nG00 X16. Z2.\nG01 Z-20. F0.1\nX15.\nG00 Z5.\n"
      "T0707 (ROSCA INTERIOR M24X1.5)\nG00 X20. Z5.\nG76 P010060 Q50 R0.05\nG76 X24. Z-12. P812 Q250 F1.5\n"
      "T1212 (TRONZADO 3MM)\nG00 X44. Z-45.\nG01 X-0.5 F0.04\nM30\n%\n";
  const ToolInference es = infer(spanish);
  expectChoice(es, 3, "grooving-3mm", ToolReason::Comment, 4, "HERRAMIENTA DE RANURADO 3MM");
  expectChoice(es, 5, "drill-18mm", ToolReason::Comment, 12, "BROCA 18MM");
  expectChoice(es, 6, "boring-bar-16", ToolReason::Comment, 16, "BARRA DE MANDRINADO");
  expectChoice(es, 7, "threading-60-id", ToolReason::Comment, 21, "ROSCA INTERIOR M24X1.5");
  expectChoice(es, 12, "parting-3mm", ToolReason::Comment, 25, "TRONZADO 3MM");
  expectChoice(es, 4, "threading-60", ToolReason::Comment, 8, "ROSCA EXTERIOR 60 GRADOS");  // the table's T04 grooves

  const std::string polish =
      "O2210 (TULEJA)\nG21 G99\n"
      "T0909 (WIERTLO FI12)\nG00 X0. Z2.\nG74 R0.5\nG74 Z-25. Q4000 F0.1\n"
      "T1010 (NOZ DO ROWKOW 2MM)\nG00 X36. Z-10.\nG75 R0.5\nG75 X30. Z-10. P1000 F0.05\n"
      "T1111 (NOZ DO GWINTOW WEWN. 60ST)\nG00 X14. Z5.\nG76 P010060 Q50 R0.05\nG76 X16. Z-10. P812 Q250 F1.5\n"
      "T1212 (NOZ DO ODCINANIA 3MM)\nG00 X36. Z-30.\nG01 X10. F0.04\nM30\n";
  const ToolInference pl = infer(polish);
  expectChoice(pl, 9, "drill-12mm", ToolReason::Comment, 3, "WIERTLO FI12");
  expectChoice(pl, 10, "grooving-3mm", ToolReason::Comment, 7, "NOZ DO ROWKOW 2MM");
  expectChoice(pl, 11, "threading-60-id", ToolReason::Comment, 11, "NOZ DO GWINTOW WEWN. 60ST");
  expectChoice(pl, 12, "parting-3mm", ToolReason::Comment, 15, "NOZ DO ODCINANIA 3MM");
}

// A plain program's station that only plunges straight in behind the face, with
// no word on what it is, is a blade (issue 26 item 1: "a plunge no wider than a
// blade is grooving or parting"): shallow, a grooving blade; a cut-off into a
// bore, a parting blade. Facing to the centre at the face is not a plunge.
TEST(ToolInference, APlainProgramsStraightPlungesAreABlade) {
  const std::string text =
      "G21 G99\nT0909\nG97 S600 M03\nG00 X42. Z-12.\nG01 X36. F0.05\nG00 X42.\n"
      "T1010\nG00 X42. Z-33.\nG01 X18. F0.04\nG00 X44.\n"
      "T1111\nG00 X44. Z0.\nG01 X-1.6 F0.15\nG00 Z2.\nM30\n";
  const ToolInference r = inferPlain(text);
  expectChoice(r, 9, "grooving-3mm", ToolReason::Grooving, 5, "G01 X36. F0.05");
  expectChoice(r, 10, "parting-3mm", ToolReason::Parting, 9, "G01 X18. F0.04");
  EXPECT_NE(r.choiceFor(11), nullptr);
  EXPECT_EQ(r.choiceFor(11)->reason, ToolReason::Turning) << summary(r);
}

// A G72 face profile finished by a tool the comment names by its insert: the
// finishing pass runs up the hub toward the tailstock, which is the profile's
// way, not a left-hand tool's; the named VBMT is taken (a right-hand holder).
TEST(ToolInference, ANamedInsertIsNotTakenForALeftHandTool) {
  const std::string text =
      "G21 G99\nT0101 (OD CNMG 120408)\nG96 S180 M03\nG00 X64. Z2.\n"
      "G72 W2. R0.5\nG72 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 Z-15.\nG01 X30. F0.1\nZ-1.\n"
      "N20 X28. Z0.\nG28 U0. W0.\nT0202 (FINISH VBMT 160404)\nG96 S220 M03\nG00 X64. Z2.\n"
      "G70 P10 Q20\nG28 U0. W0.\nM30\n";
  const ToolInference r = inferPlain(text);
  expectChoice(r, 2, "vnmg-35-r02", ToolReason::Comment, 12, "FINISH VBMT 160404");
  // T01's G72 passes and its own finishing run up the hub too: still an outside tool, never a bar.
  const ToolChoice* t1 = r.choiceFor(1);
  if (t1) {
    EXPECT_NE(t1->libraryId.find("cnmg"), std::string::npos) << summary(r);
  }
}

// The tool side (issue 26 item 5): a plain program that faces and turns at
// X < 0 has its tools beyond the centre line (I412); the user's choice for the
// file (Job details) wins either way, and a file with a header follows it too.
TEST(ToolInference, TheToolSideIsTheRunsUnlessTheUserChoseIt) {
  const std::string text =
      "G21 G99\nT0101\nG97 S800 M03\nG00 X-32. Z0.\nG01 X1.6 F0.15\nG00 Z2.\n"
      "X-28.\nG01 Z-30. F0.2\nX-32.\nG00 Z2.\nM30\n";
  const gcode::Program program = gcode::parse(text, 1);
  InferenceContext context;
  context.fromProgram = true;
  const ToolInference seen = inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
  EXPECT_TRUE(seen.setup.machine.toolsBeyondCentre);
  EXPECT_NE(summary(seen).find("the program cuts at X < 0 (from line 5)"), std::string::npos) << summary(seen);

  context.toolsBeyondCentre = false;
  const ToolInference front = inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
  EXPECT_FALSE(front.setup.machine.toolsBeyondCentre);
  EXPECT_EQ(summary(front).find("X < 0"), std::string::npos) << summary(front);

  InferenceContext header;  // a file with Klueng's header: no run, the choice still holds
  header.toolsBeyondCentre = true;
  EXPECT_TRUE(inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, header)
                  .setup.machine.toolsBeyondCentre);
  // A machine set to rear tools (machine.cfg tools_beyond_centre = 1) and a program that works in front:
  // the plain program's moves decide.
  MachineSetup rear = shippedSetup();
  rear.machine.toolsBeyondCentre = true;
  const std::string inFront = "G21 G99\nT0101\nG97 S800 M03\nG00 X42. Z2.\nG01 Z-30. F0.2\nX46.\nG00 Z2.\nM30\n";
  const gcode::Program p2 = gcode::parse(inFront, 1);
  InferenceContext plain;
  plain.fromProgram = true;
  EXPECT_FALSE(
      inferTools(p2, inFront, 1, rear, io::shippedToolLibrary(), {}, 0, plain).setup.machine.toolsBeyondCentre);
}

// One recorded run is the evidence (issue 26 item 2): a station chosen by a macro
// variable (T#1, which no reading of the text can resolve) and a tool selected in a
// subprogram get their tools from the cycles they really run, in a plain program
// and in a file with Klueng's header alike.
TEST(ToolInference, TheRunSeesToolsChosenByVariablesAndInSubprograms) {
  const std::string text =
      "O1000 (BUSHING)\n"                   // 1
      "G21 G99\n"                           // 2
      "#1 = 909\n"                          // 3
      "T#1\n"                               // 4
      "G97 S600 M03\n"                      // 5
      "G00 X30. Z5.\n"                      // 6
      "G76 P010060 Q50 R0.05\n"             // 7
      "G76 X27.4 Z-20. P1300 Q400 F2.\n"    // 8
      "G00 X60. Z50.\n"                     // 9
      "M98 P3000\n"                         // 10
      "M30\n"                               // 11
      "O3000\n"                             // 12
      "T1010\n"                             // 13
      "G97 S500 M03\n"                      // 14
      "G00 X52. Z-15.\n"                    // 15
      "G75 R0.5\n"                          // 16
      "G75 X40. Z-18. P1000 Q2500 F0.05\n"  // 17
      "G00 X60.\n"                          // 18
      "M99\n";                              // 19
  for (const bool plain : {true, false}) {
    const gcode::Program program = gcode::parse(text, 1);
    InferenceContext context;
    context.fromProgram = plain;
    const ToolInference r = inferTools(program, text, 1, shippedSetup(), io::shippedToolLibrary(), {}, 0, context);
    expectChoice(r, 9, "threading-60", ToolReason::Threading, 8, "G76");
    expectChoice(r, 10, "grooving-3mm", ToolReason::Grooving, 17, "G75");
    ASSERT_NE(r.record, nullptr);
    EXPECT_FALSE(r.record->alarm.has_value());
  }
}

// An alarm does not hide the tools after it: the record goes on past a cut made
// before the spindle runs (A104, the run's own alarm, kept first), so T10's drilling
// and T09's G92 thread are still seen from their moves.
TEST(ToolInference, AnAlarmInTheRecordDoesNotHideTheToolsAfterIt) {
  const std::string text =
      "G21 G99\n"               // 1
      "T0101\n"                 // 2
      "G00 X42. Z2.\n"          // 3
      "G01 Z-30. F0.2\n"        // 4  (no M03 yet: A104)
      "G00 X50. Z50.\n"         // 5
      "T1010\n"                 // 6
      "G97 S900 M03\n"          // 7
      "G00 X0 Z3.\n"            // 8
      "G74 R1.\n"               // 9
      "G74 Z-30. Q4000 F0.1\n"  // 10
      "G00 Z50.\n"              // 11
      "T0909\n"                 // 12
      "G00 X45. Z5.\n"          // 13
      "G92 X41.2 Z-18. F1.5\n"  // 14
      "X40.4\n"                 // 15
      "G00 X50. Z50.\n"         // 16
      "M30\n";
  const ToolInference r = inferPlain(text);
  expectChoice(r, 10, "drill-6mm", ToolReason::Drilling, 10, "G74");
  expectChoice(r, 9, "threading-60", ToolReason::Threading, 14, "G92");
  ASSERT_NE(r.record, nullptr);
  ASSERT_TRUE(r.record->alarm.has_value());
  EXPECT_EQ(r.record->alarm->code, "A104");
  EXPECT_EQ(r.record->alarm->range.line, 4);
}

// Facing in steps (a short feed along -Z, then across to the centre line) is
// not a bore's wall: the tool stays a turning tool, in front of the centre or
// beyond it.
TEST(ToolInference, FacingInStepsToTheCentreIsNotBoring) {
  for (const char* side : {"", "-"}) {
    const std::string x = std::string(side) + "30.5";
    const std::string text = "G21 G98\nT0101\nG97 S600 M03\nG00 X" + x + " Z0\nG01 Z-1. F60\nX0\nG00 Z3.\nX" + x +
                             "\nG01 Z-2.\nX0\nG00 Z3.\nM30\n";
    const ToolInference r = inferPlain(text);
    EXPECT_EQ(r.choiceFor(1), nullptr) << side << "\n" << summary(r);
  }
}

// A Haas program in inch by power-on (no G20 anywhere): the drill size its comment
// writes, ".5 DIA", is read in the run's units, half an inch.
TEST(ToolInference, ADrillSizeIsReadInThePowerOnUnits) {
  const std::string text =
      "O2001\nT0505 (.5 DIA DRILL)\nG97 S1000 M03\nG00 X0 Z0.1\nG01 Z-1. F0.004\n"
      "G00 Z1.\nM30\n";
  const ToolInference r = inferHaas(text);
  expectChoice(r, 5, "drill-12.7mm", ToolReason::Comment, 2, ".5 DIA DRILL");
}

TEST(StationOverride, ParsesNEqualsId) {
  const io::ToolLibrary& lib = io::shippedToolLibrary();
  StationOverride o;
  std::string error;
  ASSERT_TRUE(parseStationOverride("12=parting-3mm", 12, lib, o, error)) << error;
  EXPECT_EQ(o.station, 12);
  EXPECT_EQ(o.libraryId, "parting-3mm");
  EXPECT_FALSE(parseStationOverride("13=parting-3mm", 12, lib, o, error));
  EXPECT_NE(error.find("1 to 12"), std::string::npos) << error;
  EXPECT_FALSE(parseStationOverride("3=knurl", 12, lib, o, error));
  EXPECT_NE(error.find("threading-60"), std::string::npos) << error;
  EXPECT_FALSE(parseStationOverride("threading-60", 12, lib, o, error));
  EXPECT_FALSE(parseStationOverride("0=threading-60", 12, lib, o, error));
}

// The shipped samples and golden programs keep their tools exactly.
TEST(ToolInference, ShippedSamplesAndGoldenProgramsAreUnchanged) {
  std::vector<fs::path> files;
  for (const std::string& dir : {kTop + "/resources/samples", std::string(KLUENG_SAMPLES_DIR)})
    if (fs::is_directory(dir))
      for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
  for (const auto& e : fs::recursive_directory_iterator(kTop + "/tests/golden"))
    if (e.path().filename() == "program.nc") files.push_back(e.path());
  ASSERT_GT(files.size(), 20u);
  const MachineSetup setup = shippedSetup();
  for (const fs::path& f : files) {
    const auto file = io::readProgramFile(f.string());
    if (!file.value) continue;
    const gcode::Program program = gcode::parse(file.value->gcode, file.value->gcodeFirstLine);
    // 04-grammar-errors.txt is meant for the classic dialect: stations 01-08 (its T0917 is E118).
    const int stations = f.filename() == "04-grammar-errors.txt" ? 8 : 0;
    const ToolInference r = inferTools(program, file.value->gcode, file.value->gcodeFirstLine, setup,
                                       io::shippedToolLibrary(), {}, stations);
    EXPECT_TRUE(r.choices.empty()) << f << "\n" << summary(r);
    EXPECT_EQ(r.setup.tools.bitmap, setup.tools.bitmap) << f;
  }
}

}  // namespace
}  // namespace klueng::core::machine::tool_inference_test
