// Runs the real klueng-cli binary on real files and checks its output and exit status.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "klueng/core/io/image.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_check_test {

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kCli = KLUENG_CLI_PATH;
const std::string kSamples = KLUENG_SAMPLES_DIR;
const std::string kShipped = KLUENG_SOURCE_DIR;

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct CliRun {
  int exitCode = -1;
  std::string out;
};

// Runs `klueng-cli <args>` under a neutral English locale unless `env` says otherwise.
CliRun runCli(const std::string& args, const std::string& env = "LC_ALL= LC_MESSAGES= LANG=C") {
  const std::string command = "env " + env + " " + quote(kCli) + " " + args + " 2>/dev/null";
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// As runCli, with what the program writes to stderr in `out` too.
CliRun runCliWithErrors(const std::string& args, const std::string& env = "LC_ALL= LC_MESSAGES= LANG=C") {
  const std::string command = "env " + env + " " + quote(kCli) + " " + args + " 2>&1";
  CliRun run;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[65536];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

struct Line {
  std::string file;
  int line = 0;
  int column = 0;
  std::string severity;
  std::string code;
  std::string message;
};

// FILE:LINE:COL: severity CODE: message
std::vector<Line> parseGccLines(const std::string& out) {
  static const std::regex re(R"(^(.*):(\d+):(\d+): (\S+) ([A-Z]\d{3}): (.*)$)");
  std::vector<Line> lines;
  std::istringstream in(out);
  std::string text;
  while (std::getline(in, text)) {
    std::smatch m;
    if (!std::regex_match(text, m, re)) continue;
    lines.push_back({m[1], std::stoi(m[2]), std::stoi(m[3]), m[4], m[5], m[6]});
  }
  return lines;
}

class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("klueng-cli-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& bytes) const {
    const std::string p = file(name);
    fs::create_directories(fs::path(p).parent_path());
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  // A config folder: the shipped one with some files replaced.
  std::string config(const std::map<std::string, std::string>& replaced) const {
    const std::string dir = file("config");
    fs::create_directories(dir);
    for (const char* name : {"tools.cfg", "offset.cfg", "machine.cfg"})
      fs::copy_file(kShipped + "/" + name, dir + "/" + name, fs::copy_options::overwrite_existing);
    fs::create_directories(dir + "/resources");
    fs::copy(kShipped + "/resources/tools", dir + "/resources/tools",
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    for (const auto& [name, text] : replaced) {
      if (text == "<delete>")
        fs::remove(dir + "/" + name);
      else
        std::ofstream(dir + "/" + name, std::ios::binary) << text;
    }
    return dir;
  }

 private:
  fs::path path_;
};

const std::string kHeader = "Job\nPart\nSteel\n150\n1100\nMe\n";

// ------------------------------------------------------------------ a tiny JSON reader

struct Json;
using JsonObject = std::map<std::string, Json>;
using JsonArray = std::vector<Json>;
struct Json {
  std::variant<std::nullptr_t, bool, double, std::string, JsonArray, JsonObject> v;
};

class JsonReader {
 public:
  explicit JsonReader(const std::string& s) : s_(s) {}
  // Throws std::runtime_error on any syntax error, including trailing text.
  Json document() {
    Json j = value();
    space();
    if (i_ != s_.size()) fail("trailing text");
    return j;
  }

 private:
  [[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + " at byte " + std::to_string(i_)); }
  void space() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
  }
  void expect(char c) {
    space();
    if (i_ >= s_.size() || s_[i_] != c) fail(std::string("expected ") + c);
    ++i_;
  }
  Json value() {
    space();
    if (i_ >= s_.size()) fail("unexpected end");
    const char c = s_[i_];
    if (c == '{') return object();
    if (c == '[') return array();
    if (c == '"') return Json{string()};
    if (s_.compare(i_, 4, "true") == 0) return i_ += 4, Json{true};
    if (s_.compare(i_, 5, "false") == 0) return i_ += 5, Json{false};
    if (s_.compare(i_, 4, "null") == 0) return i_ += 4, Json{nullptr};
    std::size_t used = 0;
    const double d = std::stod(s_.substr(i_, 32), &used);
    if (used == 0) fail("bad value");
    i_ += used;
    return Json{d};
  }
  Json object() {
    JsonObject o;
    expect('{');
    space();
    if (s_[i_] == '}') return ++i_, Json{o};
    for (;;) {
      space();
      const std::string key = string();
      expect(':');
      o[key] = value();
      space();
      if (s_[i_] == ',') {
        ++i_;
        continue;
      }
      expect('}');
      return Json{o};
    }
  }
  Json array() {
    JsonArray a;
    expect('[');
    space();
    if (s_[i_] == ']') return ++i_, Json{a};
    for (;;) {
      a.push_back(value());
      space();
      if (s_[i_] == ',') {
        ++i_;
        continue;
      }
      expect(']');
      return Json{a};
    }
  }
  std::string string() {
    if (s_[i_] != '"') fail("expected string");
    ++i_;
    std::string out;
    while (i_ < s_.size() && s_[i_] != '"') {
      const auto c = static_cast<unsigned char>(s_[i_]);
      if (c < 0x20) fail("raw control character in string");
      if (c != '\\') {
        out += s_[i_++];
        continue;
      }
      const char e = s_.at(++i_);
      ++i_;
      switch (e) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          const unsigned cp = static_cast<unsigned>(std::stoul(s_.substr(i_, 4), nullptr, 16));
          i_ += 4;
          if (cp < 0x80)
            out += static_cast<char>(cp);
          else if (cp < 0x800)
            out += static_cast<char>(0xC0 | (cp >> 6)), out += static_cast<char>(0x80 | (cp & 0x3F));
          else
            out += static_cast<char>(0xE0 | (cp >> 12)), out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F)),
                out += static_cast<char>(0x80 | (cp & 0x3F));
          break;
        }
        default: fail("bad escape");
      }
    }
    if (i_ >= s_.size()) fail("unterminated string");
    ++i_;
    return out;
  }
  const std::string& s_;
  std::size_t i_ = 0;
};

