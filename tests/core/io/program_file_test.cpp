#include <cstring>
#include "klueng/core/io/program_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "klueng/core/gcode/parser.h"

#include <filesystem>

#include "klueng/core/messages.h"
#include "test_util.h"

namespace klueng::core::io {
namespace {

using testing::TempDir;

std::string codes(const std::vector<Diagnostic>& diags) {
  std::string s;
  for (const Diagnostic& d : diags)
    s += d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + " ";
  return s;
}

const std::string kHeader = "Step shaft\nShaft SS-01\nAluminium\n150\n1100\nSomchai\n";

TEST(ProgramFile, ReadsTheSixLineHeaderOfSample01) {
  const auto r = readProgramFile(std::string(KLUENG_SOURCE_DIR "/resources/samples") + "/01-step-shaft.txt");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  const ProgramFile& f = *r.value;
  EXPECT_FALSE(f.plainGcode);
  EXPECT_EQ(f.header.project, "Step shaft exercise");
  EXPECT_EQ(f.header.part, "Shaft SS-01");
  EXPECT_EQ(f.header.material, "Aluminium 6061");
  EXPECT_DOUBLE_EQ(f.header.diameter, 50.0);
  EXPECT_EQ(f.header.diameterUnit, LengthUnit::Millimetre);
  EXPECT_DOUBLE_EQ(f.header.length, 100.0);
  EXPECT_EQ(f.header.programmer, "Klueng samples");
  EXPECT_EQ(f.gcodeFirstLine, 7);
  EXPECT_EQ(f.gcode.substr(0, 16), "O0001\nN10 G21 G4");
  EXPECT_EQ(f.encoding, SourceEncoding::Utf8);
}

TEST(ProgramFile, HeaderStartingWithGOrMWordsIsStillAHeader) {
  // Sample 04's project name starts with G, its material with M.
  const auto r = readProgramFile(std::string(KLUENG_SOURCE_DIR "/resources/samples") + "/04-grammar-errors.txt");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_EQ(r.value->header.project, "Grammar checker demonstration");
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 40.0);
  EXPECT_DOUBLE_EQ(r.value->header.length, 80.0);
}

TEST(ProgramFile, InchUnitDigit) {
  const auto r = parseProgramFile("P\nQ\nSteel\n02.5\n04\nMe\nG20\n");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 2.5);
  EXPECT_EQ(r.value->header.diameterUnit, LengthUnit::Inch);
  EXPECT_DOUBLE_EQ(r.value->header.diameterMm(), 63.5);
  EXPECT_DOUBLE_EQ(r.value->header.lengthMm(), 101.6);
  EXPECT_EQ(r.value->gcode, "G20\n");
}

class PlainGcodeFirstLine : public ::testing::TestWithParam<const char*> {};

TEST_P(PlainGcodeFirstLine, IsReadAsPlainGcodeWithDefaults) {
  JobHeader defaults;
  defaults.project = "Last job";
  defaults.diameter = 32.0;
  const std::string text = std::string(GetParam()) + "\nG00 X10.\n";
  const auto r = parseProgramFile(text, defaults, "plain.nc");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.value->plainGcode);
  EXPECT_EQ(r.value->gcodeFirstLine, 1);
  EXPECT_EQ(r.value->gcode, text);
  EXPECT_EQ(r.value->header.project, "Last job");
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 32.0);
}

INSTANTIATE_TEST_SUITE_P(Starts, PlainGcodeFirstLine,
                         ::testing::Values("%", "O0001", "N10 G21", "G21 G99", "g01 x20", "M03 S500", "T0101",
                                           "(turning)", "; comment", "  N5", "G.5"));

class HeaderFirstLine : public ::testing::TestWithParam<const char*> {};

TEST_P(HeaderFirstLine, IsReadAsAHeader) {
  const std::string text = std::string(GetParam()) + "\nPart\nSteel\n150\n1100\nMe\nG00 X10.\n";
  const auto r = parseProgramFile(text);
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_EQ(r.value->gcode, "G00 X10.\n");
}

