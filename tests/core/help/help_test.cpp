// Help that teaches (issue 11): every code's worked example runs clean through
// the simulator — check, run and cut on a Ø50 x 100 bar with the shipped
// setup — and the search finds codes from the words students use.
#include <string>
#include "klueng/core/help/help.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/gcode/machine_file.h"
#include "klueng/core/help/explain.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/job/job.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"
#include "../../scratch_folders.h"

namespace klueng::core::machine {
namespace {

namespace fs = std::filesystem;

const LoadedSetup& shipped() {
  static const LoadedSetup setup = loadMachineSetup(KLUENG_SOURCE_DIR);
  return setup;
}

std::string codeName(char letter, int number) {
  return std::string(1, letter) + (number < 10 ? "0" : "") + std::to_string(number);
}

// Runs one worked example as a student would: the file, the check, the run, the cut.
std::string problems(const std::string& gcode, gcode::Dialect dialect,
                     const std::vector<std::pair<std::string, std::string>>& files) {
  // One folder per process: test runs of other builds on the same machine write theirs at once.
  const fs::path dir = fs::temp_directory_path() / ("klueng-help-examples-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& [name, text] : files) std::ofstream(dir / name, std::ios::binary) << text;
  const fs::path path = dir / "example.nc";
  std::ofstream(path, std::ios::binary) << "Worked example\nHelp\nAluminium\n150\n1100\nKlueng help\n" << gcode;
  job::JobInput request;
  request.path = path.string();
  request.setup = shipped().setup;
  request.run.dialect = dialect;
  request.stations = shipped().setup.tools.stations;
  const std::shared_ptr<const job::Job> made = job::makeJob(request);
  const job::Job& job = *made;
  std::string out;
  for (const Diagnostic& d : job.diagnostics())
    if (isError(d.severity) || d.severity == Severity::Warning)
      out += "check " + formatWithPlace("example", d, Lang::En) + "\n";
  if (!job.file() || !job.program() || job.hasErrors()) return out + "does not load\n";
  const Timeline& t = *job.timeline();
  if (t.alarm) return out + "run " + formatWithPlace("example", *t.alarm, Lang::En) + "\n";
  cut::CutSimulator sim(t, cut::CutSetup::from(job.file()->header, job.setup()));
  sim.runToEnd();
  if (sim.alarm()) out += "cut " + formatWithPlace("example", *sim.alarm(), Lang::En) + "\n";
  if (t.cycleTime() <= 0.0) out += "nothing moves\n";
  return out;
}

TEST(Help, EveryCodeHasAWorkedExampleThatRunsClean) {
  int examples = 0;
  for (const gcode::CodeInfo& row : gcode::codeTable())
    for (gcode::Dialect d : {gcode::Dialect::Fanuc, gcode::Dialect::Haas, gcode::Dialect::Classic}) {
      if (!row.in(d)) continue;
      const std::string text = workedExample(row.letter, row.number, d);
      const std::string name = codeName(row.letter, row.number);
      ASSERT_FALSE(text.empty()) << name;
      EXPECT_NE(text.find(name), std::string::npos) << name << " is not in its own example:\n" << text;
      const std::string found = problems(text, d, workedExampleFiles(row.letter, row.number, d));
      if (row.action == gcode::CodeAction::NotSimulated) {
        // A code Klueng does not simulate: the check says so, and the run stops at it.
        EXPECT_NE(found.find("warning W119: " + name), std::string::npos) << found;
        EXPECT_NE(found.find("alarm A117: " + name), std::string::npos) << found;
      } else {
        EXPECT_EQ(found, "") << name << " in " << gcode::dialectName(d) << ":\n" << text;
      }
      ++examples;
    }
  EXPECT_GT(examples, 150);
  EXPECT_TRUE(workedExample('G', 999, gcode::Dialect::Fanuc).empty());
}

TEST(Help, TheG71PictureIsTheExamplesRealPath) {
  std::vector<bool> rapid;
  const std::vector<Segment> path = workedExamplePath('G', 71, gcode::Dialect::Fanuc, &rapid);
  ASSERT_EQ(path.size(), rapid.size());
  // Roughing passes along Z at the profile's diameters: cuts that reach Z-45 at Ø40 (radius 20.2 with U0.4).
  int cuts = 0;
  for (std::size_t i = 0; i < path.size(); ++i) cuts += rapid[i] ? 0 : 1;
  EXPECT_GT(cuts, 10);
  EXPECT_TRUE(workedExamplePath('G', 999, gcode::Dialect::Fanuc).empty());
}

TEST(Help, SearchFindsRoughingInEnglishAndInThai) {
  for (std::string_view q : {"roughing", "กลึงปอกหยาบ", "rough turning"}) {
    const std::vector<HelpHit> hits = searchHelp(q, gcode::Dialect::Fanuc);
    ASSERT_FALSE(hits.empty()) << q;
    EXPECT_TRUE(std::any_of(hits.begin(), hits.end(), [](const HelpHit& h) {
      return h.letter == 'G' && h.number == 71;
    })) << q;
  }
  // The code itself comes first, written either way.
  for (std::string_view q : {"G71", "g71", "G071"}) {
    const std::vector<HelpHit> hits = searchHelp(q, gcode::Dialect::Haas);
    ASSERT_FALSE(hits.empty()) << q;
    EXPECT_EQ(hits.front().letter, 'G');
    EXPECT_EQ(hits.front().number, 71);
  }
  // G28 and G30 are found by the words teachers use for both (each has its own action).
  const std::vector<HelpHit> home = searchHelp("home", gcode::Dialect::Fanuc);
  for (int code : {28, 30})
    EXPECT_TRUE(std::any_of(home.begin(), home.end(), [code](const HelpHit& h) {
      return h.letter == 'G' && h.number == code;
    })) << code;
  const std::vector<HelpHit> thread = searchHelp("เกลียว", gcode::Dialect::Fanuc);
  for (int code : {32, 76, 92})
    EXPECT_TRUE(std::any_of(thread.begin(), thread.end(), [code](const HelpHit& h) {
      return h.letter == 'G' && h.number == code;
    })) << code;
  EXPECT_TRUE(searchHelp("coolant", gcode::Dialect::Fanuc).front().letter == 'M');
  EXPECT_TRUE(searchHelp("xyzzy", gcode::Dialect::Fanuc).empty());
  EXPECT_TRUE(searchHelp("  ", gcode::Dialect::Fanuc).empty());
}

// Issue 27: help and worked examples speak the machine's G-code system. On the
// ROMI (system B) the thread is G33, the clamp G92 S, the feed G95; every code
// the machine has gets a worked example in its numbers that runs clean.
TEST(Help, ASystemBMachineSpeaksItsOwnNumbers) {
  gcode::Dialect romi{};
  ASSERT_TRUE(gcode::parseDialectId("romi-gl240m", romi));
  const gcode::CodeInfo* g33 = gcode::findCode('G', 33, romi);
  ASSERT_NE(g33, nullptr);
  EXPECT_EQ(g33->exampleEn.substr(0, 4), "G33 ");
  EXPECT_EQ(g33->exampleEn.find("G32"), std::string_view::npos);
  const gcode::CodeInfo* g92 = gcode::findCode('G', 92, romi);
  ASSERT_NE(g92, nullptr);
  EXPECT_EQ(g92->action, gcode::CodeAction::CoordinateSet);
  EXPECT_EQ(g92->exampleEn.substr(0, 4), "G92 ");
  // System A keeps its own texts.
  EXPECT_EQ(gcode::findCode('G', 32, gcode::Dialect::Fanuc)->exampleEn.substr(0, 4), "G32 ");

  const std::string thread = workedExample('G', 33, romi);
  EXPECT_NE(thread.find("G33 Z-25. F1.5"), std::string::npos) << thread;
  EXPECT_NE(thread.find("G92 S2500"), std::string::npos) << thread;
  EXPECT_NE(thread.find("G95\n"), std::string::npos) << thread;
  for (const char* a : {"G32", "G50", "G99"}) EXPECT_EQ(thread.find(a), std::string::npos) << a << "\n" << thread;
  EXPECT_NE(workedExample('G', 78, romi).find("G78 X47.2 Z-25. F1.5"), std::string::npos);
  EXPECT_TRUE(workedExample('G', 32, romi).empty());  // no G32 in system B

  int examples = 0;
  for (const char letter : {'G', 'M'})
    for (int n = 0; n < gcode::kCodeNumbers; ++n) {
      const gcode::CodeInfo* row = gcode::findCode(letter, n, romi);
      if (!row || row->action == gcode::CodeAction::NotSimulated) continue;  // (W119 and A117: Help test above)
      const std::string text = workedExample(letter, n, romi);
      const std::string name = codeName(letter, n);
      ASSERT_FALSE(text.empty()) << name;
      EXPECT_NE(text.find(name), std::string::npos) << name << " is not in its own example:\n" << text;
      EXPECT_EQ(problems(text, romi, workedExampleFiles(letter, n, romi)), "") << name << ":\n" << text;
      ++examples;
    }
  EXPECT_GT(examples, 60);

  // The search and the explain bar find the system's numbers.
  const std::vector<HelpHit> hits = searchHelp("thread", romi);
  EXPECT_TRUE(
      std::any_of(hits.begin(), hits.end(), [](const HelpHit& h) { return h.letter == 'G' && h.number == 33; }));
  EXPECT_TRUE(
      std::none_of(hits.begin(), hits.end(), [](const HelpHit& h) { return h.letter == 'G' && h.number == 32; }));
  EXPECT_EQ(searchHelp("G78", romi).front().number, 78);
  EXPECT_EQ(explainCode('G', 99, romi, Lang::En), "drilling cycles return to the R point");
}

}  // namespace
}  // namespace klueng::core::machine

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kHelpScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng-help-examples-"});
