// Issue 29: klueng-cli never loses a file it writes over. A failed write (a
// full disk) keeps the old file's bytes and exits 2; a read-only output is
// refused (exit 2); an output naming an input is refused before any work
// (exit 2). Messages in English and Thai, with the path and the reason.
//
// The full disk is the file size limit (ulimit -f, SIGXFSZ ignored): writes
// past it fail with EFBIG for root too, in any container, without a mount.
#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_write_test {

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exitCode = -1;
  std::string err;
};

// klueng-cli ARGS in `dir`, stderr captured; `limitBlocks` > 0: files may grow
// to that many 512-byte blocks (POSIX sh's ulimit -f unit) at most.
CliRun cli(const fs::path& dir, const std::string& args, int limitBlocks = 0) {
  std::string command = "cd '" + dir.string() + "' && ";
  if (limitBlocks > 0) command += "trap '' XFSZ && ulimit -f " + std::to_string(limitBlocks) + " && ";
  command += "env LC_ALL= LC_MESSAGES= LANG=C QT_QPA_PLATFORM=offscreen '" + std::string(KLUENG_CLI_PATH) + "' " +
             args + " --config '" + KLUENG_SOURCE_DIR + "' 2>&1 >/dev/null";
  CliRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.err.append(buf, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Whole bytes compared, only the sizes shown on failure (a PDF is no readable diff).
::testing::AssertionResult sameBytes(const fs::path& p, const std::string& expected) {
  const std::string actual = slurp(p);
  if (actual == expected) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << p << " changed: " << actual.size() << " bytes, expected the old "
                                       << expected.size() << " bytes";
}

void put(const fs::path& p, const std::string& bytes) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << bytes;
}

// Only the lines klueng-cli wrote (Qt's start-up chatter on stderr left out).
std::string kluengLines(const std::string& err) {
  std::istringstream in(err);
  std::string out, line;
  while (std::getline(in, line))
    if (line.find("QStandardPaths") == std::string::npos) out += line + "\n";
  return out;
}

class CliWrite : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("klueng_cli_write_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    fs::copy_file(std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt", dir_ / "prog.nc");
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  // No temporary file is left behind in the folder.
  void expectNoTemporaryFiles(const fs::path& folder) {
    for (const auto& e : fs::directory_iterator(folder)) {
      EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
      EXPECT_NE(e.path().extension(), ".partial") << e.path();
    }
  }
  fs::path dir_;
};

const std::string kNoSpaceEn =
    ": cannot write the file: there is no space for it (the disk is full, or the file is over the size allowed); an "
    "existing file of that name is left unchanged\n";
const std::string kNoSpaceTh =
    ": บันทึกไฟล์ไม่ได้ เพราะไม่มีที่ว่างพอ (ดิสก์เต็ม หรือไฟล์ใหญ่เกินขนาดที่อนุญาต) ถ้ามีไฟล์ชื่อนี้อยู่แล้ว "
    "ไฟล์นั้นยังคงเดิม\n";

// Item 1: print --pdf on a full disk turned a good sheet into 0 bytes and exited 0.
TEST_F(CliWrite, PrintPdfOnAFullDiskKeepsTheOldSheet) {
  ASSERT_EQ(cli(dir_, "print prog.nc --pdf sheet.pdf").exitCode, 0);
  const std::string good = slurp(dir_ / "sheet.pdf");
  ASSERT_GT(good.size(), 20000u);
  CliRun full = cli(dir_, "print prog.nc --pdf sheet.pdf --lang en", 8);  // 4 KB
  EXPECT_EQ(full.exitCode, 2);
  EXPECT_EQ(kluengLines(full.err), "sheet.pdf: error F109: sheet.pdf" + kNoSpaceEn);
  EXPECT_TRUE(sameBytes(dir_ / "sheet.pdf", good));
  full = cli(dir_, "print prog.nc --pdf sheet.pdf --lang th", 8);
  EXPECT_EQ(full.exitCode, 2);
  EXPECT_EQ(kluengLines(full.err), "sheet.pdf: ข้อผิดพลาด F109: sheet.pdf" + kNoSpaceTh);
  EXPECT_TRUE(sameBytes(dir_ / "sheet.pdf", good));
  expectNoTemporaryFiles(dir_);
}