INSTANTIATE_TEST_SUITE_P(Starts, HeaderFirstLine,
                         ::testing::Values("Gear shaft", "Mild steel", "Turning job", "Nut", "O-ring groove", "",
                                           "งานกลึง", "Shaft"));

// SPEC 2 (ext): a header needs sizes on lines 4 and 5; a broken size line
// makes the file plain G-code, with a warning that names the line.
TEST(ProgramFile, BadUnitDigitMakesAPlainFileWithAHint) {
  const auto r = parseProgramFile("P\nQ\nSteel\n  250\n1100\nMe\n", {}, "job.txt");
  ASSERT_TRUE(r.value);
  EXPECT_TRUE(r.value->plainGcode);
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.code, "F117");
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.range, (SourceRange{4, 3, 3}));
  EXPECT_EQ(d.args, (std::vector<std::string>{"job.txt", "250", "4"}));
  EXPECT_EQ(formatMessage(d, Lang::En),
            "job.txt: read as a plain G-code file without a job header: line 4 ('250') is not a stock size "
            "(a unit digit 0 = inch or 1 = mm, then the size, e.g. 150 = 50 mm)");
  EXPECT_NE(formatMessage(d, Lang::Th).find("ไม่มีส่วนหัวของงาน"), std::string::npos);
}

TEST(ProgramFile, NonSizeLinesMakeAPlainFile) {
  for (const char* text : {"P\nQ\nSteel\n150\nกขค\nMe\n", "P\nQ\nSteel\n15O\n1abc\nMe\n", "P\nQ\nSteel\n\n   \nMe\n",
                           "Project\nPart\nSteel"}) {
    const auto r = parseProgramFile(text);
    ASSERT_TRUE(r.value) << text;
    EXPECT_TRUE(r.value->plainGcode) << text;
    EXPECT_EQ(r.value->gcode, text);
  }
}

// Issue 8: files that used to lose lines to the header.
class NeverAHeader : public ::testing::TestWithParam<const char*> {};

TEST_P(NeverAHeader, IsPlainAndKeepsEveryLine) {
  const std::string text = GetParam();
  const auto r = parseProgramFile(text, {}, "p.nc");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.value->plainGcode);
  EXPECT_EQ(r.value->gcodeFirstLine, 1);
  EXPECT_EQ(r.value->gcode, text);
  EXPECT_EQ(r.value->header.stockSource, StockSource::Default);
}

INSTANTIATE_TEST_SUITE_P(
    Files, NeverAHeader,
    ::testing::Values("\nO0001\nG21 G99\nT0101\nG00 X52. Z2.\nG01 Z-30. F0.2\nM30\n",   // blank first line
                      "%\n\nO1000\nG20\nT0101\nG00 X2.1 Z0.1\nM30\n%\n",                // % then a blank line
                      "(SHAFT 50 X 100)\n(OD ROUGH)\nG21\nT0101\nG00 X52. Z2.\nM30\n",  // comment first
                      "O1234\nN10 G21\nN20 T0101\n150\n1100\nN60 M30\n",                // O number, size-like lines
                      "\n\n\n150\n1100\nG00 X10.\n",         // size lines but G-code on line 6
                      "G21\nG99\nT0101\n150\n1100\nMe\n"));  // size lines but G-code on lines 1-3

TEST(ProgramFile, RealHeaderAndThaiHeader) {
  const auto r = parseProgramFile(kHeader + "G00 X10.\n");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_EQ(r.value->header.stockSource, StockSource::Header);
  const auto th = parseProgramFile("งานกลึงเพลา\nเพลาขั้นบันได\nอะลูมิเนียม\n150\n1100\nสมชาย ใจดี\nG00 X10.\n");
  ASSERT_TRUE(th.ok()) << codes(th.diagnostics);
  EXPECT_FALSE(th.value->plainGcode);
  EXPECT_EQ(th.value->header.material, "อะลูมิเนียม");
  EXPECT_EQ(th.value->header.programmer, "สมชาย ใจดี");
  EXPECT_DOUBLE_EQ(th.value->header.diameter, 50.0);
  EXPECT_EQ(th.value->gcode, "G00 X10.\n");
}

