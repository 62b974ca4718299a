// Issue 42 item 1 (the rest): a subprogram file that is a link leaving the program's
// folder is never opened; the job drops it with F158 and the call is E404.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "../../scratch_folders.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/subprogram_files.h"

namespace subprogram_link_test {
namespace {

namespace fs = std::filesystem;
using namespace klueng::core;

const auto* const kCleanup = klueng::test::removeScratchFoldersAtExit({"klueng_subprogram_link-"});

TEST(SubprogramFiles, ALinkOutOfTheFolderIsNeverOpened) {
  const fs::path root = fs::temp_directory_path() / ("klueng_subprogram_link-" + std::to_string(::getpid()));
  fs::create_directories(root / "prog");
  // Read, this file would give blocks and a lexical error of file 1 (a letter without a value).
  std::ofstream(root / "outside.nc") << "O1000\nG01 X\nM99\n";
  fs::create_symlink(root / "outside.nc", root / "prog" / "O1000.nc");
  std::ofstream(root / "prog" / "O2000.nc") << "O2000\nG00 X10.\nM99\n";
  gcode::Program program = gcode::parse("O0001\nM98 P1000\nM98 P2000\nM30\n", 1, 0);
  const std::vector<Diagnostic> read =
      machine::attachSubprogramFiles(program, (root / "prog").string(), gcode::Dialect::Fanuc);
  ASSERT_EQ(program.files.size(), 3u);  // named, so that the job can say F158 of it
  const int link = program.files[1].ends_with("O1000.nc") ? 1 : 2;
  const int inside = 3 - link;
  EXPECT_TRUE(read.empty());
  EXPECT_TRUE(std::none_of(program.blocks.begin(), program.blocks.end(),
                           [&](const gcode::Block& b) { return b.file == link; }));
  EXPECT_TRUE(std::none_of(program.lexicalDiagnostics.begin(), program.lexicalDiagnostics.end(),
                           [&](const Diagnostic& d) { return d.range.file == link; }));
  // The file inside the folder is read as before.
  EXPECT_TRUE(std::any_of(program.blocks.begin(), program.blocks.end(),
                          [&](const gcode::Block& b) { return b.file == inside; }));
}

}  // namespace
}  // namespace subprogram_link_test
