#include "klueng/core/io/tool_config.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>
#include <fstream>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "klueng/core/messages.h"
#include "test_util.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::io::tool_config_test {
namespace {

using testing::TempDir;
using testing::writeFile;

std::string codes(const std::vector<Diagnostic>& diags) {
  std::string s;
  for (const Diagnostic& d : diags)
    s += d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + " ";
  return s;
}

const std::string kShipped = KLUENG_SOURCE_DIR;

// Sets an environment variable for one test and restores it afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// ---------------------------------------------------------------- tools.cfg

TEST(ToolTable, ShippedTableNamesEightExistingBitmaps) {
  const auto r = readToolTable(kShipped + "/tools.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->bitmap[0], "resources/tools/01-outside-turning.bmp");
  EXPECT_EQ(r.value->bitmap[2], "resources/tools/03-threading-60.bmp");
  for (int tool = 1; tool <= kSeedToolLines; ++tool)
    EXPECT_TRUE(std::filesystem::is_regular_file(r.value->bitmapPath(tool))) << tool;
  EXPECT_EQ(r.value->bitmapPath(0), "");
  EXPECT_EQ(r.value->bitmapPath(9), "");
  EXPECT_EQ(r.value->stations, kDefaultTurretStations);
}

TEST(ToolTable, EmptyLineMeansNoBitmapAndPathsResolveAgainstTheFolder) {
  const auto r = parseToolTable("a.bmp\n\n  sub/c.PNG  \n/abs/d.bmp\n\n\n\n\n", "/data", "tools.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->bitmapPath(1), "/data/a.bmp");
  EXPECT_EQ(r.value->bitmapPath(2), "");
  EXPECT_EQ(r.value->bitmap[2], "sub/c.PNG");
  EXPECT_EQ(r.value->bitmapPath(3), "/data/sub/c.PNG");
  EXPECT_EQ(r.value->bitmapPath(4), "/abs/d.bmp");
}

TEST(ToolTable, WindowsBackslashesInNamesAreFolderSeparators) {
  const auto r = parseToolTable("tools\\turn.bmp\n\n\n\n\n\n\n\n", "/data", "tools.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->bitmap[0], "tools\\turn.bmp");  // kept as written
  EXPECT_EQ(r.value->bitmapPath(1), "/data/tools/turn.bmp");
}

TEST(ToolTable, MissingLinesAreAnError) {
  const auto r = parseToolTable("a.bmp\nb.bmp\nc.bmp\n", "/d", "tools.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.code, "F120");
  EXPECT_EQ(d.range.line, 3);
  EXPECT_EQ(d.args, (std::vector<std::string>{"tools.cfg", "3", "04"}));
  EXPECT_EQ(
      formatMessage(d, Lang::En),
      "tools.cfg: the tool table needs 8 lines (bitmaps of tools 01 to 08) but has 3; tools 04 to 08 have no bitmap");
  ASSERT_TRUE(r.value);
  EXPECT_EQ(r.value->bitmap[2], "c.bmp");
}

TEST(ToolTable, EmptyFileHasNoLines) {
  const auto r = parseToolTable("", "/d", "tools.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F120");
  EXPECT_EQ(r.diagnostics[0].args.at(1), "0");
}

TEST(ToolTable, ExtraLinesAreIgnoredWithAWarning) {
  // An 8-station turret (the seed's): line 10 is past it.
  const auto r =
      parseToolTable("1.bmp\n2.bmp\n3.bmp\n4.bmp\n5.bmp\n6.bmp\n7.bmp\n8.bmp\n\nnine.bmp\n", "/d", "t.cfg", 8);
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F107");
  EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
  EXPECT_EQ(r.diagnostics[0].range.line, 10);
  EXPECT_TRUE(r.ok());
}

TEST(ToolTable, GarbageLineIsNotABitmapName) {
  const auto r = parseToolTable("a.bmp\n  12 34 hello\nc.bmp\nx.bmp\ny.bmp\nz.bmp\nq.bmp\nw.bmp\n", "/d", "t.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F122");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{2, 3, 11}));
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"t.cfg", "02", "12 34 hello"}));
  EXPECT_EQ(r.value->bitmap[1], "");
}

TEST(ToolTable, BinaryFileIsRefused) {
  const auto r = parseToolTable(std::string("a.bmp\n\x01\x02\0\x03", 10), "/d", "t.cfg");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F104");
  EXPECT_EQ(r.diagnostics[0].range.line, 2);
}