TEST(ProgramFile, TubeStockOnLineFour) {
  const std::string text = "Bush\nB-1\nSteel\n1118x90\n180\nMe\nG00 X120.\n";
  const auto r = parseProgramFile(text);
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 118.0);
  EXPECT_DOUBLE_EQ(r.value->header.bore, 90.0);
  EXPECT_DOUBLE_EQ(r.value->header.length, 80.0);
  EXPECT_EQ(formatProgramFile(*r.value), text);
  EXPECT_EQ(stockSizeText(r.value->header), "Ø118/Ø90 x 80 mm");
  const auto inch = parseProgramFile("P\nQ\nS\n02.5X1.25\n04\nMe\n");
  ASSERT_TRUE(inch.ok()) << codes(inch.diagnostics);
  EXPECT_DOUBLE_EQ(inch.value->header.boreMm(), 31.75);
  EXPECT_EQ(stockSizeText(inch.value->header), "Ø2.5/Ø1.25 x 4 in");
  // Solid bars are written as before.
  const auto solid = parseProgramFile(kHeader);
  EXPECT_EQ(formatProgramFile(*solid.value), kHeader);
  EXPECT_DOUBLE_EQ(solid.value->header.bore, 0.0);
  EXPECT_EQ(stockSizeText(solid.value->header), "Ø50 x 100 mm");
}

TEST(ProgramFile, BoreMustBeInsideTheDiameter) {
  for (const char* line : {"150x50", "150x60", "150x0", "150x-5"}) {
    const auto r = parseProgramFile(std::string("P\nQ\nS\n") + line + "\n1100\nMe\n", {}, "t.txt");
    ASSERT_EQ(r.diagnostics.size(), 1u) << line << " " << codes(r.diagnostics);
    EXPECT_EQ(r.diagnostics[0].code, "F118");
    EXPECT_EQ(r.diagnostics[0].range.column, 5);
    EXPECT_DOUBLE_EQ(r.value->header.bore, 0.0);
  }
  const auto r = parseProgramFile("P\nQ\nS\n150x60\n1100\nMe\n", {}, "t.txt");
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            "stock bore: '60' must be a number greater than 0 and less than the diameter 50");
}

// Issue 29 item 9: a bar no lathe holds is refused at its line, as --stock and Job details bound it.
TEST(ProgramFile, StockSizeLargerThanAnyLatheHoldsIsRefused) {
  const auto r = parseProgramFile("P\nQ\nSteel\n1100000\n0250.5\nMe\nG00 X10.\n", {}, "big.txt");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F128");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{4, 2, 6}));
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            "big.txt: stock size 100000 is larger than any lathe holds; write at most 9999.999");
  EXPECT_NE(formatMessage(r.diagnostics[0], Lang::Th).find("ไม่เกิน 9999.999"), std::string::npos);
  EXPECT_FALSE(r.ok());
  ASSERT_TRUE(r.value);
  EXPECT_DOUBLE_EQ(r.value->header.length, 250.5);  // inch: the length line is fine
  EXPECT_EQ(r.value->header.lengthUnit, LengthUnit::Inch);
}