// ------------------------------------------------------------------ samples

TEST(CliCheck, Sample04ClassicReportsEveryBrokenLineAndNoOther) {
  const CliRun run = runCli("check --dialect classic " + quote(kSamples + "/04-grammar-errors.txt"));
  EXPECT_EQ(run.exitCode, 1);
  const std::vector<Line> lines = parseGccLines(run.out);
  ASSERT_FALSE(lines.empty()) << run.out;
  std::set<int> errorLines;
  for (const Line& l : lines) {
    EXPECT_EQ(l.file, kSamples + "/04-grammar-errors.txt");
    EXPECT_GE(l.column, 1);
    if (l.severity == "error") errorLines.insert(l.line);
  }
  // N30 is file line 11 (6 header lines, O0004, N10, N15, N20) ... N230 is line 30.
  for (int fileLine = 11; fileLine <= 30; ++fileLine)
    EXPECT_TRUE(errorLines.count(fileLine)) << "no error on file line " << fileLine << "\n" << run.out;
  for (int clean : {7, 8, 9, 10, 31})
    EXPECT_FALSE(errorLines.count(clean)) << "unexpected error on file line " << clean << "\n" << run.out;
  // Every output line is a diagnostic.
  EXPECT_EQ(static_cast<std::size_t>(std::count(run.out.begin(), run.out.end(), '\n')), lines.size());
}

TEST(CliCheck, Sample04ClassicPointsAtTheOffendingWord) {
  const CliRun run = runCli("check --dialect classic " + quote(kSamples + "/04-grammar-errors.txt"));
  const std::vector<Line> lines = parseGccLines(run.out);
  const auto has = [&](int line, int column, const std::string& code) {
    return std::any_of(lines.begin(), lines.end(),
                       [&](const Line& l) { return l.line == line && l.column == column && l.code == code; });
  };
  EXPECT_TRUE(has(11, 14, "E201")) << run.out;  // N30 ... Y5.
  EXPECT_TRUE(has(12, 14, "E210")) << run.out;  // N40 ... U2.
  EXPECT_TRUE(has(30, 6, "E112")) << run.out;   // N230 F-0.2
}

TEST(CliCheck, Sample04FanucAcceptsG98WithOtherWords) {
  const CliRun run = runCli("check --dialect fanuc " + quote(kSamples + "/04-grammar-errors.txt"));
  EXPECT_EQ(run.exitCode, 1);
  for (const Line& l : parseGccLines(run.out))
    if (l.line == 19) {
      EXPECT_NE(l.severity, "error") << "N110 is legal in the Fanuc dialect: " << l.message;
    }
}

class CleanSample : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(CleanSample, HasNoDiagnosticsAndExitsZero) {
  const auto [name, dialect] = GetParam();
  const CliRun run = runCli(std::string("check --dialect ") + dialect + " " + quote(kSamples + "/" + name));
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_EQ(run.out, "");
}

INSTANTIATE_TEST_SUITE_P(Samples, CleanSample,
                         ::testing::Combine(::testing::Values("01-step-shaft.txt", "02-thread.txt",
                                                              "05-runtime-alarms.txt"),
                                            ::testing::Values("fanuc", "classic")),
                         [](const auto& info) {
                           std::string n =
                               std::string(std::get<0>(info.param)).substr(0, 2) + "_" + std::get<1>(info.param);
                           return "sample" + n;
                         });

// ------------------------------------------------------------------ exit codes and options

TEST(CliCheck, MissingFileExitsTwoAndSaysSo) {
  const CliRun run = runCli("check /no/such/program.txt");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_EQ(run.out, "/no/such/program.txt: error F101: /no/such/program.txt: no such file\n");
}

TEST(CliCheck, UnreadableFileWinsOverErrorsButEveryFileIsStillChecked) {
  const CliRun run = runCli("check --dialect classic " + quote(kSamples + "/04-grammar-errors.txt") + " /no/such.txt");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_THAT(run.out, HasSubstr("04-grammar-errors.txt:11:14: error E201"));
  EXPECT_THAT(run.out, HasSubstr("/no/such.txt: error F101"));
}

TEST(CliCheck, HelpOfEachCommandListsTheDialectsAndExitsZero) {
  for (const char* command : {"check --help", "simulate --help"}) {
    const auto r = runCli(command);
    EXPECT_EQ(r.exitCode, 0) << command;
    EXPECT_NE(r.out.find("--dialect fanuc|haas|classic"), std::string::npos) << command << "\n" << r.out;
    EXPECT_NE(r.out.find("--stock DxL[xBORE][in]"), std::string::npos) << command;
    EXPECT_NE(r.out.find("--tool N=ID"), std::string::npos) << command;
  }
}

