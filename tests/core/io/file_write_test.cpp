// io/file_write.h (issue 29): a failed or refused write leaves the old file's
// bytes as they were and says why, in English and Thai.
#include "klueng/core/io/file_write.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "klueng/core/messages.h"
#include "test_util.h"

namespace klueng::core::io {
namespace {

using testing::TempDir;
namespace fs = std::filesystem;

// A "full disk" any CI container can make: the file size limit (ulimit -f)
// fails writes past it with EFBIG, root included, no mount needed.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);  // else the process is killed instead of write failing
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, oldHandler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*oldHandler_)(int) = nullptr;
};

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(FileWrite, WritesAndReplacesKeepingTheMode) {
  TempDir dir;
  const std::string path = dir.file("part.nc");
  ASSERT_FALSE(writeFileAtomic(path, "G21\n"));
  EXPECT_EQ(testing::readFile(path), "G21\n");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::owner_exec);
  ASSERT_FALSE(writeFileAtomic(path, "G20\n"));
  EXPECT_EQ(testing::readFile(path), "G20\n");
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::owner_exec);
  EXPECT_EQ(entries(dir.path()), 1);
}

TEST(FileWrite, AFullDiskLeavesTheOldFileAndNoTemporaryFile) {
  TempDir dir;
  const std::string path = dir.file("sheet.pdf");
  const std::string old(3000, 'o');
  testing::writeFile(path, old);
  std::optional<Diagnostic> failed;
  {
    const FileSizeLimit limit(4096);
    failed = writeFileAtomic(path, std::string(10000, 'n'));
  }
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->code, "F109");
  EXPECT_EQ(testing::readFile(path), old);
  EXPECT_EQ(entries(dir.path()), 1);
  EXPECT_EQ(formatMessage(*failed, Lang::En),
            path +
                ": cannot write the file: there is no space for it (the disk is full, or the file is over the "
                "size allowed); an existing file of that name is left unchanged");
  EXPECT_EQ(formatMessage(*failed, Lang::Th), path +
                                                  ": บันทึกไฟล์ไม่ได้ เพราะไม่มีที่ว่างพอ (ดิสก์เต็ม หรือไฟล์ใหญ่เกินขนาดที่อนุญาต) "
                                                  "ถ้ามีไฟล์ชื่อนี้อยู่แล้ว ไฟล์นั้นยังคงเดิม");
}

// /dev/full is a device: written into (never renamed over) and its ENOSPC reported.
TEST(FileWrite, AFullDeviceIsReportedAndStaysADevice) {
  ASSERT_TRUE(fs::is_character_file("/dev/full"));
  const auto failed = writeFileAtomic("/dev/full", "G21\n");
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->code, "F109");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

// Refused even for root: no write bit means the owner wants it kept, as editors read it.
TEST(FileWrite, RefusesAReadOnlyFileAndKeepsIt) {
  TempDir dir;
  const std::string path = dir.file("part.nc");
  testing::writeFile(path, "old\n");
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);  // 0444
  EXPECT_TRUE(isReadOnlyFile(path));
  const auto failed = writeFileAtomic(path, "new\n");
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->code, "F119");
  EXPECT_EQ(testing::readFile(path), "old\n");
  EXPECT_EQ(entries(dir.path()), 1);
  EXPECT_EQ(formatMessage(*failed, Lang::En),
            path + ": the file is read-only, so it was not replaced; write to another file, or make it writable first");
  EXPECT_EQ(formatMessage(*failed, Lang::Th),
            path + ": ไฟล์นี้เป็นแบบอ่านอย่างเดียว จึงไม่ได้เขียนทับ ให้บันทึกเป็นไฟล์อื่น หรือเปลี่ยนให้เขียนได้ก่อน");
  // Through a link too: the file the link names is what would be replaced.
  const std::string link = dir.file("link.nc");
  fs::create_symlink(path, link);
  const auto viaLink = writeFileAtomic(link, "new\n");
  ASSERT_TRUE(viaLink);
  EXPECT_EQ(viaLink->code, "F119");
  EXPECT_EQ(testing::readFile(path), "old\n");
}

TEST(FileWrite, AFolderAndAMissingFolder) {
  TempDir dir;
  const auto folder = writeFileAtomic(dir.path().string(), "x");
  ASSERT_TRUE(folder);
  EXPECT_EQ(folder->code, "F127");
  const std::string inMissing = dir.file("no/such/job.txt");
  const auto missing = writeFileAtomic(inMissing, "x");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->code, "F125");
  EXPECT_EQ(formatMessage(*missing, Lang::En), inMissing + ": cannot create the file: the folder " +
                                                   dir.file("no/such") + " does not exist or cannot be written to");
}

TEST(FileWrite, AnOutputThatIsAnInputIsFound) {
  TempDir dir;
  const std::string program = dir.file("prog.nc");
  testing::writeFile(program, "G21\n");
  fs::create_directories(dir.path() / "sub");
  // The same file however it is named: `..`, a relative name, a symbolic or a hard link.
  const std::string viaDots = (dir.path() / "sub" / ".." / "prog.nc").string();
  const auto clash = outputOverwritesInput(viaDots, {dir.file("other.nc"), program});
  ASSERT_TRUE(clash);
  EXPECT_EQ(clash->code, "F126");
  EXPECT_EQ(formatMessage(*clash, Lang::En), viaDots + ": this output is the input file " + program +
                                                 "; writing it would destroy that file, so choose another name");
  fs::create_symlink(program, dir.file("link.nc"));
  EXPECT_TRUE(outputOverwritesInput(dir.file("link.nc"), {program}));
  fs::create_hard_link(program, dir.file("hard.nc"));
  EXPECT_TRUE(outputOverwritesInput(dir.file("hard.nc"), {program}));
  const fs::path cwd = fs::current_path();
  fs::current_path(dir.path());
  EXPECT_TRUE(outputOverwritesInput("prog.nc", {program}));
  EXPECT_TRUE(outputOverwritesInput(program, {"./prog.nc"}));
  fs::current_path(cwd);
  // Different files, a new file, and a stream are fine.
  EXPECT_FALSE(outputOverwritesInput(dir.file("trace.csv"), {program}));
  EXPECT_FALSE(outputOverwritesInput("/dev/stdout", {program, "/dev/stdout"}));
}

}  // namespace
}  // namespace klueng::core::io