// Item 1: class --pdf left 4 KB of a report and exited 0; the CSV the same way.
TEST_F(CliWrite, ClassOutputsOnAFullDiskKeepTheOldFiles) {
  fs::create_directories(dir_ / "cls");
  fs::copy_file(dir_ / "prog.nc", dir_ / "cls" / "ref.nc");
  fs::copy_file(dir_ / "prog.nc", dir_ / "cls" / "somchai.nc");
  const std::string oldPdf = "%PDF-1.4 the old grades\n", oldCsv = std::string(3000, 'c');
  put(dir_ / "grades.pdf", oldPdf);
  put(dir_ / "grades.csv", oldCsv);
  CliRun full = cli(dir_, "class cls --reference cls/ref.nc --pdf grades.pdf", 4);  // 2 KB
  EXPECT_EQ(full.exitCode, 2) << full.err;
  EXPECT_NE(full.err.find("grades.pdf: error F109: grades.pdf" + kNoSpaceEn), std::string::npos) << full.err;
  EXPECT_TRUE(sameBytes(dir_ / "grades.pdf", oldPdf));
  // The CSV of many students over the limit: 2 KB of 40 rows.
  for (int i = 0; i < 40; ++i) fs::copy_file(dir_ / "prog.nc", dir_ / "cls" / ("student-" + std::to_string(i) + ".nc"));
  full = cli(dir_, "class cls --reference cls/ref.nc --csv grades.csv --lang th", 4);
  EXPECT_EQ(full.exitCode, 2);
  EXPECT_NE(full.err.find("grades.csv: ข้อผิดพลาด F109: grades.csv" + kNoSpaceTh), std::string::npos) << full.err;
  EXPECT_TRUE(sameBytes(dir_ / "grades.csv", oldCsv));
  expectNoTemporaryFiles(dir_);
}

// Item 1: every writer of simulate and generate, the same way.
TEST_F(CliWrite, SimulateAndGenerateOnAFullDiskKeepTheOldFiles) {
  const std::string old = "old output\n";
  for (const char* name : {"t.csv", "p.png", "s.svg", "d.dxf", "gen.nc"}) put(dir_ / name, old);
  CliRun full = cli(dir_, "simulate prog.nc --trace t.csv", 2);  // 1 KB
  EXPECT_EQ(full.exitCode, 2);
  EXPECT_EQ(kluengLines(full.err), "t.csv: error F109: t.csv" + kNoSpaceEn);
  full = cli(dir_, "simulate prog.nc --png p.png --svg s.svg --dxf d.dxf", 1);  // 512 bytes
  EXPECT_EQ(full.exitCode, 2);
  for (const char* name : {"p.png", "s.svg", "d.dxf"}) EXPECT_NE(full.err.find(name), std::string::npos) << full.err;
  full = cli(dir_, "generate '" + std::string(KLUENG_SOURCE_DIR) + "/resources/parts/step-shaft.json' -o gen.nc", 2);
  EXPECT_EQ(full.exitCode, 2);
  EXPECT_EQ(kluengLines(full.err), "gen.nc: error F109: gen.nc" + kNoSpaceEn);
  for (const char* name : {"t.csv", "p.png", "s.svg", "d.dxf", "gen.nc"}) EXPECT_TRUE(sameBytes(dir_ / name, old));
  expectNoTemporaryFiles(dir_);
}

const std::string kReadOnlyEn =
    ": the file is read-only, so it was not replaced; write to another file, or make it writable first\n";
const std::string kReadOnlyTh = ": ไฟล์นี้เป็นแบบอ่านอย่างเดียว จึงไม่ได้เขียนทับ ให้บันทึกเป็นไฟล์อื่น หรือเปลี่ยนให้เขียนได้ก่อน\n";

// Item 2: a read-only output (0444) is refused, root included, and keeps its bytes.
TEST_F(CliWrite, AReadOnlyOutputIsRefused) {
  const std::string old = "G21 (keep me)\n";
  put(dir_ / "gen.nc", old);
  put(dir_ / "sheet.pdf", old);
  put(dir_ / "t.csv", old);
  for (const char* name : {"gen.nc", "sheet.pdf", "t.csv"})
    fs::permissions(dir_ / name, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  CliRun r = cli(dir_, "generate '" + std::string(KLUENG_SOURCE_DIR) + "/resources/parts/step-shaft.json' -o gen.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), "gen.nc: error F119: gen.nc" + kReadOnlyEn);
  r = cli(dir_, "print prog.nc --pdf sheet.pdf --lang th");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), "sheet.pdf: ข้อผิดพลาด F119: sheet.pdf" + kReadOnlyTh);
  r = cli(dir_, "simulate prog.nc --trace t.csv");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), "t.csv: error F119: t.csv" + kReadOnlyEn);
  for (const char* name : {"gen.nc", "sheet.pdf", "t.csv"}) EXPECT_TRUE(sameBytes(dir_ / name, old));
  expectNoTemporaryFiles(dir_);
}