TEST(CliCheck, UsageErrorsExitTwo) {
  EXPECT_EQ(runCli("check").exitCode, 2);
  EXPECT_EQ(runCli("check --lang de " + quote(kSamples + "/01-step-shaft.txt")).exitCode, 2);
  EXPECT_EQ(runCli("check --dialect okuma " + quote(kSamples + "/01-step-shaft.txt")).exitCode, 2);
  EXPECT_EQ(runCli("check --frobnicate " + quote(kSamples + "/01-step-shaft.txt")).exitCode, 2);
  EXPECT_EQ(runCli("check " + quote(kSamples + "/01-step-shaft.txt") + " --config").exitCode, 2);
  EXPECT_EQ(runCli("nosuchcommand").exitCode, 2);
}

TEST(CliCheck, OptionsTakeEqualsFormAndComeAnywhere) {
  const CliRun run = runCli(quote(kSamples + "/04-grammar-errors.txt") + " check --dialect=classic --lang=th");
  // "check" must be the first argument: here it is a file name, and the command is unknown.
  EXPECT_EQ(run.exitCode, 2);
  const CliRun ok = runCli("check " + quote(kSamples + "/04-grammar-errors.txt") + " --dialect=classic --lang=en");
  EXPECT_EQ(ok.exitCode, 1);
  EXPECT_THAT(ok.out, HasSubstr("error E207"));  // G98 alone: classic only
}

TEST(CliCheck, WarningsAloneExitZero) {
  TempDir dir;
  // M77 is a machine-specific M code: a warning in the Fanuc dialect.
  const std::string file = dir.write("warn.nc", "O0001\nM77\nM30\n");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_THAT(run.out, HasSubstr(file + ":2:1: warning "));
}

TEST(CliCheck, AFolderChecksTheProgramsInIt) {
  const CliRun run = runCli("check --summary " + quote(kSamples));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr("04-grammar-errors.txt:11:14: error E201"));
  EXPECT_THAT(run.out, HasSubstr("01-step-shaft.txt"));  // in the summary table
  EXPECT_THAT(run.out, Not(HasSubstr("README.md")));
}

// ------------------------------------------------------------------ language

TEST(CliCheck, LangThPrintsThai) {
  const CliRun run = runCli("check --lang th --dialect classic " + quote(kSamples + "/04-grammar-errors.txt"));
  EXPECT_EQ(run.exitCode, 1);
  const std::vector<Line> lines = parseGccLines(run.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0].severity, "ข้อผิดพลาด");
  EXPECT_THAT(lines[0].message, HasSubstr("อักขระ"));
}

TEST(CliCheck, LanguageFollowsTheLocale) {
  const std::string file = quote(kSamples + "/04-grammar-errors.txt") + " --dialect classic";
  EXPECT_THAT(runCli("check " + file, "LC_ALL= LC_MESSAGES= LANG=th_TH.UTF-8").out, HasSubstr("ข้อผิดพลาด"));
  EXPECT_THAT(runCli("check " + file, "LC_ALL= LC_MESSAGES=th_TH.UTF-8 LANG=C").out, HasSubstr("ข้อผิดพลาด"));
  EXPECT_THAT(runCli("check " + file, "LC_ALL=en_US.UTF-8 LANG=th_TH.UTF-8").out, Not(HasSubstr("ข้อผิดพลาด")));
  EXPECT_THAT(runCli("check --lang en " + file, "LC_ALL=th_TH.UTF-8").out, Not(HasSubstr("ข้อผิดพลาด")));
}

// ------------------------------------------------------------------ JSON

TEST(CliCheck, JsonIsOneArrayOfDiagnosticsForAllFiles) {
  const CliRun run = runCli("check --json --dialect classic " + quote(kSamples + "/04-grammar-errors.txt") + " " +
                            quote(kSamples + "/01-step-shaft.txt") + " /no/such.txt");
  EXPECT_EQ(run.exitCode, 2);
  Json doc;
  ASSERT_NO_THROW(doc = JsonReader(run.out).document()) << run.out;
  ASSERT_TRUE(std::holds_alternative<JsonArray>(doc.v));
  const JsonArray& items = std::get<JsonArray>(doc.v);
  ASSERT_GE(items.size(), 21u);
  std::set<std::string> files;
  for (const Json& item : items) {
    ASSERT_TRUE(std::holds_alternative<JsonObject>(item.v));
    const JsonObject& o = std::get<JsonObject>(item.v);
    ASSERT_EQ(o.size(), 6u);
    for (const char* key : {"file", "severity", "code", "message"})
      ASSERT_TRUE(o.count(key) && std::holds_alternative<std::string>(o.at(key).v)) << key;
    for (const char* key : {"line", "column"})
      ASSERT_TRUE(o.count(key) && std::holds_alternative<double>(o.at(key).v)) << key;
    const std::string severity = std::get<std::string>(o.at("severity").v);
    EXPECT_TRUE(severity == "error" || severity == "warning") << severity;
    files.insert(std::get<std::string>(o.at("file").v));
  }
  EXPECT_EQ(files, (std::set<std::string>{kSamples + "/04-grammar-errors.txt", "/no/such.txt"}));
  const JsonObject& first = std::get<JsonObject>(items[0].v);
  EXPECT_EQ(std::get<double>(first.at("line").v), 11.0);
  EXPECT_EQ(std::get<double>(first.at("column").v), 14.0);
  EXPECT_EQ(std::get<std::string>(first.at("code").v), "E201");
}

