// Acceptance (issue 2): the shared sample programs through the core API.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

std::string readFile(const std::string& name) {
  std::ifstream in(std::string(KLUENG_SAMPLES_DIR) + "/" + name, std::ios::binary);
  EXPECT_TRUE(in.good()) << name;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The G-code after the 6 header lines (file line 7 onward).
std::string body(const std::string& file) {
  std::size_t pos = 0;
  for (int i = 0; i < 6; ++i) pos = file.find('\n', pos) + 1;
  return file.substr(pos);
}

std::vector<Diagnostic> checkSample(const std::string& name, Dialect dialect) {
  CheckOptions options;
  options.dialect = dialect;
  return check(parse(body(readFile(name)), 7), options);
}

std::string listing(const std::vector<Diagnostic>& diags) {
  std::ostringstream s;
  for (const auto& d : diags)
    s << "  line " << d.range.line << ":" << d.range.column << " " << formatMessage(d, Lang::En) << "\n";
  return s.str();
}

TEST(Samples, GrammarErrorsReportsEveryBrokenLineInClassic) {
  const std::string file = readFile("04-grammar-errors.txt");
  const Program program = parse(body(file), 7);
  CheckOptions options;
  options.dialect = Dialect::Classic;
  const auto diags = check(program, options);

  std::map<int, int> errorsPerLine;
  for (const auto& d : diags)
    if (d.severity == Severity::Error) ++errorsPerLine[d.range.line];

  int brokenBlocks = 0;
  for (const Block& b : program.blocks) {
    if (b.words.empty() || b.words[0].letter != 'N') continue;
    const int n = b.words[0].code();
    if (n == 10 || n == 15 || n == 20 || n == 240) {
      EXPECT_EQ(errorsPerLine[b.line], 0) << "N" << n << " must be clean\n" << listing(diags);
    } else if (n >= 30 && n <= 230) {
      EXPECT_GE(errorsPerLine[b.line], 1) << "N" << n << " (line " << b.line << ") must be reported\n"
                                          << listing(diags);
      ++brokenBlocks;
    }
  }
  EXPECT_EQ(brokenBlocks, 20);  // N30..N230, N190 holding the misplaced N200
  // N130 "G01 X" (file line 21): the lone X is a lexical error on that line.
  EXPECT_GE(errorsPerLine[21], 1);
}

TEST(Samples, GrammarErrorsNamesTheRuleOfEachLine) {
  const auto diags = checkSample("04-grammar-errors.txt", Dialect::Classic);
  std::map<int, std::set<std::string>> codes;
  for (const auto& d : diags) codes[d.range.line].insert(d.code);
  // file line -> a code that must be among that line's diagnostics
  const std::map<int, std::string> expected = {{11, "E201"}, {12, "E210"}, {13, "E210"}, {14, "E205"}, {15, "E206"},
                                               {16, "E204"}, {17, "E204"}, {18, "E203"}, {19, "E207"}, {20, "E202"},
                                               {21, "E101"}, {22, "E110"}, {23, "E114"}, {24, "E115"}, {25, "E117"},
                                               {26, "E211"}, {27, "E209"}, {28, "E208"}, {29, "E210"}, {30, "E112"}};
  for (const auto& [line, code] : expected)
    EXPECT_TRUE(codes[line].count(code)) << "line " << line << " lacks " << code << "\n" << listing(diags);
}

TEST(Samples, GrammarErrorsN110IsLegalInFanuc) {
  const auto diags = checkSample("04-grammar-errors.txt", Dialect::Fanuc);
  for (const auto& d : diags) EXPECT_NE(d.range.line, 19) << listing(diags);
}

class CleanSample : public ::testing::TestWithParam<std::tuple<std::string, Dialect>> {};

TEST_P(CleanSample, HasNoDiagnostics) {
  const auto& [name, dialect] = GetParam();
  const auto diags = checkSample(name, dialect);
  EXPECT_TRUE(diags.empty()) << name << "\n" << listing(diags);
}

INSTANTIATE_TEST_SUITE_P(Samples, CleanSample,
                         ::testing::Combine(::testing::Values("01-step-shaft.txt", "02-thread.txt",
                                                              "05-runtime-alarms.txt"),
                                            ::testing::Values(Dialect::Fanuc, Dialect::Classic)));

}  // namespace
}  // namespace klueng::core::gcode