std::string clashEn(const std::string& output, const std::string& input) {
  return output + ": error F126: " + output + ": this output is the input file " + input +
         "; writing it would destroy that file, so choose another name\n";
}

// Item 3: an output naming an input is refused before anything is written, as a compiler does.
TEST_F(CliWrite, AnOutputThatIsAnInputIsRefused) {
  const std::string program = slurp(dir_ / "prog.nc");
  CliRun r = cli(dir_, "simulate prog.nc --trace prog.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), clashEn("prog.nc", "prog.nc"));
  r = cli(dir_, "simulate prog.nc --svg s.svg --png ./sub/../prog.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), clashEn("./sub/../prog.nc", "prog.nc"));
  EXPECT_FALSE(fs::exists(dir_ / "s.svg"));  // refused before the run: nothing written
  r = cli(dir_, "print prog.nc --pdf '" + (dir_ / "prog.nc").string() + "' --lang th");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), (dir_ / "prog.nc").string() + ": ข้อผิดพลาด F126: " + (dir_ / "prog.nc").string() +
                                    ": ไฟล์ผลลัพธ์นี้คือไฟล์ขาเข้า prog.nc ถ้าเขียนลงไปไฟล์นั้นจะหายไป จึงให้ตั้งชื่อไฟล์อื่น\n");
  EXPECT_TRUE(sameBytes(dir_ / "prog.nc", program));

  // class: the reference and every graded file in the folder.
  fs::create_directories(dir_ / "cls");
  fs::copy_file(dir_ / "prog.nc", dir_ / "cls" / "ref.nc");
  fs::copy_file(dir_ / "prog.nc", dir_ / "cls" / "somchai.nc");
  r = cli(dir_, "class cls --reference cls/ref.nc --csv cls/ref.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), clashEn("cls/ref.nc", "cls/ref.nc"));
  r = cli(dir_, "class cls --reference cls/ref.nc --pdf cls/somchai.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), clashEn("cls/somchai.nc", "cls/somchai.nc"));
  EXPECT_TRUE(sameBytes(dir_ / "cls" / "ref.nc", program));
  EXPECT_TRUE(sameBytes(dir_ / "cls" / "somchai.nc", program));

  // generate: the part file.
  fs::copy_file(std::string(KLUENG_SOURCE_DIR) + "/resources/parts/step-shaft.json", dir_ / "part.json");
  const std::string part = slurp(dir_ / "part.json");
  r = cli(dir_, "generate part.json -o part.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_EQ(kluengLines(r.err), clashEn("part.json", "part.json"));
  EXPECT_TRUE(sameBytes(dir_ / "part.json", part));
}

// Item 3: a subprogram file the run reads from the folder is an input too.
TEST_F(CliWrite, ASubprogramFileIsAnInputToo) {
  put(dir_ / "main.nc", "O0010\nG21 G99\nT0101\nG97 S800 M03\nG00 X44. Z-8.\nM98 P1000\nG00 X100. Z100.\nM30\n");
  const std::string groove = "O1000\nG01 X36. F0.05\nG00 X44.\nM99\n";
  put(dir_ / "O1000.nc", groove);
  const CliRun r = cli(dir_, "simulate main.nc --stock 40x100 --trace O1000.nc");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("O1000.nc: error F126: O1000.nc: this output is the input file"), std::string::npos) << r.err;
  EXPECT_TRUE(sameBytes(dir_ / "O1000.nc", groove));
}

// What must still work: a new output, and an output replacing an old one.
TEST_F(CliWrite, OrdinaryOutputsStillReplaceOldOnes) {
  put(dir_ / "t.csv", "old\n");
  const CliRun r = cli(dir_, "simulate prog.nc --trace t.csv --svg s.svg");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "t.csv").rfind("kind,line,", 0), 0u);
  EXPECT_TRUE(fs::exists(dir_ / "s.svg"));
  expectNoTemporaryFiles(dir_);
}

}  // namespace

}  // namespace cli_write_test
