// The check's cutting-data warnings (issue 39 item 1): measured on the run the check already
// records (the tool inference's record), they join the job's diagnostics on their blocks, in
// both languages, where klueng-cli check and the editor's diagnostics list show them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "klueng/core/design/part_design.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

namespace klueng::core::job {
namespace {

const machine::LoadedSetup& cutCheckSetup() {
  static const machine::LoadedSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

// The editor's way in: the text in memory. Station 1 is the shipped plain bitmap (offset R0.8),
// given a tool material when `toolMaterial` is set.
std::shared_ptr<const Job> cutCheckJob(const std::string& text, const std::string& toolMaterial = {},
                                       std::vector<cut::FinishMark> marks = {}, bool cuttingData = true) {
  JobInput r;
  r.setup = cutCheckSetup().setup;
  r.stations = r.setup.tools.stations;
  if (!toolMaterial.empty()) r.setup.tools.material[0] = toolMaterial;
  r.file = *io::parseProgramFile(text).value;
  r.folder = std::string();
  r.finishMarks = std::move(marks);
  r.cuttingData = cuttingData;
  return makeJob(std::move(r));
}

std::vector<std::string> cuttingCodesOn(const Job& job, int line) {
  std::vector<std::string> out;
  for (const Diagnostic& d : job.diagnostics())
    if (d.range.line == line && d.code.size() == 4 && d.code.rfind("W33", 0) == 0) out.push_back(d.code);
  return out;
}

std::string cutCheckProgram(const char* speed, const char* feed) {
  return std::string(
             "Cutting data\nShaft\nS45C\n150\n1100\nTest\n"
             "G21 G40 G99\n"  // 7
             "T0101\n"        // 8
             "G97 S") +
         speed +
         " M03\n"          // 9
         "G00 X60. Z2.\n"  // 10
         "X49.4\n"         // 11
         "G01 Z-20. F" +
         feed +
         "\n"          // 12: ap 0.3 mm
         "G00 X60.\n"  // 13
         "M30\n";
}

TEST(CheckCuttingData, AnHssToolTooFastIsWarnedOnItsBlock) {
  // HSS in S45C: 20-35 m/min. At S1000 on Ø49.4: pi * 49.4 * 1000 / 1000 = 155.2 m/min, too fast;
  // the fix is the middle of the range, 27.5 m/min: 27.5 * 1000 / (pi * 49.4) = 177 rpm.
  const auto fast = cutCheckJob(cutCheckProgram("1000", "0.2"), "hss");
  EXPECT_EQ(cuttingCodesOn(*fast, 12), std::vector<std::string>{codes::kCutSpeedHigh});
  const auto w = std::find_if(fast->diagnostics().begin(), fast->diagnostics().end(),
                              [](const Diagnostic& d) { return d.code == codes::kCutSpeedHigh; });
  ASSERT_NE(w, fast->diagnostics().end());
  EXPECT_EQ(w->severity, Severity::Warning);
  EXPECT_FALSE(fast->hasErrors());  // a warning: the real control runs the program
  EXPECT_EQ(formatMessage(*w, Lang::En),
            "cutting speed 155 m/min is above the 35 m/min a HSS tool stands in Carbon steel S45C (C 0.45 %): the "
            "edge burns; lower the spindle speed to about S177 (rpm, G97) or the G96 S value");
  EXPECT_NE(formatMessage(*w, Lang::Th).find("ความเร็วตัด 155 m/min สูงกว่า 35 m/min"), std::string::npos);
  // At S180: 27.9 m/min, inside the range: a sound program says nothing of its cuts.
  const auto sound = cutCheckJob(cutCheckProgram("180", "0.2"), "hss");
  for (const Diagnostic& d : sound->diagnostics()) EXPECT_NE(d.code.rfind("W33", 0), 0u) << d.code;
  // The plain bitmap has no material: its speed is not judged at all.
  EXPECT_TRUE(cuttingCodesOn(*cutCheckJob(cutCheckProgram("1000", "0.2")), 12).empty());
  // Turned off (JobInput::cuttingData), none.
  EXPECT_TRUE(cuttingCodesOn(*cutCheckJob(cutCheckProgram("1000", "0.2"), "hss", {}, false), 12).empty());
}

TEST(CheckCuttingData, TheDesignsMarkJudgesTheFinishingFeedInTheCheck) {
  // F0.25 with R0.8: Ra = 0.0625 / 25.6 * 1000 = 2.44 um: within the default 3.2 ...
  EXPECT_TRUE(cuttingCodesOn(*cutCheckJob(cutCheckProgram("800", "0.25")), 12).empty());
  // ... but not within a design's Ra 1.6 on that diameter.
  design::PartDesign part;
  part.outside.push_back(design::OutsideStep{});
  part.outside[0].diameter = 49.4;
  part.outside[0].length = 30.0;
  part.outside[0].roughness = 1.6;
  const std::vector<cut::FinishMark> marks = design::finishMarks(part);
  ASSERT_EQ(marks.size(), 1u);
  EXPECT_DOUBLE_EQ(marks[0].zLeft, -30.0);
  EXPECT_DOUBLE_EQ(marks[0].dMin, 49.4);
  const auto marked = cutCheckJob(cutCheckProgram("800", "0.25"), {}, marks);
  EXPECT_EQ(cuttingCodesOn(*marked, 12), std::vector<std::string>{codes::kFinishTooRough});
}

TEST(CheckCuttingData, NothingIsMeasuredPastTheFirstAlarm) {
  // Line 12 cuts without a feed (an alarm): the real run stops there, so the too fast HSS cut
  // of line 14 after it is never reached and never warned.
  const auto job = cutCheckJob(
      "Cutting data\nAlarm\nS45C\n150\n1100\nTest\nG21 G40 G99\nT0101\nG97 S1000 M03\nG00 X60. Z2.\nX49.4\n"
      "G01 Z-20.\nG00 X60.\nG01 X49. Z-25. F0.2\nG00 X60.\nM30\n",
      "hss");
  for (const Diagnostic& d : job->diagnostics()) EXPECT_NE(d.code.rfind("W33", 0), 0u) << d.code;
}

// The shipped samples teach G code, not cutting data: none gives a cutting-data warning.
TEST(CheckCuttingData, TheShippedSamplesGiveNoCuttingDataWarning) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(KLUENG_SAMPLES_DIR)) {
    if (entry.path().extension() != ".txt") continue;
    JobInput r;
    r.path = entry.path().string();
    r.setup = cutCheckSetup().setup;
    r.stations = r.setup.tools.stations;
    const auto job = makeJob(std::move(r));
    ++checked;
    for (const Diagnostic& d : job->diagnostics())
      EXPECT_NE(d.code.rfind("W33", 0), 0u) << entry.path().filename() << ": " << formatMessage(d, Lang::En);
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace klueng::core::job