TEST(ProgramFile, StockSizeMustBePositiveRule13) {
  const auto r = parseProgramFile("P\nQ\nSteel\n1-50\n10\nMe\nG00 X10.\n", {}, "neg.txt");
  ASSERT_EQ(r.diagnostics.size(), 2u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "E213");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{4, 1, 4}));
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"neg.txt", "-50", "1-50"}));
  EXPECT_EQ(formatMessage(r.diagnostics[1], Lang::En),
            "stock diameter and length must be greater than 0, not 0 (written '10': unit digit, then the size)");
  EXPECT_EQ(r.diagnostics[1].code, "E213");
  EXPECT_EQ(r.diagnostics[1].range.line, 5);
  EXPECT_NE(formatMessage(r.diagnostics[0], Lang::Th).find("มากกว่า 0"), std::string::npos);
  EXPECT_FALSE(r.ok());
  ASSERT_TRUE(r.value);  // the G-code is still there to check
  EXPECT_EQ(r.value->gcode, "G00 X10.\n");
}

TEST(ProgramFile, MissingHeaderLines) {
  const auto r = parseProgramFile("Project\nPart\nSteel\n150\n1100", {}, "short.txt");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F110");
  EXPECT_EQ(r.diagnostics[0].range.line, 5);
  EXPECT_EQ(r.diagnostics[0].range.column, 5);  // just after "1100"
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"short.txt", "5"}));
}

TEST(ProgramFile, SixHeaderLinesAndNoCodeIsAnEmptyProgram) {
  const auto r = parseProgramFile("P\nQ\nSteel\n150\n1100\nMe");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->gcode, "");
  EXPECT_EQ(r.value->header.programmer, "Me");
}

TEST(ProgramFile, BinaryContentIsRefusedWithThePositionOfTheNul) {
  const std::string bytes = std::string("P\nQ\nab") + '\0' + "cd\n";
  const auto r = parseProgramFile(bytes, {}, "bin.dat");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F104");
  EXPECT_EQ(r.diagnostics[0].range.line, 3);
  EXPECT_EQ(r.diagnostics[0].range.column, 3);
  EXPECT_EQ(formatMessage(r.diagnostics[0], Lang::En),
            "bin.dat: this is a binary file (it contains a NUL byte), not text");
}

TEST(ProgramFile, EmptyFile) {
  for (const char* text : {"", "\xEF\xBB\xBF"}) {
    const auto r = parseProgramFile(text, {}, "empty.txt");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].code, "F105");
    EXPECT_FALSE(r.ok());
  }
}

TEST(ProgramFile, OverSixtyFourMegabytesIsRefused) {
  const std::string big(64u * 1024u * 1024u + 1u, 'G');
  const auto r = parseProgramFile(big, {}, "big.nc");
  EXPECT_FALSE(r.value);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F103");
  EXPECT_EQ(r.diagnostics[0].args.at(1), std::to_string(big.size()));
}

TEST(ProgramFile, OverlongLineIsReportedAndReadAsEmpty) {
  const std::string longLine = "G01" + std::string(5000, 'X');
  const auto r = parseProgramFile("O0001\n" + longLine + "\nG00 X1.\n", {}, "long.nc");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F106");
  EXPECT_EQ(r.diagnostics[0].range.line, 2);
  EXPECT_EQ(r.diagnostics[0].args, (std::vector<std::string>{"long.nc", "5003", "4096"}));
  EXPECT_EQ(r.value->gcode, "O0001\n\nG00 X1.\n");  // line 3 stays line 3
}

TEST(ProgramFile, ThaiCommentOfFourThousandCharactersIsNotTooLong) {
  std::string comment;
  for (int i = 0; i < 4000; ++i) comment += "ก";  // 12000 bytes, 4000 characters
  const auto r = parseProgramFile("O0001 (" + comment + ")\n");
  EXPECT_TRUE(r.ok()) << codes(r.diagnostics);
}

