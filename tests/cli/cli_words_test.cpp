// Issue 42 item 6: false alarms and wrong words. Each message says what is really
// wrong, in our words and in real Thai: a broken machine file named by --machine,
// a part file that is no JSON, a part field, a design `generate` would turn into a
// program its own check refuses, a bare G65, a path too long to open.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../scratch_folders.h"
#include "cli_shell.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_words_test {

namespace {

namespace fs = std::filesystem;

const std::string kCli = std::getenv("KLUENG_CLI_UNDER_TEST") ? std::getenv("KLUENG_CLI_UNDER_TEST") : KLUENG_CLI_PATH;

const auto* const kCleanup = klueng::test::removeScratchFoldersAtExit({"klueng_cli_words-"});

constexpr auto quote = &klueng::test::shellQuote;

// klueng-cli ARGS (stdout and stderr together); the exit status.
int run(const std::string& args, std::string& out) {
  return klueng::test::runShell(klueng::test::cliCommand(kCli, 60) + " " + args, out);
}

fs::path scratch() {
  const fs::path p = fs::temp_directory_path() / ("klueng_cli_words-" + std::to_string(::getpid()));
  fs::create_directories(p);
  return p;
}

std::string put(const std::string& name, const std::string& text) {
  const fs::path p = scratch() / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

const std::string kConfig = std::string(" --config ") + quote(KLUENG_SOURCE_DIR);

}  // namespace

// `--machine deep` with a broken machines/deep.machine: its own errors, not "no such machine".
TEST(CliWords, ABrokenMachineOfTheConfigFolderSaysItsOwnErrors) {
  const fs::path config = scratch() / "config";
  fs::create_directories(config / "machines");
  for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"})
    fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, config / f, fs::copy_options::overwrite_existing);
  std::ofstream(config / "machines" / "deep.machine") << "base = fanuc\nid = deep\nfamily = fanuk\n";
  const std::string program = put("p.nc", "G21\nG00 X10. Z2.\nM30\n");
  std::string out;
  EXPECT_EQ(run("check --machine deep --config " + quote(config.string()) + " " + quote(program), out), 2) << out;
  EXPECT_EQ(out.find("no such machine"), std::string::npos) << out;
  EXPECT_NE(out.find("deep.machine:3:10: error F200: "), std::string::npos) << out;
}

// F180 and F182 in our words, Thai all through.
TEST(CliWords, PartFileMessagesAreOursInBothLanguages) {
  const std::string broken = put("broken.json", "{ \"name\": \"x\", \"stock\": { \"diameter\": 50 \n");
  std::string out;
  EXPECT_EQ(run("generate " + quote(broken) + " -o " + quote((scratch() / "b.nc").string()) + kConfig, out), 2) << out;
  EXPECT_NE(out.find("error F180: " + broken + " is not a part file: the text ends before the JSON is complete"),
            std::string::npos)
      << out;
  for (const char* library : {"parse_error", "syntax error", "json.exception", "unexpected end"})
    EXPECT_EQ(out.find(library), std::string::npos) << library << "\n" << out;
  const std::string junk = put("junk.json", "{ \"name\": nope }\n");
  EXPECT_EQ(
      run("generate " + quote(junk) + " -o " + quote((scratch() / "j.nc").string()) + " --lang th" + kConfig, out), 2)
      << out;
  EXPECT_NE(out.find("ไม่ใช่ไฟล์ชิ้นงาน: JSON ไม่ถูกต้องที่ตำแหน่งนี้"), std::string::npos) << out;
  EXPECT_EQ(out.find("syntax"), std::string::npos) << out;

  const std::string bad = put("bad.json", "{ \"stock\": { \"diameter\": -5, \"length\": 100 }, \"outside\": [] }\n");
  EXPECT_EQ(run("generate " + quote(bad) + " -o " + quote((scratch() / "x.nc").string()) + " --lang th" + kConfig, out),
            2)
      << out;
  EXPECT_NE(out.find("ค่า \"stock.diameter\" ต้องเป็นตัวเลขเป็นมิลลิเมตรที่มากกว่า 0 (ไม่เกิน 2000)"), std::string::npos) << out;
  EXPECT_EQ(out.find("a number of millimetres"), std::string::npos) << out;
}