TEST(CliCheck, JsonOfACleanFileIsAnEmptyArray) {
  const CliRun run = runCli("check --json " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_EQ(run.out, "[]\n");
}

TEST(CliCheck, JsonEscapesQuotesBackslashesAndThai) {
  TempDir dir;
  const std::string file = dir.write("we\"ird\\name.nc", "O0001\nG01 X20. Y5. (ทดสอบ)\n");
  const CliRun run = runCli("check --json --lang th " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  Json doc;
  ASSERT_NO_THROW(doc = JsonReader(run.out).document()) << run.out;
  const JsonArray& items = std::get<JsonArray>(doc.v);
  ASSERT_EQ(items.size(), 1u) << run.out;
  const JsonObject& o = std::get<JsonObject>(items[0].v);
  EXPECT_EQ(std::get<std::string>(o.at("file").v), file);
  EXPECT_EQ(std::get<std::string>(o.at("severity").v), "error");  // always English for machines
  EXPECT_THAT(std::get<std::string>(o.at("message").v), HasSubstr("อักขระ Y"));
}

// ------------------------------------------------------------------ bad input

TEST(CliBadInput, EmptyFile) {
  TempDir dir;
  const std::string file = dir.write("empty.txt", "");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(run.out, file + ":1:1: error F105: " + file + ": the file is empty\n");
}

TEST(CliBadInput, BinaryFile) {
  TempDir dir;
  std::string bytes =
      "\x7f"
      "ELF\x02\x01\x01";
  bytes += std::string(64, '\0');
  for (int i = 0; i < 4096; ++i) bytes += static_cast<char>((i * 7919) & 0xFF);
  const std::string file = dir.write("program.exe", bytes);
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(run.out,
            file + ":1:8: error F104: " + file + ": this is a binary file (it contains a NUL byte), not text\n");
}

TEST(CliBadInput, TenMegabyteSingleLine) {
  TempDir dir;
  std::string big = "O0001\nG01 ";
  while (big.size() < 10u * 1024u * 1024u) big += "X1.Z2.";
  big += "\nM30\n";
  const std::string file = dir.write("huge.nc", big);
  const auto start = std::chrono::steady_clock::now();
  const CliRun run = runCli("check " + quote(file));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(run.exitCode, 1);
  const std::vector<Line> lines = parseGccLines(run.out);
  ASSERT_EQ(lines.size(), 1u) << run.out.substr(0, 2000);
  EXPECT_EQ(lines[0].line, 2);
  EXPECT_EQ(lines[0].code, "F106");
  EXPECT_THAT(lines[0].message, HasSubstr("too long"));
  EXPECT_LT(seconds, 20.0);  // a loose guard against pathological behaviour, not a benchmark
}

TEST(CliBadInput, FileOverSixtyFourMegabytesIsNotRead) {
  TempDir dir;
  const std::string file = dir.file("giant.nc");
  {
    std::ofstream out(file, std::ios::binary);
    out << "O0001\n";
    out.seekp(65 * 1024 * 1024);
    out << "\n";
  }
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_THAT(run.out, HasSubstr("error F103"));
  EXPECT_THAT(run.out, HasSubstr("64 MB"));
}

TEST(CliBadInput, InvalidUtf8IsReadAsTis620) {
  TempDir dir;
  // "(\xA1\xC5\xD6\xA7)" is "(กลึง)" in TIS-620; Y5. after it is at column 11 in characters.
  const std::string file = dir.write("tis.nc", "O0001\n(\xA1\xC5\xD6\xA7) G00 Y5.\nM30\n");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  const std::vector<Line> lines = parseGccLines(run.out);
  ASSERT_EQ(lines.size(), 1u) << run.out;
  EXPECT_EQ(lines[0].line, 2);
  EXPECT_EQ(lines[0].column, 12);
  EXPECT_EQ(lines[0].code, "E201");
}

TEST(CliBadInput, RandomInvalidUtf8DoesNotCrash) {
  TempDir dir;
  std::string bytes = kHeader + "G01 X10. ";
  for (int i = 0; i < 2000; ++i) bytes += static_cast<char>(0x80 + (i * 37) % 0x7F);
  bytes += "\n";
  const CliRun run = runCli("check " + quote(dir.write("junk.nc", bytes)));
  EXPECT_TRUE(run.exitCode == 0 || run.exitCode == 1) << run.exitCode;
}

TEST(CliBadInput, HeaderWithBadUnitDigitIsReadAsPlainGcode) {
  // SPEC 2 (ext): without sizes on lines 4 and 5 there is no header; a warning says why.
  TempDir dir;
  const std::string file = dir.write("unit.txt", "Job\nPart\nSteel\n250\n1100\nMe\nG00 X10.\n");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);  // "Job" is not G-code
  EXPECT_THAT(run.out,
              HasSubstr(file + ":4:1: warning F117: " + file +
                        ": read as a plain G-code file without a job header: line 4 ('250') is not a stock size"));
  const CliRun th = runCli("check --lang th " + quote(file));
  EXPECT_THAT(th.out, HasSubstr("ไม่มีส่วนหัวของงาน"));
}

TEST(CliBadInput, NegativeStockSizeIsRule13) {
  TempDir dir;
  const std::string file = dir.write("neg.txt", "Job\nPart\nSteel\n150\n1-20\nMe\nG00 X10.\n");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_EQ(run.out, file +
                         ":5:1: error E213: stock diameter and length must be greater than 0, not -20 "
                         "(written '1-20': unit digit, then the size)\n");
}

TEST(CliBadInput, MissingHeaderLines) {
  TempDir dir;
  const std::string file = dir.write("short.txt", "Job\nPart\nSteel\n150\n180");
  const CliRun run = runCli("check " + quote(file));
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_THAT(run.out, HasSubstr(file + ":5:4: error F110: "));
}

TEST(CliBadInput, FolderWithoutProgramsIsUnreadable) {
  TempDir dir;
  const CliRun run = runCli("check " + quote(dir.file("")));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_THAT(run.out, HasSubstr("error F102"));
}

// ------------------------------------------------------------------ machine files

TEST(CliConfig, ToolsCfgWithMissingLinesLeavesToolsWithoutBitmap) {
  TempDir dir;
  const std::string config = dir.config({{"tools.cfg",
                                          "resources/tools/01-outside-turning.bmp\n"
                                          "resources/tools/02-outside-left-hand.bmp\n"
                                          "resources/tools/03-threading-60.bmp\n"}});
  const std::string program = dir.write("t4.nc", "O0001\nT0101\nT0404\nM30\n");
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(program));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr(config + "/tools.cfg:3:1: error F120: "));
  EXPECT_THAT(run.out, HasSubstr("tools 04 to 08 have no bitmap"));
  EXPECT_THAT(run.out, HasSubstr(program + ":3:1: error E305: "));  // T0404: no bitmap
  EXPECT_THAT(run.out, Not(HasSubstr(program + ":2:")));            // T0101 is fine
}