TEST(ProgramFile, NormalisesCrLfAndCrLineEnds) {
  const auto crlf = parseProgramFile("P\r\nQ\r\nSteel\r\n150\r\n1100\r\nMe\r\nN10 G00\r\nN20 M30\r\n");
  ASSERT_TRUE(crlf.ok());
  EXPECT_EQ(crlf.value->gcode, "N10 G00\nN20 M30\n");
  EXPECT_EQ(crlf.value->header.programmer, "Me");
  const auto cr = parseProgramFile("P\rQ\rSteel\r150\r1100\rMe\rN10 G00\rN20 M30");
  ASSERT_TRUE(cr.ok());
  EXPECT_EQ(cr.value->gcode, "N10 G00\nN20 M30");
  EXPECT_DOUBLE_EQ(cr.value->header.length, 100.0);
}

TEST(ProgramFile, ReadsTis620AndUtf8Bom) {
  // "งาน" (A7 D2 B9) as project, "เหล็ก" (E0 CB C5 E7 A1) as material, in TIS-620.
  const auto r = parseProgramFile("\xA7\xD2\xB9\nPart\n\xE0\xCB\xC5\xE7\xA1\n150\n1100\nMe\nG00 (\xA1)\n");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->encoding, SourceEncoding::Tis620);
  EXPECT_EQ(r.value->header.project, "งาน");
  EXPECT_EQ(r.value->header.material, "เหล็ก");
  EXPECT_EQ(r.value->gcode, "G00 (ก)\n");
  const auto bom = parseProgramFile("\xEF\xBB\xBFO0001\nG00\n");
  ASSERT_TRUE(bom.ok());
  EXPECT_TRUE(bom.value->plainGcode);
  EXPECT_EQ(bom.value->gcode, "O0001\nG00\n");
}

TEST(ProgramFile, ColumnsCountThaiCharactersNotBytes) {
  const auto r = parseProgramFile("P\nQ\nS\n1ห้า\n1100\nMe\n");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F117");  // not a size: the file is plain G-code
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{4, 1, 4}));
}

TEST(ProgramFile, FormatRoundTripsAHeaderFile) {
  ProgramFile f;
  f.header.project = "งานกลึง";
  f.header.part = "Shaft";
  f.header.material = "S45C";
  f.header.diameter = 2.5;
  f.header.diameterUnit = LengthUnit::Inch;
  f.header.length = 0.1 + 0.2;  // needs all 17 digits
  f.header.programmer = "สมชาย";
  f.gcode = "O0001\nG00 X10.\n";
  const std::string text = formatProgramFile(f);
  EXPECT_EQ(text.substr(0, text.find("0.3")), "งานกลึง\nShaft\nS45C\n02.5\n1");
  const auto r = parseProgramFile(text);
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->header.project, f.header.project);
  EXPECT_EQ(r.value->header.diameterUnit, LengthUnit::Inch);
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 2.5);
  EXPECT_EQ(r.value->header.length, f.header.length);
  EXPECT_EQ(r.value->header.programmer, "สมชาย");
  EXPECT_EQ(r.value->gcode, f.gcode);
  EXPECT_EQ(formatProgramFile(*r.value), text);
}

TEST(ProgramFile, FormatKeepsAPlainFilePlain) {
  const std::string text = "%\nO0001\nG00 X10.\n%\n";
  const auto r = parseProgramFile(text);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(formatProgramFile(*r.value), text);
}

// A part named "M10 bolt" or a project "%1" used to be saved as a file that read back as plain G-code.
TEST(ProgramFile, HeaderTextsThatLookLikeGcodeRoundTrip) {
  ProgramFile f;
  f.header.project = "%1 class";
  f.header.part = "M10 bolt";
  f.header.material = "(S45C)";
  f.header.programmer = "T1 group";
  f.gcode = "G00 X10.\n";
  const std::string text = formatProgramFile(f);
  EXPECT_EQ(text.substr(0, 16), "\xC2\xA0%1 class\n\xC2\xA0M10");
  const auto r = parseProgramFile(text);
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_EQ(r.value->header.project, "%1 class");
  EXPECT_EQ(r.value->header.part, "M10 bolt");
  EXPECT_EQ(r.value->header.material, "(S45C)");
  EXPECT_EQ(r.value->header.programmer, "T1 group");
  EXPECT_EQ(r.value->gcode, "G00 X10.\n");
  EXPECT_EQ(formatProgramFile(*r.value), text);
  EXPECT_EQ(headerText("Gear shaft"), "Gear shaft");  // only what would read as G-code is marked
}

