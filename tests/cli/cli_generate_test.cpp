// Issue 29 item 6: klueng-cli generate bounds what it reads and what it writes.
// A part file over 16 MB (a 90 MB drawing took 16 s and 1.1 GB; /dev/zero ran
// out of memory after 2 GB) is refused before it is read, with F103 naming the
// file (exit 2); a design too long for the dialect's block numbers is numbered
// more closely, or refused with E519 (exit 1) when even N1, N2, ... would not
// fit, and nothing is written. English and Thai.
#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_generate_test {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exitCode = -1;
  std::string err;
};

// klueng-cli ARGS in `dir`, stderr captured (stdout dropped).
CliRun cli(const fs::path& dir, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && env LC_ALL= LC_MESSAGES= LANG=C '" +
                              std::string(KLUENG_CLI_PATH) + "' " + args + " --config '" + KLUENG_SOURCE_DIR +
                              "' 2>&1 >/dev/null";
  CliRun r;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.err.append(buf, n);
  const int status = ::pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A turnable design of `steps` cylinders 0.01 mm long, each a little wider than the last.
std::string manySteps(int steps) {
  std::ostringstream s;
  s << R"({"name": "Many steps", "material": "aluminium", "stock": {"diameter": 60, "length": 130}, "outside": [)";
  for (int k = 0; k < steps; ++k)
    s << (k ? ", " : "") << R"({"cylinder": )" << 10.0 + k * 0.004 << R"(, "length": 0.01})";
  s << "]}\n";
  return s.str();
}

class CliGenerateLimits : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("klueng_cli_generate_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
            "-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path dir_;
};

TEST_F(CliGenerateLimits, ADeviceThatNeverEndsIsRefusedAtTheLimit) {
  CliRun r = cli(dir_, "generate /dev/zero -o out.nc");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err.rfind("/dev/zero: error F103: /dev/zero: the file is ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(" bytes; files over 16 MB are refused\n"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "out.nc"));
  r = cli(dir_, "generate /dev/zero -o out.nc --lang th");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero: ข้อผิดพลาด F103: /dev/zero: ไฟล์มีขนาด "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" ไบต์ ไม่รับไฟล์ที่ใหญ่กว่า 16 MB\n"), std::string::npos) << r.err;
}

TEST_F(CliGenerateLimits, AHugeDrawingIsRefusedBeforeItIsRead) {
  { std::ofstream(dir_ / "big.dxf") << "0\nSECTION\n"; }
  fs::resize_file(dir_ / "big.dxf", 90u * 1024u * 1024u);  // sparse: 90 MB on paper
  const CliRun r = cli(dir_, "generate big.dxf -o out.nc");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_EQ(r.err, "big.dxf: error F103: big.dxf: the file is 94371840 bytes; files over 16 MB are refused\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.nc"));
  // A missing part file is told in the same words as a missing program.
  const CliRun missing = cli(dir_, "generate none.json -o out.nc");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_EQ(missing.err, "none.json: error F101: none.json: no such file\n");
}

TEST_F(CliGenerateLimits, ALongDesignIsNumberedWithinTheDialectsBlockNumbers) {
  { std::ofstream(dir_ / "steps.json") << manySteps(10'500); }
  // Fanuc: 21,000 blocks at N10 steps would pass N99999; numbered closer, the program checks clean.
  CliRun r = cli(dir_, "generate steps.json -o fanuc.nc");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  r = cli(dir_, "check fanuc.nc");
  EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.find("E116"), std::string::npos) << r.err.substr(0, 2000);
  // Classic numbers only N1 to N9999: refused, nothing written.
  r = cli(dir_, "generate steps.json -o classic.nc --dialect classic");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_EQ(r.err,
            "steps.json: error E519: The program would have 21065 blocks, but Rook classic (1999 rules) numbers "
            "blocks only from N1 to N9999: it is not written; turn the part in fewer steps\n");
  EXPECT_FALSE(fs::exists(dir_ / "classic.nc"));
  r = cli(dir_, "generate steps.json -o classic.nc --dialect classic --lang th");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("steps.json: ข้อผิดพลาด E519: โปรแกรมจะมี 21065 บล็อก แต่ รุก คลาสสิก (กฎปี 2542) "
                       "ใช้หมายเลขบล็อกได้เพียง N1 ถึง N9999"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "classic.nc"));
}

// Issue 27: --machine writes the program in the machine's G-code system and names
// the machine at its head; check then runs it on that machine without being told.
TEST_F(CliGenerateLimits, AMachineGetsItsOwnNumbers) {
  const CliRun r = cli(dir_, "generate '" + std::string(KLUENG_SOURCE_DIR) +
                                 "/resources/parts/step-shaft.json' -o out.nc --machine romi-gl240m");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir_ / "out.nc");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("(MACHINE: romi-gl240m)"), std::string::npos) << text;
  EXPECT_NE(text.find(" G92 S"), std::string::npos) << text;
  EXPECT_NE(text.find(" G95"), std::string::npos) << text;
  EXPECT_EQ(text.find("G50"), std::string::npos) << text;
  EXPECT_EQ(cli(dir_, "check out.nc").exitCode, 0);
  EXPECT_EQ(cli(dir_, "check --dialect fanuc out.nc").exitCode, 1);  // G95 is no system-A code
  EXPECT_EQ(cli(dir_, "generate x.json -o y.nc --machine no-such-lathe").exitCode, 2);
}

}  // namespace
}  // namespace cli_generate_test