// `generate` refuses at the input what would make a program its own check refuses.
TEST(CliWords, GenerateRefusesWhatItsOwnCheckWouldRefuse) {
  const std::string huge = put(
      "huge.json",
      "{ \"stock\": { \"diameter\": 10000, \"length\": 100 }, \"outside\": [ { \"cylinder\": 30, \"length\": 20 } ] "
      "}\n");
  const std::string nc = (scratch() / "huge.nc").string();
  std::string out;
  EXPECT_EQ(run("generate " + quote(huge) + " -o " + quote(nc) + kConfig, out), 2) << out;
  EXPECT_NE(out.find("\"stock.diameter\" must be a number of millimetres above 0 (at most 2000)"), std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(nc));

  const std::string name = put("name.json", "{ \"name\": \"" + std::string(10 * 1024 * 1024, 'N') +
                                                "\", \"stock\": { \"diameter\": 50, \"length\": 100 }, \"outside\": "
                                                "[ { \"cylinder\": 30, \"length\": 20 } ] }\n");
  EXPECT_EQ(run("generate " + quote(name) + " -o " + quote(nc) + kConfig, out), 2) << out.substr(0, 500);
  EXPECT_LT(out.size(), 4000u);
  EXPECT_NE(out.find("\"name\" must be a text of at most 200 characters"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(nc));

  // At the limits, the program generate writes passes its own check.
  const std::string big = put(
      "big.json", "{ \"name\": \"" + std::string(200, 'B') +
                      "\", \"stock\": { \"diameter\": 2000, \"length\": 5000 }, \"outside\": [ { \"cylinder\": 1990, "
                      "\"length\": 20 } ] }\n");
  ASSERT_EQ(run("generate " + quote(big) + " -o " + quote(nc) + kConfig, out), 0) << out;
  EXPECT_EQ(run("check " + quote(nc) + kConfig, out), 0) << out;
}

// A bare G65 names no program: the alarm says P is missing, not "program O?".
TEST(CliWords, ABareG65SaysThatPIsMissing) {
  const std::string program = put("g65.nc", "G21 G99\nG65\nM30\n");
  std::string out;
  EXPECT_EQ(run("simulate " + quote(program) + " --no-stock --no-persist" + kConfig, out), 1) << out;
  EXPECT_EQ(out.find("O?"), std::string::npos) << out;
  EXPECT_NE(out.find(":2:1: error E419: G65 without P: the block names no program to call"), std::string::npos) << out;
  EXPECT_EQ(run("check " + quote(program) + " --stock 50x100" + kConfig + " --lang th", out), 1) << out;
  EXPECT_NE(out.find("G65 ไม่มี P: บล็อกนี้ไม่ได้ระบุโปรแกรมที่จะเรียก"), std::string::npos) << out;
}

// A path of 5,000 characters that is there: the real reason, not "no such file".
TEST(CliWords, APathTooLongToOpenSaysSo) {
  const std::string folder(200, 'd');
  std::string shell = "cd " + quote(scratch().string());
  for (int i = 0; i < 25; ++i) shell += " && mkdir -p " + folder + " && cd " + folder;
  shell += " && cp " + quote(std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt") + " p.nc";
  ASSERT_EQ(std::system(("bash -c " + quote(shell)).c_str()), 0);
  std::string path = scratch().string();
  for (int i = 0; i < 25; ++i) path += "/" + folder;
  path += "/p.nc";
  ASSERT_GT(path.size(), 5000u);
  std::string out;
  EXPECT_EQ(run("check " + quote(path) + kConfig, out), 2) << out.substr(0, 300);
  EXPECT_EQ(out.find("no such file"), std::string::npos) << out.substr(0, 300);
  EXPECT_NE(out.find("error F176: "), std::string::npos) << out.substr(0, 300);
  EXPECT_NE(out.find("the path is too long for the system to open (" + std::to_string(path.size()) + " characters"),
            std::string::npos)
      << out.substr(0, 300);
  // fs::remove_all cannot reach so deep a path: rm works folder by folder.
  EXPECT_EQ(std::system(("rm -rf " + quote((scratch() / folder).string())).c_str()), 0);
}

// A 10 MB tool name made a 10 MB message: the message is shortened, and says so.
TEST(CliWords, AHugeToolNameMakesAShortMessage) {
  const fs::path config = scratch() / "long-name";
  fs::create_directories(config);
  for (const char* f : {"offset.cfg", "machine.cfg"})
    fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, config / f, fs::copy_options::overwrite_existing);
  std::ofstream(config / "tools.cfg") << std::string(10 * 1024 * 1024, 'T') << ".bmp\n";
  const std::string program = put("t.nc", "G21\nG00 X10. Z2.\nM30\n");
  std::string out;
  EXPECT_EQ(run("check --config " + quote(config.string()) + " " + quote(program), out), 2) << out.substr(0, 500);
  EXPECT_LT(out.size(), 20000u);
  EXPECT_NE(out.find("characters left out"), std::string::npos) << out.substr(0, 3000);
}

// A tool picture of 20000 x 20000 pixels: the T word's error says why the picture cannot be
// used (E311, with the limit), not "tool 01 has no bitmap" (E305). The GUI shows the same Job.
TEST(CliWords, AToolPictureTooLargeSaysWhy) {
  const fs::path config = scratch() / "big-picture";
  fs::create_directories(config / "resources" / "tools");
  for (const char* f : {"tools.cfg", "offset.cfg", "machine.cfg"})
    fs::copy_file(fs::path(KLUENG_SOURCE_DIR) / f, config / f, fs::copy_options::overwrite_existing);
  for (const fs::directory_entry& e : fs::directory_iterator(fs::path(KLUENG_SOURCE_DIR) / "resources" / "tools"))
    if (e.is_regular_file())
      fs::copy_file(e.path(), config / "resources" / "tools" / e.path().filename(),
                    fs::copy_options::overwrite_existing);
  // A BMP header that says 20000 x 20000 pixels, 24 bits.
  std::string bmp = "BM";
  const auto u32 = [&bmp](unsigned v) {
    for (int i = 0; i < 4; ++i) bmp += static_cast<char>((v >> (8 * i)) & 0xFF);
  };
  const auto u16 = [&bmp](unsigned v) {
    bmp += static_cast<char>(v & 0xFF);
    bmp += static_cast<char>((v >> 8) & 0xFF);
  };
  u32(54), u16(0), u16(0), u32(54), u32(40), u32(20000), u32(20000), u16(1), u16(24);
  for (int i = 0; i < 6; ++i) u32(0);
  std::ofstream(config / "resources" / "tools" / "01-outside-turning.bmp", std::ios::binary) << bmp;
  std::string out;
  run("check " + quote(std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt") + " --config " + quote(config.string()),
      out);
  EXPECT_EQ(out.find("E305"), std::string::npos) << out;
  EXPECT_NE(out.find("01-step-shaft.txt:10:5: error E311: T0101: tool 01's bitmap in tools.cfg cannot be used "
                     "(resources/tools/01-outside-turning.bmp: image size 20000 × 20000 pixels is not allowed (1 to "
                     "4096 pixels each way))"),
            std::string::npos)
      << out;
}

}  // namespace cli_words_test