TEST(ProgramFile, FormatFlattensLineBreaksInHeaderFields) {
  ProgramFile f;
  f.header.project = "two\nlines";
  const auto r = parseProgramFile(formatProgramFile(f));
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->header.project, "two lines");
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 50.0);
}

TEST(ProgramFile, SamplesRoundTripByteForByte) {
  for (const char* name : {"01-step-shaft.txt", "02-thread.txt", "04-grammar-errors.txt", "05-runtime-alarms.txt"}) {
    const std::string path = std::string(KLUENG_SOURCE_DIR "/resources/samples") + "/" + name;
    const auto r = readProgramFile(path);
    ASSERT_TRUE(r.ok()) << name << " " << codes(r.diagnostics);
    EXPECT_EQ(formatProgramFile(*r.value), testing::readFile(path)) << name;
  }
}

TEST(ProgramFile, ReadReportsMissingFilesAndFolders) {
  TempDir dir;
  const auto missing = readProgramFile(dir.file("nope.txt"));
  EXPECT_FALSE(missing.value);
  ASSERT_EQ(missing.diagnostics.size(), 1u);
  EXPECT_EQ(missing.diagnostics[0].code, "F101");
  EXPECT_EQ(missing.diagnostics[0].args.at(0), dir.file("nope.txt"));
  const auto folder = readProgramFile(dir.path().string());
  ASSERT_EQ(folder.diagnostics.size(), 1u);
  EXPECT_EQ(folder.diagnostics[0].code, "F102");
}

TEST(ProgramFile, AtomicWriteCreatesAndReplaces) {
  TempDir dir;
  const std::string path = dir.file("job.txt");
  std::string error;
  ASSERT_TRUE(writeTextFileAtomic(path, "first\n", &error)) << error;
  EXPECT_EQ(testing::readFile(path), "first\n");
  ASSERT_TRUE(writeTextFileAtomic(path, "second ไทย\n", &error)) << error;
  EXPECT_EQ(testing::readFile(path), "second ไทย\n");
  // No temporary file is left behind.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);
}

// Saving through a link writes the file it names; the link stays a link.
TEST(ProgramFile, AtomicWriteFollowsASymlink) {
  TempDir dir;
  const std::string real = dir.file("real.nc");
  const std::string link = dir.file("link.nc");
  std::string error;
  ASSERT_TRUE(writeTextFileAtomic(real, "old\n", &error)) << error;
  std::filesystem::create_symlink(real, link);
  ASSERT_TRUE(writeTextFileAtomic(link, "new\n", &error)) << error;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(testing::readFile(real), "new\n");
}

// A device is written into, never renamed over: /dev/full reports a full disk
// (and stays a device, even for root).
TEST(ProgramFile, AtomicWriteToAFullDeviceFailsAndLeavesIt) {
  ASSERT_TRUE(std::filesystem::is_character_file("/dev/full"));
  std::string error;
  EXPECT_FALSE(writeTextFileAtomic("/dev/full", "G21\n", &error));
  EXPECT_NE(error.find("the disk is full"), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/full"));
}

TEST(ProgramFile, AtomicWriteRefusesAFolder) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(writeTextFileAtomic(dir.path().string(), "x", &error));
  EXPECT_NE(error.find("folder"), std::string::npos) << error;
}

TEST(ProgramFile, AtomicWriteFailsCleanlyInAMissingFolder) {
  TempDir dir;
  std::string error;
  EXPECT_FALSE(writeTextFileAtomic(dir.file("no/such/folder/job.txt"), "x", &error));
  EXPECT_NE(error.find("job.txt"), std::string::npos);
}

}  // namespace
}  // namespace klueng::core::io

