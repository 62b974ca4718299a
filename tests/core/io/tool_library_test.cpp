// Turrets up to 24 stations, 64 offset rows, and the tool library (docs/tools.md).
#include "klueng/core/io/tool_library.h"

#include <unistd.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace klueng::core::io::tool_library_test {
namespace {

std::string codes(const std::vector<Diagnostic>& diags) {
  std::string s;
  for (const Diagnostic& d : diags)
    s += d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + " ";
  return s;
}

std::string lines(int n, const std::string& each) {
  std::string s;
  for (int i = 1; i <= n; ++i) s += each + "\n";
  return s;
}

// ---------------------------------------------------------------- 24 stations

TEST(Turret, TwentyFourStationsAreRead) {
  std::string text;
  for (int i = 1; i <= 24; ++i) text += "t" + std::to_string(i) + ".bmp\n";
  const auto r = parseToolTable(text, "/d", "tools.cfg", 24);
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->stations, 24);
  EXPECT_EQ(r.value->bitmapPath(12), "/d/t12.bmp");
  EXPECT_EQ(r.value->bitmapPath(24), "/d/t24.bmp");
  EXPECT_EQ(r.value->bitmapPath(25), "");
}

TEST(Turret, LinesPastTheDefaultTwelveStationsAreIgnoredWithF107) {
  std::string text;
  for (int i = 1; i <= 24; ++i) text += "t" + std::to_string(i) + ".bmp\n";
  const auto r = parseToolTable(text, "/d", "tools.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F107");
  EXPECT_EQ(r.diagnostics[0].range.line, 13);
  EXPECT_EQ(r.diagnostics[0].args.at(1), "12");
  EXPECT_EQ(r.value->bitmapPath(12), "/d/t12.bmp");
  EXPECT_EQ(r.value->bitmapPath(13), "");
}

TEST(Turret, TheSeedsEightLinesAreEnoughForTwelveStations) {
  const auto r = parseToolTable(lines(8, "a.bmp"), "/d", "tools.cfg", 12);
  EXPECT_TRUE(r.ok());
  EXPECT_TRUE(r.diagnostics.empty()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->bitmapPath(9), "");
}

