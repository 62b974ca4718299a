// The one reader of a machine setup folder (setup_files.h): what the GUI, the
// CLI and the reports all see.
#include "klueng/core/machine/setup_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "klueng/core/io/image.h"
#include "klueng/core/machine/setup_files.h"
#include "klueng/core/messages.h"

namespace klueng::core::machine {
namespace {

namespace fs = std::filesystem;

class SetupFolder {
 public:
  SetupFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ =
        fs::temp_directory_path() / ("klueng-setup-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~SetupFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  void write(const std::string& name, const std::string& bytes) const {
    fs::create_directories((path_ / name).parent_path());
    std::ofstream(path_ / name, std::ios::binary) << bytes;
  }
  void copyShipped(const std::string& name) const {
    fs::create_directories((path_ / name).parent_path());
    fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / name, path_ / name);
  }
  std::string dir() const { return path_.string(); }

 private:
  fs::path path_;
};

TEST(LoadMachineSetup, ReadsTheShippedFolder) {
  const LoadedSetup loaded = loadMachineSetup(KLUENG_SOURCE_DIR, true);
  EXPECT_FALSE(loaded.hasErrors());
  EXPECT_FALSE(loaded.unreadable);
  EXPECT_TRUE(loaded.toolTableRead);
  EXPECT_EQ(loaded.toolsWithBitmap(), (std::optional<std::vector<int>>{{1, 2, 3, 4, 5, 6, 7, 8}}));
  EXPECT_EQ(loaded.setup.machine.rapidX, 4000.0);  // machine.cfg: rapid_x = 4000
  EXPECT_EQ(loaded.setup.offsets.at(1).tip, 3);
  ASSERT_TRUE(loaded.bitmaps[2]);
  EXPECT_EQ(loaded.bitmaps[2]->width, 60);  // tool 03: 30 mm at 2 px/mm
}

TEST(LoadMachineSetup, ImagesAreKeptOnlyWhenAsked) {
  const LoadedSetup loaded = loadMachineSetup(KLUENG_SOURCE_DIR, false);
  EXPECT_FALSE(loaded.bitmaps[0]);
  EXPECT_EQ(loaded.toolsWithBitmap()->size(), 8u);
}

TEST(LoadMachineSetup, ABitmapThatDoesNotDecodeIsNoToolForEveryone) {
  SetupFolder folder;
  folder.write("tools.cfg", "t1.bmp\nt2.bmp\n");
  folder.write("offset.cfg", "");
  folder.write("t1.bmp", "BM this is not a bitmap");
  folder.copyShipped("resources/tools/02-outside-left-hand.bmp");
  fs::copy_file(fs::path(folder.dir()) / "resources/tools/02-outside-left-hand.bmp", fs::path(folder.dir()) / "t2.bmp");
  const LoadedSetup loaded = loadMachineSetup(folder.dir());
  // The decoder's error, on t1.bmp.
  const auto onT1 = std::find_if(loaded.diagnostics.begin(), loaded.diagnostics.end(), [](const SetupDiagnostic& d) {
    return d.file.size() >= 6 && d.file.compare(d.file.size() - 6, 6, "t1.bmp") == 0;
  });
  ASSERT_NE(onT1, loaded.diagnostics.end());
  EXPECT_TRUE(isError(onT1->diagnostic.severity));
  EXPECT_EQ(onT1->diagnostic.code.substr(0, 3), "F15");
  EXPECT_TRUE(loaded.setup.tools.bitmapUnreadable[0]);
  // The check (toolsWithBitmap) and a compiled job agree: station 2 only.
  EXPECT_EQ(loaded.toolsWithBitmap(), (std::optional<std::vector<int>>{{2}}));
  EXPECT_EQ(toolsWithBitmap(loaded.setup), (std::vector<int>{2}));
}

TEST(LoadMachineSetup, NoToolTableMeansTWordsAreNotChecked) {
  SetupFolder folder;  // empty: no tools.cfg
  const LoadedSetup loaded = loadMachineSetup(folder.dir());
  EXPECT_FALSE(loaded.toolTableRead);
  EXPECT_TRUE(loaded.unreadable);
  EXPECT_EQ(loaded.toolsWithBitmap(), std::nullopt);
}

TEST(LoadMachineSetup, MachineCfgComesFirstAndBoundsTheTurret) {
  SetupFolder folder;
  folder.write("machine.cfg", "turret_stations = 12\n");
  folder.write("tools.cfg", "\n\n\n\n\n\n\n\n\n\n\n\n");
  folder.write("offset.cfg", "");
  const LoadedSetup loaded = loadMachineSetup(folder.dir());
  EXPECT_EQ(loaded.setup.machine.turretStations, 12);
  EXPECT_EQ(loaded.setup.tools.stations, 12);
}

// A white bitmap with a red cutting edge in its lower left corner.
std::string toolBmp(int width, int height) {
  io::RgbImage image{width, height, std::vector<std::uint32_t>(static_cast<std::size_t>(width) * height, 0xFFFFFF)};
  for (int y = height - 8; y < height; ++y)
    for (int x = 0; x < 8; ++x) image.pixels[static_cast<std::size_t>(y) * width + x] = 0xFF0000;
  return io::encodeBmp(image);
}

// Issue 29 item 10: a bitmap larger than a tool can be (500 mm at 2 px/mm = 1000
// pixels) is a setup error at its tools.cfg line when the setup is read, not an
// alarm when the tool first cuts.
TEST(LoadMachineSetup, ABitmapLargerThanAToolIsASetupErrorAtItsLine) {
  SetupFolder folder;
  folder.write("tools.cfg", "wide.bmp\nedge.bmp\n\n\n\n\n\n\n");
  folder.copyShipped("offset.cfg");
  folder.write("wide.bmp", toolBmp(1001, 40));
  folder.write("edge.bmp", toolBmp(1000, 40));  // the largest a tool may be
  const LoadedSetup loaded = loadMachineSetup(folder.dir(), true);
  ASSERT_EQ(loaded.diagnostics.size(), 1u);
  const SetupDiagnostic& d = loaded.diagnostics.front();
  const std::string tools = (fs::path(folder.dir()) / "tools.cfg").string();
  EXPECT_EQ(d.file, tools);
  EXPECT_EQ(d.diagnostic.code, "F139");
  EXPECT_EQ(d.diagnostic.range.line, 1);
  EXPECT_EQ(d.diagnostic.range.column, 1);
  EXPECT_EQ(formatMessage(d.diagnostic, Lang::En),
            tools +
                ": tool 01: the bitmap 'wide.bmp' is 1001 x 40 pixels; a tool bitmap may be at most 1000 x 1000 "
                "pixels (500 mm each way at 2 pixels per mm)");
  EXPECT_EQ(formatMessage(d.diagnostic, Lang::Th),
            tools +
                ": มีดตัด 01: ภาพ 'wide.bmp' มีขนาด 1001 x 40 พิกเซล ภาพมีดตัดต้องไม่เกิน 1000 x 1000 พิกเซล "
                "(ด้านละ 500 มม. ที่ 2 พิกเซลต่อมม.)");
  EXPECT_TRUE(loaded.hasErrors());
  EXPECT_TRUE(loaded.setup.tools.bitmapUnreadable[0]);
  EXPECT_FALSE(loaded.bitmaps[0]);
  EXPECT_FALSE(loaded.setup.tools.bitmapUnreadable[1]);
  EXPECT_EQ(loaded.toolsWithBitmap(), (std::optional<std::vector<int>>{{2}}));
}

}  // namespace
}  // namespace klueng::core::machine