namespace klueng::core::io {
namespace {

// Issue 13: a UTF-16 program (Notepad's "Unicode") is text, not "binary (NUL byte)".
std::string utf16(const std::u16string& text, bool little, bool bom) {
  std::string out;
  if (bom) out += little ? std::string("\xFF\xFE") : std::string("\xFE\xFF");
  for (char16_t c : text) {
    const char lo = static_cast<char>(c & 0xFF), hi = static_cast<char>(c >> 8);
    out += little ? std::string{lo, hi} : std::string{hi, lo};
  }
  return out;
}

TEST(ProgramFile, Utf16ProgramsAreReadAsText) {
  const std::u16string text = u"O0001 (\u0E01\u0E25\u0E36\u0E07)\nG00 X20. Z2.\nM30\n";
  for (bool little : {true, false})
    for (bool bom : {true, false}) {
      if (!bom && !little) continue;  // without a BOM, only little-endian is guessed from the NULs
      const auto r = parseProgramFile(utf16(text, little, bom), {}, "u16.nc");
      ASSERT_TRUE(r.ok()) << little << bom << (r.diagnostics.empty() ? "" : r.diagnostics[0].code);
      EXPECT_EQ(r.value->gcode, "O0001 (\xE0\xB8\x81\xE0\xB8\xA5\xE0\xB8\xB6\xE0\xB8\x87)\nG00 X20. Z2.\nM30\n");
    }
  // Real binary with NULs is still refused.
  const auto bin = parseProgramFile(std::string("G00\0\x01\x02X", 7), {}, "bin.nc");
  ASSERT_FALSE(bin.value);
  EXPECT_EQ(bin.diagnostics[0].code, "F104");
}

}  // namespace
}  // namespace klueng::core::io

namespace klueng::core::io {
namespace {

// Issue 13: CR CR LF (a CRLF file converted again) shifted the header by a line per line.
TEST(ProgramFile, CrCrLfEndsOneLine) {
  const auto r = parseProgramFile("P\r\r\nQ\r\r\nSteel\r\r\n150\r\r\n1100\r\r\nMe\r\r\nN10 G00\r\r\nN20 M30\r\r\n");
  ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].code);
  EXPECT_FALSE(r.value->plainGcode);
  EXPECT_DOUBLE_EQ(r.value->header.diameter, 50.0);
  EXPECT_EQ(r.value->gcode, "N10 G00\nN20 M30\n");
  const gcode::Program p = gcode::parse("G00 X1.\r\r\nG01 Z2.\r\r\n", 7);
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[1].line, 8);
}

// Issue 27: the machine a program names at its head, written by Job details.
TEST(ProgramFile, MachineNamedAtTheHeadRoundTrips) {
  const auto r = parseProgramFile(kHeader + "%\nO0027 (BUCHA)\n(machine: romi-gl240m)\nG90 G95 G21;\n%\n");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->header.machine, "romi-gl240m");
  EXPECT_EQ(r.value->header.machineLine, 9);  // 6 header lines, %, O0027, then the comment
  const auto named = machineNamedIn(r.value->gcode);
  ASSERT_TRUE(named.has_value());
  EXPECT_EQ(named->line, 3);
  EXPECT_EQ(named->column, 11);

  // Job details picks another machine: the comment is rewritten in place, nothing else moves.
  ProgramFile f = *r.value;
  f.gcode = withMachineNamed(f.gcode, "fanuc");
  EXPECT_EQ(f.gcode, "%\nO0027 (BUCHA)\n(MACHINE: fanuc)\nG90 G95 G21;\n%\n");
  const auto again = parseProgramFile(formatProgramFile(f));
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again.value->header.machine, "fanuc");
  EXPECT_EQ(again.value->header.project, "Step shaft");
  EXPECT_DOUBLE_EQ(again.value->header.diameter, 50.0);

  // And none: the line goes.
  EXPECT_EQ(withMachineNamed(f.gcode, ""), "%\nO0027 (BUCHA)\nG90 G95 G21;\n%\n");
}