TEST(Turret, FormatWritesUpToTheLastStationWithATool) {
  ToolTable t;
  t.bitmap[0] = "a.bmp";
  EXPECT_EQ(formatToolTable(t), "a.bmp\n\n\n\n\n\n\n\n");  // the seed's 8 lines at least
  t.bitmap[11] = "library:parting-3mm";
  const std::string text = formatToolTable(t);
  EXPECT_EQ(text, "a.bmp\n\n\n\n\n\n\n\n\n\n\nlibrary:parting-3mm\n");
  const auto r = parseToolTable(text, "/d", "t.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->libraryId(12), "parting-3mm");
}

// ---------------------------------------------------------------- 64 offsets

TEST(Offsets, SixtyFourRowsAreRead) {
  std::string text;
  for (int i = 1; i <= 64; ++i) text += "0 " + std::to_string(-i) + " 0.4 3\n";
  const auto r = parseOffsetTable(text, "offset.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.value->at(64).z, -64.0);
  EXPECT_EQ(r.value->at(17).z, -17.0);
}

TEST(Offsets, AShorterFileLeavesTheLaterRowsZero) {
  const auto r = parseOffsetTable(lines(30, "1 2 0.8 3"), "offset.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty());
  EXPECT_EQ(r.value->at(30).r, 0.8);
  EXPECT_EQ(r.value->at(31).r, 0.0);
  EXPECT_EQ(r.value->at(64).tip, 0);
}

TEST(Offsets, AMalformedRowPastSixteenIsReportedWithLineAndColumn) {
  std::string text = lines(39, "0 0 0 0") + "0 0 abc 3\n" + lines(5, "0 0 0 0");
  const auto r = parseOffsetTable(text, "offset.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F133");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{40, 5, 3}));
  EXPECT_EQ(r.diagnostics[0].args.at(1), "40");
}

TEST(Offsets, FewerThanSixteenIsStillTheSeedsError) {
  const auto r = parseOffsetTable(lines(10, "0 0 0 0"), "offset.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].code, "F130");
}

TEST(Offsets, FormatWritesSixteenRowsAndUpToTheLastOneSet) {
  OffsetTable t;
  EXPECT_EQ(formatOffsetTable(t), lines(16, "0 0 0 0"));
  t.at(40) = Offset{1.5, -2, 0.4, 3};
  const std::string text = formatOffsetTable(t);
  EXPECT_EQ(text, lines(39, "0 0 0 0") + "1.5 -2 0.4 3\n");
  const auto r = parseOffsetTable(text, "o.cfg");
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.value->at(40).r, 0.4);
}

// ---------------------------------------------------------------- the library

TEST(Library, ShippedLibraryHasTheSchoolLathesTools) {
  const auto r = readToolLibrary(shippedToolLibraryPath());
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_TRUE(r.diagnostics.empty()) << codes(r.diagnostics);
  for (const char* id :
       {"cnmg-80-r08", "cnmg-80-r04", "dnmg-55-r04", "vnmg-35-r02", "threading-60", "threading-60-id", "grooving-3mm",
        "parting-3mm", "centre-drill", "drill-6mm", "drill-10mm", "drill-16mm", "drill-20mm", "boring-bar-16"}) {
    const LibraryTool* t = r.value->find(id);
    ASSERT_NE(t, nullptr) << id;
    EXPECT_EQ(t->pixelsPerMm, 10.0) << id;
    EXPECT_FALSE(t->nameTh.empty()) << id;
    EXPECT_TRUE(std::filesystem::is_regular_file(r.value->bitmapPath(*t))) << id;
  }
  const LibraryTool& cnmg = *r.value->find("cnmg-80-r08");
  EXPECT_EQ(cnmg.kind, ToolKind::Turning);
  EXPECT_EQ(cnmg.noseRadius, 0.8);
  EXPECT_EQ(cnmg.tip, 3);
  EXPECT_EQ(r.value->find("threading-60-id")->kind, ToolKind::ThreadingId);
  EXPECT_EQ(r.value->find("threading-60-id")->tip, 6);
  EXPECT_EQ(r.value->find("boring-bar-16")->tip, 2);
  EXPECT_EQ(r.value->find("drill-16mm")->size, 16.0);
}

TEST(Library, LineFields) {
  const auto r =
      parseToolLibrary("# comment\n\n  my-tool | grooving | 5 | 0.2 | 3 | 4 | sub/g.png | Groove 4 | มีดกลึงร่อง 4 มม. \n",
                       "/lib", "l.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  ASSERT_EQ(r.value->tools.size(), 1u);
  const LibraryTool& t = r.value->tools[0];
  EXPECT_EQ(t.id, "my-tool");
  EXPECT_EQ(t.kind, ToolKind::Grooving);
  EXPECT_EQ(t.pixelsPerMm, 5.0);
  EXPECT_EQ(t.noseRadius, 0.2);
  EXPECT_EQ(t.size, 4.0);
  EXPECT_EQ(t.nameTh, "มีดกลึงร่อง 4 มม.");
  EXPECT_EQ(r.value->bitmapPath(t), "/lib/sub/g.png");
}

struct BadLine {
  const char* line;
  const char* code;
  int column;
};

class LibraryErrors : public ::testing::TestWithParam<BadLine> {};

TEST_P(LibraryErrors, NameFileLineAndColumn) {
  const std::string good = "ok | turning | 10 | 0.8 | 3 | 0 | ok.png | OK | ดี\n";
  const auto r = parseToolLibrary(good + GetParam().line + "\n", "/lib", "library.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  const Diagnostic& d = r.diagnostics[0];
  EXPECT_EQ(d.code, GetParam().code);
  EXPECT_EQ(d.range.line, 2);
  EXPECT_EQ(d.range.column, GetParam().column);
  EXPECT_EQ(d.args.at(0), "library.cfg");
  EXPECT_NE(formatMessage(d, Lang::Th), formatMessage(d, Lang::En));
  EXPECT_EQ(r.value->tools.size(), 1u);  // the bad line is left out, the good one kept
}

INSTANTIATE_TEST_SUITE_P(
    Cases, LibraryErrors,
    ::testing::Values(BadLine{"x | turning | 10", "F160", 1},
                      BadLine{"Bad_ID! | turning | 10 | 0 | 3 | 0 | a.png | A | ก", "F161", 1},
                      BadLine{"ok | turning | 10 | 0 | 3 | 0 | a.png | A | ก", "F162", 1},
                      BadLine{"t2 | knurling | 10 | 0 | 3 | 0 | a.png | A | ก", "F163", 6},
                      BadLine{"t2 | turning | 0.5 | 0 | 3 | 0 | a.png | A | ก", "F164", 16},
                      BadLine{"t2 | turning | 10 | -1 | 3 | 0 | a.png | A | ก", "F165", 21},
                      BadLine{"t2 | turning | 10 | 0 | 12 | 0 | a.png | A | ก", "F166", 25},
                      BadLine{"t2 | turning | 10 | 0 | 3 | 0 | a.gif | A | ก", "F167", 33},
                      BadLine{"t2 | turning | 10 | 0 | 3 | 0 | a.png |  | ก", "F168", 40},
                      BadLine{"t2 | turning | 10 | 0 | 3 | 0 | a.png | A | ก | material=hss edge=x", "F172", 62},
                      BadLine{"t2 | turning | 10 | 0 | 3 | 0 | a.png | A | ก | material=steel", "F172", 49}));

// Issue 39: the optional 10th field says the tool's cutting material and its edge's length.
TEST(Library, ToolMaterialAndEdgeAreOptional) {
  const auto r = parseToolLibrary(
      "a | turning | 10 | 0.8 | 3 | 0 | a.png | A | ก | material=coated-carbide edge=12.9\n"
      "b | drill | 10 | 0 | 7 | 8 | b.png | B | ข |  material=hss \n"
      "c | turning | 10 | 0.4 | 3 | 0 | c.png | C | ค\n",
      "/lib", "library.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  ASSERT_EQ(r.value->tools.size(), 3u);
  EXPECT_EQ(r.value->tools[0].material, "coated-carbide");
  EXPECT_DOUBLE_EQ(r.value->tools[0].edge, 12.9);
  EXPECT_EQ(r.value->tools[1].material, "hss");
  EXPECT_DOUBLE_EQ(r.value->tools[1].edge, 0.0);
  EXPECT_EQ(r.value->tools[2].material, "");
  // The shipped library says every tool's material.
  for (const LibraryTool& t : shippedToolLibrary().tools) EXPECT_FALSE(t.material.empty()) << t.id;
}

TEST(Library, AMissingBitmapIsF169OnItsLine) {
  const auto dir = std::filesystem::temp_directory_path() / ("klueng-library-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "library.cfg").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fputs("# tools\ngone | drill | 10 | 0 | 7 | 8 | gone.png | Drill 8 | ดอกสว่าน 8 มม.\n", f);
    std::fclose(f);
  }
  const auto r = readToolLibrary(path);
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F169");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{2, 1, 4}));
  std::filesystem::remove_all(dir);
}

// Issue 39: a station's line may say its tool's cutting material after ` | `; it is written back.
TEST(Library, ToolsCfgLineSaysTheToolMaterial) {
  const auto r =
      parseToolTable("a.bmp | material=hss\n\nlibrary:cnmg-80-r04 | material=carbide\nb.bmp\n\n\n\n\n", "/d", "t.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->bitmap[0], "a.bmp");
  EXPECT_EQ(r.value->material[0], "hss");
  EXPECT_EQ(r.value->libraryId(3), "cnmg-80-r04");
  EXPECT_EQ(r.value->material[2], "carbide");
  EXPECT_EQ(r.value->material[3], "");
  EXPECT_EQ(formatToolTable(*r.value),
            "a.bmp | material=hss\n\nlibrary:cnmg-80-r04 | material=carbide\nb.bmp\n\n\n\n\n");
  const auto bad = parseToolTable("a.bmp | material=diamond\n\n\n\n\n\n\n\n", "/d", "t.cfg");
  ASSERT_EQ(bad.diagnostics.size(), 1u) << codes(bad.diagnostics);
  EXPECT_EQ(bad.diagnostics[0].code, "F175");
  EXPECT_EQ(bad.diagnostics[0].range, (SourceRange{1, 9, 16}));
  EXPECT_EQ(bad.value->bitmap[0], "a.bmp");  // the tool itself is kept
}

TEST(Library, ToolsCfgNamesALibraryTool) {
  const auto r = parseToolTable("a.bmp\n\nlibrary:threading-60\n\n\n\n\n\n\n\n\nlibrary: parting-3mm\n", "/d", "t.cfg");
  ASSERT_TRUE(r.ok()) << codes(r.diagnostics);
  EXPECT_EQ(r.value->libraryId(3), "threading-60");
  EXPECT_EQ(r.value->pixelsPerMmOf(3), 10.0);
  EXPECT_EQ(r.value->pixelsPerMmOf(1), 2.0);
  EXPECT_TRUE(std::filesystem::is_regular_file(r.value->bitmapPath(3))) << r.value->bitmapPath(3);
  EXPECT_TRUE(std::filesystem::is_regular_file(r.value->bitmapPath(12)));
  EXPECT_EQ(r.value->bitmapPath(1), "/d/a.bmp");
}

TEST(Library, AnUnknownLibraryToolInToolsCfgIsF123WithTheIds) {
  const auto r = parseToolTable("a.bmp\nlibrary:knurl-30\n\n\n\n\n\n\n", "/d", "t.cfg");
  ASSERT_EQ(r.diagnostics.size(), 1u) << codes(r.diagnostics);
  EXPECT_EQ(r.diagnostics[0].code, "F123");
  EXPECT_EQ(r.diagnostics[0].range, (SourceRange{2, 9, 8}));
  EXPECT_NE(r.diagnostics[0].args.at(3).find("parting-3mm"), std::string::npos);
  EXPECT_EQ(r.value->bitmapPath(2), "");
}

TEST(Library, KindsOfTheSeedsBitmaps) {
  EXPECT_EQ(guessToolKind("resources/tools/01-outside-turning.bmp"), ToolKind::Turning);
  EXPECT_EQ(guessToolKind("02-outside-left-hand.bmp"), ToolKind::Unknown);
  EXPECT_EQ(guessToolKind("03-threading-60.bmp"), ToolKind::ThreadingOd);
  EXPECT_EQ(guessToolKind("04-grooving-3mm.bmp"), ToolKind::Grooving);
  EXPECT_EQ(guessToolKind("05-boring-bar.bmp"), ToolKind::Boring);
  EXPECT_EQ(guessToolKind("06-drill-10mm.bmp"), ToolKind::Drill);
  EXPECT_EQ(guessToolKind("07-parting-3mm.bmp"), ToolKind::Parting);
  EXPECT_EQ(guessToolKind("08-inside-threading.bmp"), ToolKind::ThreadingId);
  EXPECT_TRUE(toolKindFits(ToolKind::Grooving, ToolKind::Parting));
  EXPECT_TRUE(toolKindFits(ToolKind::Unknown, ToolKind::Drill));
  EXPECT_FALSE(toolKindFits(ToolKind::Turning, ToolKind::Parting));
  EXPECT_FALSE(toolKindFits(ToolKind::ThreadingOd, ToolKind::ThreadingId));
}

}  // namespace
}  // namespace klueng::core::io::tool_library_test
