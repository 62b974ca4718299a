// Grade a class (issue 39): each student's run carries the teacher's cutting-data warnings,
// on their blocks, and they never change pass or fail; a sound program has none.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "../../scratch_folders.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::job {
namespace {

namespace fs = std::filesystem;

const char* const kClassCuttingPrefix = "klueng-class-cutting-";

fs::path classCuttingFile(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / (kClassCuttingPrefix + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

JobInput classCuttingInput() {
  static const machine::LoadedSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR);
  JobInput r;
  r.setup = setup.setup;
  r.stations = setup.setup.tools.stations;
  return r;
}

// Shipped T01: a plain bitmap with offset R0.8. A 0.3 mm finishing pass at 0.35 mm/rev leaves
// Ra = 0.35^2 / (32 * 0.8) * 1000 = 4.8 um > 3.2 (line 12); at 0.2 mm/rev, Ra 1.6 (sound).
std::string classCuttingProgram(const char* feed) {
  return std::string(
             "Student\nShaft\nS45C\n150\n1100\nSomchai\nG21 G40 G99\nT0101\nG97 S800 M03\nG00 X60. Z2.\n"
             "X49.4\nG01 Z-20. F") +
         feed + "\nG00 X60.\nZ50.\nM30\n";
}

TEST(ClassCutting, AStudentsRoughFinishIsWarnedOnItsBlock) {
  const fs::path rough = classCuttingFile("rough.nc", classCuttingProgram("0.35"));
  const GradedProgram g = gradeProgram(rough.string(), classCuttingInput());
  ASSERT_EQ(g.errors, 0) << g.firstError;
  ASSERT_TRUE(g.part.has_value());
  ASSERT_EQ(g.cuttingWarnings.size(), 1u);
  EXPECT_EQ(g.cuttingWarnings[0].code, codes::kFinishTooRough);
  EXPECT_EQ(g.cuttingWarnings[0].range.line, 12);
  EXPECT_EQ(g.cuttingWarnings[0].severity, Severity::Warning);

  const fs::path sound = classCuttingFile("sound.nc", classCuttingProgram("0.2"));
  const GradedProgram s = gradeProgram(sound.string(), classCuttingInput());
  ASSERT_EQ(s.errors, 0) << s.firstError;
  EXPECT_TRUE(s.cuttingWarnings.empty());
}

[[maybe_unused]] ::testing::Environment* const kClassCuttingCleanup =
    klueng::test::removeScratchFoldersAtExit({kClassCuttingPrefix});

}  // namespace
}  // namespace klueng::core::job