TEST(ProgramFile, MachineLineGoesAfterTheProgramNumber) {
  EXPECT_EQ(withMachineNamed("%\nO0001\nG21 G99\nM30\n", "romi-gl240m"),
            "%\nO0001\n(MACHINE: romi-gl240m)\nG21 G99\nM30\n");
  EXPECT_EQ(withMachineNamed("G21 G99\nM30\n", "haas"), "(MACHINE: haas)\nG21 G99\nM30\n");
  // On the O line's own comment it stays on that line.
  EXPECT_EQ(withMachineNamed("O0001 (MACHINE: fanuc)\nG21\n", "haas"), "O0001 (MACHINE: haas)\nG21\n");
  EXPECT_EQ(withMachineNamed("O0001 (MACHINE: fanuc)\nG21\n", ""), "O0001 \nG21\n");
}

TEST(ProgramFile, OnlyTheHeadNamesTheMachine) {
  // A plain file: a comment after the first block is the program's business, not its machine.
  const auto r = parseProgramFile("G21 G99\n(MACHINE: haas)\nM30\n");
  ASSERT_TRUE(r.ok());
  EXPECT_TRUE(r.value->plainGcode);
  EXPECT_EQ(r.value->header.machine, "");
  EXPECT_FALSE(machineNamedIn("(MACHINING TIME 3 MIN)\nG21\n").has_value());
  const auto semi = machineNamedIn("%\n; Machine = haas\nG20\n");
  ASSERT_TRUE(semi.has_value());
  EXPECT_EQ(semi->id, "haas");
  EXPECT_EQ(semi->line, 2);
  // A default header never lends its machine to a file that names none.
  JobHeader defaults;
  defaults.machine = "haas";
  EXPECT_EQ(parseProgramFile("G21\nM30\n", defaults).value->header.machine, "");
}

// Issue 31 item 5: the teacher's job file asks for the setup exercise at its head.
TEST(ProgramFile, OffsetsUnknownAtTheHeadAsksForTheSetupExercise) {
  const auto r =
      parseProgramFile(kHeader + "%\nO0031 (SETUP)\n(MACHINE: fanuc)\n(OFFSETS: UNKNOWN)\nG21 G99\nM30\n%\n");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.value->header.offsetsUnknown());
  EXPECT_EQ(r.value->header.offsetsUnknownLine, 10);  // 6 header lines, %, O0031, the machine, then the key
  EXPECT_EQ(r.value->header.machine, "fanuc");        // both keys at one head
  EXPECT_EQ(offsetsUnknownIn(r.value->gcode), 4);
  // The forms a machine comment has, any case.
  EXPECT_EQ(offsetsUnknownIn("O0031 (offsets = unknown)\nG21\n"), 1);
  EXPECT_EQ(offsetsUnknownIn("%\n; Offsets unknown\nG21\n"), 2);
  // Not the key: another value, more words, or a comment after the first block.
  EXPECT_EQ(offsetsUnknownIn("(OFFSETS: KNOWN)\nG21\n"), 0);
  EXPECT_EQ(offsetsUnknownIn("(OFFSETS: UNKNOWN T1)\nG21\n"), 0);
  EXPECT_EQ(offsetsUnknownIn("(OFFSETS UNKNOWNS)\nG21\n"), 0);
  const auto plain = parseProgramFile("G21 G99\n(OFFSETS: UNKNOWN)\nM30\n");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain.value->header.offsetsUnknown());
  const auto first = parseProgramFile("(OFFSETS: UNKNOWN)\nG21 G99\nM30\n");
  EXPECT_EQ(first.value->header.offsetsUnknownLine, 1);
}

}  // namespace
}  // namespace klueng::core::io
