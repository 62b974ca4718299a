// The benchmark's program generator must produce clean programs in both dialects.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "../../../bench/program_generator.h"
#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/messages.h"

namespace klueng::core::gcode {
namespace {

std::string afterHeader(const std::string& file, int lines) {
  std::size_t pos = 0;
  for (int i = 0; i < lines; ++i) pos = file.find('\n', pos) + 1;
  return file.substr(pos);
}

std::string describe(const std::vector<Diagnostic>& diags) {
  std::ostringstream s;
  for (const auto& d : diags) s << d.range.line << ':' << d.range.column << ' ' << formatMessage(d, Lang::En) << '\n';
  return s.str();
}

class GeneratedProgram : public ::testing::TestWithParam<Dialect> {};

TEST_P(GeneratedProgram, TwoThousandBlocksAreClean) {
  const std::string file = klueng::bench::ProgramGenerator::generate(2000);
  const Program program = parse(afterHeader(file, 6), 7);
  // O0001 plus exactly 2000 N-numbered blocks.
  ASSERT_EQ(program.blocks.size(), 2001u);
  EXPECT_EQ(program.blocks.front().words.front().letter, 'O');
  EXPECT_EQ(program.blocks[1].words.front().letter, 'N');
  EXPECT_EQ(program.blocks.back().line, 7 + 2000);
  CheckOptions options;
  options.dialect = GetParam();
  options.toolsWithBitmap = std::vector<int>{1};
  const auto diags = check(program, options);
  EXPECT_TRUE(diags.empty()) << describe(diags);
}

TEST_P(GeneratedProgram, OddSizesAreCleanToo) {
  for (int blocks : {16, 17, 63, 157, 1001}) {
    const std::string file = klueng::bench::ProgramGenerator::generate(blocks);
    const Program program = parse(afterHeader(file, 6), 7);
    EXPECT_EQ(program.blocks.size(), static_cast<std::size_t>(blocks) + 1);
    CheckOptions options;
    options.dialect = GetParam();
    const auto diags = check(program, options);
    EXPECT_TRUE(diags.empty()) << blocks << " blocks:\n" << describe(diags);
  }
}

TEST(GeneratedProgramShape, HeaderStockAndSafeLimits) {
  const std::string file = klueng::bench::ProgramGenerator::generate(500);
  std::istringstream in(file);
  std::string line;
  std::vector<std::string> header;
  for (int i = 0; i < 6 && std::getline(in, line); ++i) header.push_back(line);
  ASSERT_EQ(header.size(), 6u);
  EXPECT_EQ(header[3], "150");   // Ø50 mm
  EXPECT_EQ(header[4], "1100");  // 100 mm
  // No Z word below -80 (the chuck grips Z -85..-100).
  const Program program = parse(afterHeader(file, 6), 7);
  bool sawG42 = false, sawArcR = false, sawArcIK = false, sawDwell = false;
  for (const Block& b : program.blocks) {
    for (const Word& w : b.words) {
      if (w.letter == 'Z') {
        EXPECT_GE(w.value, -80.0) << "line " << b.line;
      }
      if (w.letter == 'X') {
        EXPECT_GE(w.value, 20.0) << "line " << b.line;
      }
      if (w.letter == 'G' && w.code() == 42) sawG42 = true;
      if (w.letter == 'G' && w.code() == 4) sawDwell = true;
      if (w.letter == 'R') sawArcR = true;
      if (w.letter == 'I') sawArcIK = true;
    }
  }
  EXPECT_TRUE(sawG42 && sawArcR && sawArcIK && sawDwell);
  EXPECT_EQ(program.blocks.back().words.back().letter, 'M');
  EXPECT_EQ(program.blocks.back().words.back().code(), 30);
}

TEST_P(GeneratedProgram, RoughingProgramIsCleanAndExact) {
  for (int blocks : {klueng::bench::RoughingGenerator::kMinimumBlocks, 1000, 1003, 20000}) {
    const std::string file = klueng::bench::RoughingGenerator::generate(blocks);
    const Program program = parse(afterHeader(file, 6), 7);
    ASSERT_EQ(program.blocks.size(), static_cast<std::size_t>(blocks) + 1) << blocks;
    CheckOptions options;
    options.dialect = GetParam();
    options.toolsWithBitmap = std::vector<int>{1};
    const auto diags = check(program, options);
    EXPECT_TRUE(diags.empty()) << blocks << " blocks:\n" << describe(diags);
  }
}

TEST(GeneratedProgramShape, RoughingGoesDownAllLevelsClearOfTheChuck) {
  const std::string file = klueng::bench::RoughingGenerator::generate(20000);
  EXPECT_EQ(file.rfind("Generated roughing job\nHeavy roughing shaft\nMild steel\n160\n1120\n", 0), 0u);
  const Program program = parse(afterHeader(file, 6), 7);
  double lowestX = 1e9, lowestZ = 0.0;
  int feedsAtLowest = 0;
  for (const Block& b : program.blocks)
    for (const Word& w : b.words) {
      if (w.letter == 'Z') lowestZ = std::min(lowestZ, w.value);
      if (w.letter == 'X' && w.value < lowestX) {
        lowestX = w.value;
        feedsAtLowest = 0;
      }
      if (w.letter == 'X' && w.value == lowestX) ++feedsAtLowest;
    }
  EXPECT_EQ(lowestX, 21.0);      // the last level
  EXPECT_EQ(lowestZ, -100.0);    // the chuck grips Z -105..-120
  EXPECT_GT(feedsAtLowest, 50);  // many passes a level
}

TEST(GeneratedProgramShape, RoughingInLinuxCncDialectHasTheSameBlocks) {
  const std::string ours = klueng::bench::RoughingGenerator::generate(1000);
  const std::string theirs = klueng::bench::RoughingGenerator::generate(1000, true);
  EXPECT_EQ(theirs.rfind("%\nN1 G21 G40 G97\nN2 G95\nN3 T1 M6\n", 0), 0u);
  EXPECT_EQ(theirs.substr(theirs.size() - 2), "%\n");
  EXPECT_EQ(std::count(theirs.begin(), theirs.end(), '\n'), 1000 + 2);
  EXPECT_EQ(std::count(ours.begin(), ours.end(), '\n'), 1000 + 7);
  EXPECT_EQ(theirs.find("O0001"), std::string::npos);
  // The passes are the same text.
  EXPECT_EQ(theirs.substr(theirs.find("N6 ")), afterHeader(ours, 7).substr(afterHeader(ours, 7).find("N6 ")) + "%\n");
}

// The yardstick of issue 40 (bench/: check and simulate against rs274 on it).
TEST(GeneratedProgramShape, YardstickIsCleanWithAChainAPass) {
  using klueng::bench::YardstickGenerator;
  for (const bool steps : {false, true})
    for (int blocks : {YardstickGenerator::kMinimumBlocks, 14000}) {
      const std::string file = YardstickGenerator::generate(blocks, false, steps);
      EXPECT_EQ(file.rfind("Benchmark\nRoughing passes\nAluminium\n150\n1100\nyardstick\nO0100\n", 0), 0u);
      const Program program = parse(afterHeader(file, 6), 7);
      const int per = std::max(4, blocks / YardstickGenerator::kPasses - 4);
      // O0100, N1..N6, each pass (its chain and four more blocks), the three last blocks.
      EXPECT_EQ(program.blocks.size(), static_cast<std::size_t>(1 + 6 + YardstickGenerator::kPasses * (per + 4) + 3))
          << blocks;
      // With steps, the chains are one word a block (X or Z); else two.
      const auto oneAxisWord = std::count_if(program.blocks.begin(), program.blocks.end(), [](const Block& b) {
        return b.words.size() == 1 && (b.words[0].letter == 'X' || b.words[0].letter == 'Z');
      });
      EXPECT_EQ(oneAxisWord, steps ? YardstickGenerator::kPasses * per : 0) << blocks;
      CheckOptions options;
      options.toolsWithBitmap = std::vector<int>{1};
      const auto diags = check(program, options);
      EXPECT_TRUE(diags.empty()) << blocks << " blocks:\n" << describe(diags);
    }
}

TEST(GeneratedProgramShape, YardstickInLinuxCncDialectHasTheSameMoves) {
  const std::string ours = klueng::bench::YardstickGenerator::generate(3000);
  const std::string theirs = klueng::bench::YardstickGenerator::generate(3000, true);
  EXPECT_EQ(theirs.rfind("G18 G7 G21 G90 G40\nT1 M6\nM3 S1000\nG0 X60 Z5\nG95 F0.25\n", 0), 0u);
  // The passes are the same text: after our 13 lines and their 5, up to the last three lines.
  const std::string ourEnd = "G00 X100. Z100.\nM05\nM30\n", theirEnd = "G0 X100 Z100\nM5\nM2\n";
  const std::string passes = afterHeader(ours, 13);
  ASSERT_GT(passes.size(), ourEnd.size());
  EXPECT_EQ(passes.substr(passes.size() - ourEnd.size()), ourEnd);
  EXPECT_EQ(afterHeader(theirs, 5), passes.substr(0, passes.size() - ourEnd.size()) + theirEnd);
}

INSTANTIATE_TEST_SUITE_P(BothDialects, GeneratedProgram, ::testing::Values(Dialect::Fanuc, Dialect::Classic));

}  // namespace
}  // namespace klueng::core::gcode