TEST(ToolTable, ReadReportsBitmapsThatDoNotExist) {
  TempDir dir;
  writeFile(dir.file("here.bmp"), "BM");
  writeFile(dir.file("tools.cfg"), "here.bmp\ngone.bmp\n\n\n\n\n\n\n");
  const auto r = readToolTable(dir.file("tools.cfg"));
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F121");
  EXPECT_EQ(r.diagnostics[0].range.line, 2);
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{dir.file("tools.cfg"), "02", "gone.bmp"}));
  EXPECT_EQ(r.value->folder, dir.path().string());
}

TEST(ToolTable, FormatRoundTrips) {
  ToolTable t;
  t.bitmap = {"a.bmp", "", "ภาพ/มีด.png", "", "", "", "", "h.bmp"};
  const std::string text = formatToolTable(t);
  EXPECT_EQ(text, "a.bmp\n\nภาพ/มีด.png\n\n\n\n\nh.bmp\n");
  const auto r = parseToolTable(text, "/x", "t.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.value->bitmap, t.bitmap);
}

// ---------------------------------------------------------------- offset.cfg

TEST(OffsetTable, ShippedOffsetsMatchTheSamples) {
  const auto r = readOffsetTable(kShipped + "/offset.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  const OffsetTable& t = *r.value;
  EXPECT_DOUBLE_EQ(t.at(1).r, 0.8);
  EXPECT_EQ(t.at(1).tip, 3);
  EXPECT_DOUBLE_EQ(t.at(3).r, 0.0);
  EXPECT_EQ(t.at(3).tip, 8);
  EXPECT_EQ(t.at(2).tip, 4);
  EXPECT_EQ(t.at(5).tip, 2);
  EXPECT_EQ(t.at(6).tip, 7);
  EXPECT_EQ(t.at(8).tip, 6);
  for (int n = 1; n <= kOffsetCount; ++n) {
    EXPECT_EQ(t.at(n).x, 0.0);
    EXPECT_EQ(t.at(n).z, 0.0);
  }
}

std::string sixteen(const std::string& first) {
  std::string s = first + "\n";
  for (int i = 2; i <= 16; ++i) s += "0 0 0 0\n";
  return s;
}

TEST(OffsetTable, ReadsSignedAndDecimalNumbers) {
  const auto r = parseOffsetTable(sixteen("-1.5  +2.25\t0.4 3"), "o.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_DOUBLE_EQ(r.value->at(1).x, -1.5);
  EXPECT_DOUBLE_EQ(r.value->at(1).z, 2.25);
  EXPECT_DOUBLE_EQ(r.value->at(1).r, 0.4);
  EXPECT_EQ(r.value->at(1).tip, 3);
}

struct BadOffsetLine {
  const char* line;
  const char* code;
  int column;
  std::vector<std::string> args;
};

class OffsetLineErrors : public ::testing::TestWithParam<BadOffsetLine> {};

TEST_P(OffsetLineErrors, NameTheLineAndColumn) {
  const BadOffsetLine& p = GetParam();
  const auto r = parseOffsetTable(sixteen(p.line), "o.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.code, p.code);
  EXPECT_EQ(d.severity, Severity::Error);
  EXPECT_EQ(d.range.line, 1);
  EXPECT_EQ(d.range.column, p.column);
  EXPECT_EQ(d.args, p.args);
  // A bad row is left at 0 0 0 0, not half read.
  EXPECT_EQ(r.value->at(1).x, 0.0);
  EXPECT_EQ(r.value->at(1).tip, 0);
}

INSTANTIATE_TEST_SUITE_P(Cases, OffsetLineErrors,
                         ::testing::Values(BadOffsetLine{"1 2 0.8", "F132", 8, {"o.cfg", "01", "3"}},
                                           BadOffsetLine{"1 2 0.8 3 5", "F132", 11, {"o.cfg", "01", "5"}},
                                           BadOffsetLine{"1 2x 0.8 3", "F133", 3, {"o.cfg", "01", "2x"}},
                                           BadOffsetLine{"nan 0 0.8 3", "F133", 1, {"o.cfg", "01", "nan"}},
                                           BadOffsetLine{"0 0 -0.4 3", "F134", 5, {"o.cfg", "01", "-0.4"}},
                                           BadOffsetLine{"0 0 0.4 10", "F135", 9, {"o.cfg", "01", "10"}},
                                           BadOffsetLine{"0 0 0.4 3.5", "F135", 9, {"o.cfg", "01", "3.5"}},
                                           BadOffsetLine{"0 0 0.4 -1", "F135", 9, {"o.cfg", "01", "-1"}},
                                           BadOffsetLine{"   ", "F131", 1, {"o.cfg", "01"}}));

TEST(OffsetTable, MissingLinesAreAnError) {
  const auto r = parseOffsetTable("0 0 0.8 3\n0 0 0 8\n", "o.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F130");
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"o.cfg", "2", "03"}));
  EXPECT_EQ(r.value->at(2).tip, 8);
}

TEST(OffsetTable, ErrorInALaterLineNamesThatLine) {
  std::string text = sixteen("0 0 0 0");
  text.replace(text.rfind("0 0 0 0"), 7, "0 0 abc 0");  // line 16
  const auto r = parseOffsetTable(text, "o.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{16, 5, 3}));
  EXPECT_EQ(r.diagnostics[0].args.at(1), "16");
}

TEST(OffsetTable, ExtraLinesAreIgnoredWithAWarning) {
  std::string text = sixteen("0 0 0 0");
  for (int i = 17; i <= 64; ++i) text += "0 0 0 0\n";
  const auto r = parseOffsetTable(text + "garbage here\n", "o.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F107");
  EXPECT_EQ(r.diagnostics[0].range.line, 65);
  EXPECT_EQ(r.diagnostics[0].args.at(1), "64");
  EXPECT_TRUE(r.ok());
}

TEST(OffsetTable, FormatRoundTrips) {
  OffsetTable t;
  for (int i = 0; i < kOffsetCount; ++i)
    t.offsets[static_cast<std::size_t>(i)] = Offset{i * 0.1 - 0.7, -i / 3.0, i * 0.05, i % 10};
  const std::string text = formatOffsetTable(t);
  const auto r = parseOffsetTable(text, "o.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  for (int n = 1; n <= kOffsetCount; ++n) {
    EXPECT_EQ(r.value->at(n).x, t.at(n).x);
    EXPECT_EQ(r.value->at(n).z, t.at(n).z);
    EXPECT_EQ(r.value->at(n).r, t.at(n).r);
    EXPECT_EQ(r.value->at(n).tip, t.at(n).tip);
  }
  EXPECT_EQ(formatOffsetTable(OffsetTable{}).substr(0, 8), "0 0 0 0\n");
}

// ---------------------------------------------------------------- machine.cfg

TEST(MachineConfigFile, ShippedFileHoldsTheSpecDefaults) {
  const auto r = readMachineConfig(kShipped + "/machine.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.value->rapidX, 4000.0);
  EXPECT_EQ(r.value->rapidZ, 8000.0);
  EXPECT_EQ(r.value->maxSpindleRpm, 3000.0);
  EXPECT_EQ(r.value->startX, 0.0);
  EXPECT_EQ(r.value->startZ, 300.0);
  EXPECT_EQ(r.value->referenceZ, 300.0);
  // The shipped lathe's home (reference point) is above the part, Ø200, as on
  // a real lathe, so real programs' G28 U0 / G53 X0 retract away from the
  // part; the SPEC 1 default X0 applies when there is no machine.cfg.
  EXPECT_EQ(r.value->referenceX, 200.0);
  EXPECT_EQ(MachineConfig{}.referenceX, 0.0);
  EXPECT_EQ(r.value->chuckGrip, 15.0);
  // The shipped file is exactly what the dialogs would write for those values.
  MachineConfig shipped;
  shipped.referenceX = 200.0;
  EXPECT_EQ(testing::readFile(kShipped + "/machine.cfg"), formatMachineConfig(shipped));
}

TEST(MachineConfigFile, KeysCommentsAndMissingKeys) {
  const auto r = parseMachineConfig("# my lathe\nrapid_x=5000   # mm/min\n  max_spindle_rpm = 2500\n\n", "m.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->rapidX, 5000.0);
  EXPECT_EQ(r.value->maxSpindleRpm, 2500.0);
  EXPECT_EQ(r.value->rapidZ, 8000.0);  // default
}

struct BadMachineLine {
  const char* text;
  const char* code;
  int line;
  int column;
  Severity severity;
};

class MachineConfigErrors : public ::testing::TestWithParam<BadMachineLine> {};

TEST_P(MachineConfigErrors, NameTheLineAndColumn) {
  const BadMachineLine& p = GetParam();
  const auto r = parseMachineConfig(p.text, "m.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, p.code);
  EXPECT_EQ(r.diagnostics[0].range.line, p.line);
  EXPECT_EQ(r.diagnostics[0].range.column, p.column);
  EXPECT_EQ(r.diagnostics[0].severity, p.severity);
  EXPECT_EQ(r.diagnostics[0].args.at(0), "m.cfg");
  ASSERT_TRUE(r.value);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, MachineConfigErrors,
    ::testing::Values(BadMachineLine{"rapid_x 4000\n", "F140", 1, 1, Severity::Error},
                      BadMachineLine{"# x\n = 5\n", "F140", 2, 2, Severity::Error},
                      BadMachineLine{"\nspindle = 3000\n", "F141", 2, 1, Severity::Error},
                      BadMachineLine{"rapid_z = fast\n", "F142", 1, 11, Severity::Error},
                      BadMachineLine{"rapid_z =\n", "F142", 1, 10, Severity::Error},
                      BadMachineLine{"rapid_x = 0\n", "F143", 1, 11, Severity::Error},
                      BadMachineLine{"max_spindle_rpm = -5\n", "F143", 1, 19, Severity::Error},
                      BadMachineLine{"chuck_grip = -1\n", "F144", 1, 14, Severity::Error},
                      BadMachineLine{"rapid_x = 1\nrapid_x = 2\n", "F145", 2, 1, Severity::Warning},
                      BadMachineLine{"travel_z_min = 10\ntravel_z_max = 5\n", "F146", 2, 1, Severity::Error}));

TEST(MachineConfigFile, BadTravelRangeFallsBackToDefaults) {
  const auto r = parseMachineConfig("travel_x_max = -2000\n", "m.cfg");
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.value->travelXMin, MachineConfig{}.travelXMin);
  EXPECT_EQ(r.value->travelXMax, MachineConfig{}.travelXMax);
  EXPECT_EQ(formatMessage(r.diagnostics.at(0), Lang::En),
            "m.cfg: travel limits: travel_x_min must be less than travel_x_max");
}

TEST(MachineConfigFile, FormatRoundTrips) {
  MachineConfig m;
  m.rapidX = 3333.3;
  m.rapidZ = 7777.7;
  m.maxSpindleRpm = 4500;
  m.referenceX = 200;
  m.referenceZ = 150.5;
  m.startX = 100;
  m.startZ = 250;
  m.travelXMin = -10;
  m.travelXMax = 400;
  m.travelZMin = -500;
  m.travelZMax = 350;
  m.chuckGrip = 22.5;
  m.chuckJawHeight = 0;
  const auto r = parseMachineConfig(formatMachineConfig(m), "m.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(formatMachineConfig(*r.value), formatMachineConfig(m));
  EXPECT_EQ(r.value->rapidX, 3333.3);
  EXPECT_EQ(r.value->chuckGrip, 22.5);
  EXPECT_EQ(r.value->travelZMax, 350.0);
}

// ---------------------------------------------------------------- folders

TEST(ConfigDir, ExplicitThenEnvironmentThenUserCopyThenShipped) {
  TempDir dir;
  const std::string user = dir.file("xdg");
  ScopedEnv xdg("XDG_DATA_HOME", user);
  {
    ScopedEnv env("KLUENG_DATA_DIR", std::string("/from/env"));
    EXPECT_EQ(findConfigDir("/explicit"), "/explicit");
    EXPECT_EQ(findConfigDir(), "/from/env");
  }
  ScopedEnv noEnv("KLUENG_DATA_DIR", std::nullopt);
  EXPECT_EQ(userConfigDir(), user + "/klueng");
  EXPECT_EQ(findConfigDir(), shippedConfigDir());  // no per-user copy yet
  writeFile(user + "/klueng/tools.cfg", "\n");
  EXPECT_EQ(findConfigDir(), user + "/klueng");
}

TEST(ConfigDir, AnInstalledProgramFindsShareKluengBesideItsBin) {
  TempDir dir;
  const std::string exe = dir.file("usr/bin/klueng-cli");
  writeFile(exe, "");
  EXPECT_EQ(installedDataDir(exe), "");  // no share/klueng/tools.cfg: not an installed tree
  writeFile(dir.file("usr/share/klueng/tools.cfg"), "\n");
  EXPECT_TRUE(std::filesystem::equivalent(installedDataDir(exe), dir.file("usr/share/klueng")));
  EXPECT_EQ(installedDataDir(""), "");
  // File ▸ Open starts in the samples (issue 28 item 8): share/klueng/samples installed,
  // resources/samples in the repository.
  EXPECT_EQ(samplesDir(dir.file("usr/share/klueng")), "");
  std::filesystem::create_directories(dir.file("usr/share/klueng/samples"));
  EXPECT_EQ(samplesDir(dir.file("usr/share/klueng")), dir.file("usr/share/klueng/samples"));
  EXPECT_TRUE(std::filesystem::equivalent(samplesDir(KLUENG_SOURCE_DIR), KLUENG_SAMPLES_DIR));
  EXPECT_EQ(samplesDir(""), "");
}

TEST(ConfigDir, UserConfigFallsBackToHome) {
  ScopedEnv xdg("XDG_DATA_HOME", std::nullopt);
  ScopedEnv home("HOME", std::string("/home/somchai"));
  EXPECT_EQ(userConfigDir(), "/home/somchai/.local/share/klueng");
}

TEST(ConfigDir, EnsureUserCopyCopiesShippedFilesAndBitmapsOnce) {
  TempDir dir;
  ScopedEnv xdg("XDG_DATA_HOME", dir.path().string());
  std::string error;
  const std::string user = ensureUserConfigDir(&error);
  ASSERT_EQ(user, dir.file("klueng")) << error;
  const auto tools = readToolTable(user + "/tools.cfg");
  ASSERT_TRUE(tools.ok()) << codes(tools.diagnostics);  // the bitmaps came along
  EXPECT_EQ(tools.value->bitmapPath(1), user + "/resources/tools/01-outside-turning.bmp");
  EXPECT_TRUE(readOffsetTable(user + "/offset.cfg").ok());
  EXPECT_TRUE(readMachineConfig(user + "/machine.cfg").ok());
  // The user's edits survive a second call.
  writeFile(user + "/offset.cfg", "edited\n");
  ASSERT_EQ(ensureUserConfigDir(&error), user) << error;
  EXPECT_EQ(testing::readFile(user + "/offset.cfg"), "edited\n");
}

}  // namespace
}  // namespace klueng::core::io::tool_config_test

namespace klueng::core::io::tool_config_test {
namespace {

// Issue 13: a bitmap path that is a folder was called "does not exist".
TEST(ToolTable, ABitmapPathThatIsAFolderSaysSo) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("klueng-bitmap-folder-" + std::to_string(::getpid()));
  fs::create_directories(dir / "01-outside.bmp");
  { std::ofstream(dir / "tools.cfg") << "01-outside.bmp\n\n\n\n\n\n\n\n"; }
  const auto r = readToolTable((dir / "tools.cfg").string());
  fs::remove_all(dir);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F124");
  EXPECT_EQ(r.diagnostics[0].range.line, 1);
}

// Issue 29 item 10: a link loop, a device, a pipe and a link to nothing were all
// "does not exist"; each says what it is.
TEST(ToolTable, ABitmapThatIsNoFileSaysWhatItIs) {
  namespace fs = std::filesystem;
  TempDir dir;
  fs::create_symlink("loop.bmp", dir.path() / "loop.bmp");
  fs::create_symlink("/dev/null", dir.path() / "device.bmp");
  ASSERT_EQ(::mkfifo(dir.file("pipe.bmp").c_str(), 0644), 0);
  fs::create_symlink("gone.bmp", dir.path() / "dangling.bmp");
  writeFile(dir.file("tools.cfg"), "loop.bmp\ndevice.bmp\npipe.bmp\ndangling.bmp\nmissing.bmp\n\n\n\n");
  const std::string cfg = dir.file("tools.cfg");
  const auto r = readToolTable(cfg);
  ASSERT_EQ(r.diagnostics.size(), 5u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"F138", cfg + ": tool 01: 'loop.bmp' is a link that leads back to itself (a loop of links), not a bitmap file"},
      {"F138", cfg + ": tool 02: 'device.bmp' is a device, not a bitmap file"},
      {"F138", cfg + ": tool 03: 'pipe.bmp' is a pipe (FIFO), not a bitmap file"},
      {"F138", cfg + ": tool 04: 'dangling.bmp' is a link to 'gone.bmp', which does not exist, not a bitmap file"},
      {"F121", cfg + ": tool 05: the bitmap 'missing.bmp' does not exist"},
  };
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(r.diagnostics[i].code, expected[i].first) << i;
    EXPECT_EQ(r.diagnostics[i].range.line, static_cast<int>(i) + 1);
    EXPECT_EQ(formatMessage(r.diagnostics[i], Lang::En), expected[i].second);
  }
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::Th),
            cfg + ": มีดตัด 01: 'loop.bmp' เป็นลิงก์ที่วนกลับมาหาตัวเอง (ลิงก์วนซ้ำ) ไม่ใช่ไฟล์ภาพ");
  EXPECT_EQ(formatMessage(r.diagnostics[2], Lang::Th), cfg + ": มีดตัด 03: 'pipe.bmp' เป็นไปป์ (FIFO) ไม่ใช่ไฟล์ภาพ");
}

}  // namespace
}  // namespace klueng::core::io::tool_config_test