TEST(CliConfig, ToolsCfgGarbageLineAndMissingBitmap) {
  TempDir dir;
  std::string tools = "resources/tools/01-outside-turning.bmp\n%%% garbage %%%\nresources/tools/gone.bmp\n";
  for (int i = 4; i <= 8; ++i) tools += "\n";
  const std::string config = dir.config({{"tools.cfg", tools}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/02-thread.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr(config + "/tools.cfg:2:1: error F122: "));
  EXPECT_THAT(run.out, HasSubstr(config + "/tools.cfg:3:1: error F121: "));
  // Sample 02 uses T0303, whose bitmap is gone.
  EXPECT_THAT(run.out, HasSubstr("02-thread.txt:17:5: error E311: T0303: tool 03's bitmap in tools.cfg cannot be used "
                                 "(resources/tools/gone.bmp: no such file)"));  // why, not "has no bitmap" (issue 42)
}

TEST(CliConfig, OffsetCfgGarbageAndExtraLines) {
  TempDir dir;
  std::string offsets = "0 0 0.8 3\n0 0 abc 4\n0 0 0 8 9\n";
  for (int i = 4; i <= 64; ++i) offsets += "0 0 0 0\n";  // rows 17-64 are optional, 64 the last
  offsets += "this line is too many\n";
  const std::string config = dir.config({{"offset.cfg", offsets}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  const std::string cfg = config + "/offset.cfg";
  EXPECT_THAT(run.out, HasSubstr(cfg + ":2:5: error F133: " + cfg + ": offset 02: 'abc' is not a number"));
  EXPECT_THAT(run.out, HasSubstr(cfg + ":3:9: error F132: "));
  EXPECT_THAT(run.out, HasSubstr(cfg + ":65:1: warning F107: "));
}

TEST(CliConfig, OffsetCfgExtraLinesAloneAreOnlyAWarning) {
  TempDir dir;
  std::string offsets;
  for (int i = 1; i <= 64; ++i) offsets += "0 0 0.4 3\n";
  const std::string config = dir.config({{"offset.cfg", offsets + "0 0 0 0\n"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_THAT(run.out, HasSubstr("warning F107"));
}

TEST(CliConfig, OffsetCfgMissingLines) {
  TempDir dir;
  const std::string config = dir.config({{"offset.cfg", "0 0 0.8 3\n"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr(config + "/offset.cfg:1:1: error F130: "));
}

TEST(CliConfig, MachineCfgUnknownKeyAndBadValue) {
  TempDir dir;
  const std::string config = dir.config({{"machine.cfg", "rapid_x = 4000\nturbo = 1\nrapid_z = fast\n"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr(config + "/machine.cfg:2:1: error F141: "));
  EXPECT_THAT(run.out, HasSubstr(config + "/machine.cfg:3:11: error F142: "));
}

TEST(CliConfig, MissingMachineCfgUsesDefaults) {
  TempDir dir;
  const std::string config = dir.config({{"machine.cfg", "<delete>"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 0) << run.out;
  EXPECT_EQ(run.out, "");
}

TEST(CliConfig, MissingToolsCfgIsUnreadable) {
  TempDir dir;
  const std::string config = dir.config({{"tools.cfg", "<delete>"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_THAT(run.out, HasSubstr(config + "/tools.cfg: error F101: "));
}

TEST(CliConfig, DamagedBitmapIsReportedAndItsToolHasNoBitmap) {
  TempDir dir;
  const std::string config = dir.config({{"resources/tools/01-outside-turning.bmp", "BM this is not a bitmap"}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr("01-outside-turning.bmp: error F15"));
  EXPECT_THAT(run.out, HasSubstr("01-step-shaft.txt:10:5: error E311: T0101: tool 01's bitmap in tools.cfg cannot be "
                                 "used (resources/tools/01-outside-turning.bmp: "));  // N20 T0101, and why
}

TEST(CliConfig, BinaryConfigFileDoesNotCrash) {
  TempDir dir;
  const std::string config = dir.config({{"offset.cfg", std::string("\x01\x02\x00\xFF", 4)}});
  const CliRun run = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(run.exitCode, 2);  // the setup has errors (issue 13: exit 2, not 1)
  EXPECT_THAT(run.out, HasSubstr("error F104"));
}

// Issue 29 item 10: a 4096 x 4096 tool bitmap was accepted by check and stopped the
// run with alarm A311 when the tool cut; it is a setup error at its tools.cfg line
// for check and simulate alike (exit 2), before any run.
TEST(CliConfig, ABitmapLargerThanAToolIsASetupErrorBeforeTheRun) {
  TempDir dir;
  const int side = 4096;
  klueng::core::io::RgbImage image{side, side,
                                   std::vector<std::uint32_t>(static_cast<std::size_t>(side) * side, 0xFFFFFF)};
  for (int y = side - 20; y < side; ++y)
    for (int x = 0; x < 20; ++x) image.pixels[static_cast<std::size_t>(y) * side + x] = 0xFF0000;
  const std::string config =
      dir.config({{"resources/tools/01-outside-turning.bmp", klueng::core::io::encodeBmp(image)}});
  const std::string expected =
      config + "/tools.cfg:1:1: error F139: " + config +
      "/tools.cfg: tool 01: the bitmap 'resources/tools/01-outside-turning.bmp' is 4096 x 4096 pixels; a tool "
      "bitmap may be at most 1000 x 1000 pixels (500 mm each way at 2 pixels per mm)\n";
  const CliRun check = runCli("check --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(check.exitCode, 2);
  EXPECT_THAT(check.out, HasSubstr(expected));
  const CliRun simulate =
      runCliWithErrors("simulate --config " + quote(config) + " " + quote(kSamples + "/01-step-shaft.txt"));
  EXPECT_EQ(simulate.exitCode, 2);
  EXPECT_THAT(simulate.out, HasSubstr(expected));
  EXPECT_THAT(simulate.out, Not(HasSubstr("A311")));
}

// ------------------------------------------------------------------ the command line in Thai

// Issue 29 item 10: under --lang th the usage, the command-line mistakes, the
// class and generate errors and the write failures were English.
TEST(CliLanguage, CommandLineMistakesAndTheUsageAreThaiUnderLangTh) {
  // A mistake before --lang is said in the language that follows it.
  const CliRun bogus = runCliWithErrors("check --bogus --lang th x.nc");
  EXPECT_EQ(bogus.exitCode, 2);
  EXPECT_EQ(bogus.out.substr(0, bogus.out.find('\n')), "klueng-cli check: ไม่รู้จักตัวเลือก '--bogus'");
  EXPECT_THAT(bogus.out, HasSubstr("\nวิธีใช้: klueng-cli check FILE|FOLDER..."));
  EXPECT_THAT(bogus.out, HasSubstr("หน่วยเมื่อเปิดเครื่อง ก่อน G20/G21 ใด ๆ: mm หรือ inch"));
  EXPECT_THAT(bogus.out, Not(HasSubstr("usage:")));
  // The same in English, word for word as before.
  const CliRun english = runCliWithErrors("check --bogus x.nc");
  EXPECT_EQ(english.out.substr(0, english.out.find('\n')), "klueng-cli check: unknown option '--bogus'");
  EXPECT_THAT(english.out, HasSubstr("\nusage: klueng-cli check FILE|FOLDER..."));

  const CliRun command = runCliWithErrors("--lang th");
  EXPECT_EQ(command.exitCode, 2);
  EXPECT_EQ(command.out.substr(0, command.out.find('\n')), "klueng-cli: ไม่รู้จักคำสั่ง '--lang'");
  EXPECT_THAT(command.out, HasSubstr("\nวิธีใช้: klueng-cli check FILE..."));

  const CliRun stock =
      runCliWithErrors("simulate " + quote(kSamples + "/01-step-shaft.txt") + " --stock abc --lang=th");
  EXPECT_EQ(stock.exitCode, 2);
  EXPECT_THAT(stock.out, HasSubstr("klueng-cli simulate: ค่า 'abc' ใช้กับ --stock ไม่ได้ ค่าที่ใช้ได้: DxL[xBORE][in] "
                                   "โดย 0 < D, L <= 9999.999 และ 0 < BORE < D เช่น 50x100, 2.1x4in, 118x80x90\n"));
  const CliRun units = runCliWithErrors("check --units feet --lang th x.nc");
  EXPECT_THAT(units.out, HasSubstr("klueng-cli check: ค่า 'feet' ใช้กับ --units ไม่ได้ ค่าที่ใช้ได้: mm หรือ inch\n"));
  const CliRun sheet = runCliWithErrors("print x.nc --pdf x.pdf --sheet poster --lang th");
  EXPECT_EQ(sheet.exitCode, 2);
  EXPECT_THAT(sheet.out,
              HasSubstr("klueng-cli print: ค่า 'poster' ใช้กับ --sheet ไม่ได้ ค่าที่ใช้ได้: program, drawing หรือ both\n"));
  EXPECT_THAT(sheet.out, HasSubstr("วิธีใช้: klueng-cli print FILE --pdf OUT.pdf"));
  // A Thai locale without --lang.
  const CliRun locale = runCliWithErrors("simulate", "LC_ALL= LC_MESSAGES= LANG=th_TH.UTF-8");
  EXPECT_EQ(locale.exitCode, 2);
  EXPECT_THAT(locale.out, HasSubstr("วิธีใช้: klueng-cli simulate FILE"));
}

TEST(CliLanguage, ClassAndGenerateErrorsAreThaiUnderLangTh) {
  TempDir dir;
  const std::string missing = dir.file("no-such-folder");
  const CliRun classRun = runCliWithErrors("class " + quote(missing) + " --reference " +
                                           quote(kSamples + "/01-step-shaft.txt") + " --lang th");
  EXPECT_EQ(classRun.exitCode, 2);
  EXPECT_THAT(classRun.out, HasSubstr("klueng-cli class: " + missing + " ไม่ใช่โฟลเดอร์\n"));
  const CliRun classUse = runCliWithErrors("class --lang th");
  EXPECT_EQ(classUse.exitCode, 2);
  EXPECT_THAT(classUse.out, HasSubstr("klueng-cli class: ต้องระบุโฟลเดอร์ DIR และ --reference REF.nc หรือ --drawing "
                                      "PART.json\nวิธีใช้: klueng-cli class DIR"));
  const CliRun tolerance = runCliWithErrors("class x --reference y --tolerance lots");
  EXPECT_THAT(tolerance.out,
              HasSubstr("klueng-cli class: bad value 'lots' for --tolerance; allowed: a number from 0 to 100 (mm)\n"));

  const std::string part = dir.file("none.json");
  const CliRun generate =
      runCliWithErrors("generate " + quote(part) + " -o " + quote(dir.file("out.nc")) + " --lang th");
  EXPECT_EQ(generate.exitCode, 2);
  EXPECT_THAT(generate.out, HasSubstr("F101: " + part + ": ไม่พบไฟล์\n"));  // read with the part-file limit
  const CliRun option = runCliWithErrors("generate " + quote(part) + " -o x.nc --tool-material wood --lang th");
  EXPECT_THAT(option.out,
              HasSubstr("klueng-cli generate: ค่า 'wood' ใช้กับ --tool-material ไม่ได้ ค่าที่ใช้ได้: hss หรือ carbide\n"));
}

// A picture that cannot be written is said in the run's language, as every other output.
TEST(CliLanguage, APictureThatCannotBeWrittenIsSaidInThai) {
  TempDir dir;
  const std::string png = dir.file("no-folder/part.png");
  const CliRun run =
      runCliWithErrors("simulate " + quote(kSamples + "/01-step-shaft.txt") + " --png " + quote(png) + " --lang th");
  EXPECT_EQ(run.exitCode, 2);
  EXPECT_THAT(run.out, HasSubstr(png + ": ข้อผิดพลาด F125: " + png + ": สร้างไฟล์ไม่ได้ เพราะไม่มีโฟลเดอร์ " +
                                 dir.file("no-folder") + " หรือไม่มีสิทธิ์เขียนลงในโฟลเดอร์นี้\n"));
  EXPECT_THAT(run.out, Not(HasSubstr("cannot write")));
}

// The system's reason for a failed write is Thai too (F108): here a file name longer
// than any folder allows (255 bytes), which fails for root as for anyone.
TEST(CliLanguage, AWriteFailureGivesItsReasonInThai) {
  TempDir dir;
  const std::string trace = dir.file(std::string(300, 'a') + ".csv");
  const std::string sample = quote(kSamples + "/01-step-shaft.txt");
  const CliRun thai = runCliWithErrors("simulate " + sample + " --trace " + quote(trace) + " --lang th");
  EXPECT_EQ(thai.exitCode, 2);
  EXPECT_THAT(thai.out, HasSubstr(trace + ": ข้อผิดพลาด F108: " + trace +
                                  ": บันทึกไฟล์ไม่ได้ (ชื่อไฟล์ยาวเกินไป) ถ้ามีไฟล์ชื่อนี้อยู่แล้ว ไฟล์นั้นยังคงเดิม\n"));
  const CliRun english = runCliWithErrors("simulate " + sample + " --trace " + quote(trace));
  EXPECT_EQ(english.exitCode, 2);
  EXPECT_THAT(english.out, HasSubstr(trace + ": error F108: " + trace +
                                     ": cannot write the file (File name too long); an existing file of that name is "
                                     "left unchanged\n"));
}

// Issue 27: a machine from the --config folder's machines/ runs a system-B
// program clean; --machine FILE with a broken file names file, line and key
// (English and Thai) and exits 2; an unknown name lists the machines.
TEST(CliMachines, ConfigFolderMachineAndBrokenMachineFile) {
  TempDir dir;
  const std::string config = dir.config({});
  dir.write("config/machines/school.machine",
            "base = fanuc\nid = school\nname_en = School lathe\nname_th = "
            "\xE0\xB9\x82\xE0\xB8\xA3\xE0\xB8\x87\xE0\xB9\x80\xE0\xB8\xA3\xE0\xB8\xB5\xE0\xB8\xA2\xE0\xB8\x99\ngcode_"
            "system = B\n");
  const std::string program = dir.write("b.nc",
                                        "O0001;\nG90 G95 G21;\nG92 S3000;\nT0101;\nG97 S800 M03;\nG00 X24. Z5.;\n"
                                        "G78 X19.4 Z-13. F1.5;\nX18.9;\nG00 X100. Z100.;\nM30;\n");
  const CliRun ok = runCliWithErrors("check --config " + quote(config) + " --machine school " + quote(program));
  EXPECT_EQ(ok.exitCode, 0) << ok.out;
  EXPECT_THAT(ok.out, Not(HasSubstr("error")));
  const CliRun asA = runCliWithErrors("check --config " + quote(config) + " " + quote(program));
  EXPECT_EQ(asA.exitCode, 1);
  EXPECT_THAT(asA.out, HasSubstr(":2:5: error E114: G95 is not a G code of this lathe"));

  const std::string bad = dir.write("bad.machine", "base = fanuc\nid = bad\n\nfamily = fanuk\n");
  const CliRun broken = runCliWithErrors("check --machine " + quote(bad) + " " + quote(program));
  EXPECT_EQ(broken.exitCode, 2);
  EXPECT_THAT(broken.out,
              HasSubstr(bad + ":4:10: error F200: " + bad + ": family = 'fanuk': must be one of: fanuc haas classic"));
  const CliRun thai = runCliWithErrors("check --lang th --machine " + quote(bad) + " " + quote(program));
  EXPECT_EQ(thai.exitCode, 2);
  EXPECT_THAT(thai.out, HasSubstr(":4:10: ข้อผิดพลาด F200: " + bad +
                                  ": family = 'fanuk': ต้องเป็นค่าใดค่าหนึ่งต่อไปนี้: fanuc haas classic"));
  const CliRun unknown = runCliWithErrors("simulate --machine no-such-lathe " + quote(program));
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_THAT(unknown.out, HasSubstr("no-such-lathe: error F203: no-such-lathe: no such machine or machine file; the "
                                     "machines are: fanuc, haas, classic, romi-gl240m, thai-vocational"));
}

// Issue 27 item 2: a program that names its machine at its head, as Job details
// writes it, is checked and simulated on that machine; --dialect or --machine
// still wins; a machine that is not loaded is a located warning.
TEST(CliMachines, ProgramNamesItsMachine) {
  TempDir dir;
  const std::string body =
      "G90 G95 G21;\nG92 S3000;\nT0101;\nG97 S800 M03;\nG00 X24. Z5.;\n"
      "G78 X19.4 Z-13. F1.5;\nX18.9;\nG00 X100. Z100.;\nM30;\n";
  const std::string named = dir.write("named.nc", "%\nO0001\n(MACHINE: romi-gl240m)\n" + body + "%\n");
  const CliRun ok = runCliWithErrors("check " + quote(named));
  EXPECT_EQ(ok.exitCode, 0) << ok.out;
  EXPECT_THAT(ok.out, Not(HasSubstr("error")));
  const CliRun sim = runCliWithErrors("simulate --cycle-time " + quote(named));
  EXPECT_EQ(sim.exitCode, 0) << sim.out;
  // --dialect chooses for it: system A refuses G95 on line 4.
  const CliRun asA = runCliWithErrors("check --dialect fanuc " + quote(named));
  EXPECT_EQ(asA.exitCode, 1);
  EXPECT_THAT(asA.out, HasSubstr(":4:5: error E114: G95 is not a G code of this lathe"));

  const std::string unknown = dir.write("unknown.nc", "O0002\n(MACHINE: okuma-lb15)\n" + body);
  const CliRun warned = runCliWithErrors("check " + quote(unknown));
  EXPECT_EQ(warned.exitCode, 1);  // checked on the default Fanuc: G95 is an error there
  EXPECT_THAT(warned.out,
              HasSubstr(unknown + ":2:11: warning F205: the program names the machine 'okuma-lb15', "
                                  "which is not loaded: it is checked on the chosen machine; the machines are: "
                                  "fanuc, haas, classic, romi-gl240m, thai-vocational"));
  const CliRun thai = runCliWithErrors("check --lang th " + quote(unknown));
  EXPECT_THAT(thai.out, HasSubstr(":2:11: "));
  EXPECT_THAT(thai.out, HasSubstr("F205: โปรแกรมระบุเครื่อง 'okuma-lb15' ซึ่งไม่มีอยู่"));
}

}  // namespace

}  // namespace cli_check_test
