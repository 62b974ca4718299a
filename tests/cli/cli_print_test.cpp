// klueng-cli print (issue 10, item 6): the program sheet and the dimensioned
// drawing of one program as a PDF, read back with pdftotext and pdfinfo.
#include <unistd.h>
#include <gtest/gtest.h>

#include <array>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <cctype>
#include <vector>
#include <sstream>
#include "../scratch_folders.h"

// Its own namespace: the tests are unity-built and sibling files have helpers of the same names.
namespace cli_print_test {

namespace {

namespace fs = std::filesystem;

std::string capture(const std::string& command, int* status = nullptr) {
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return {};
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int rc = ::pclose(pipe);
  if (status) *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

int print(const std::string& args, std::string* err = nullptr) {
  int status = -1;
  const std::string out = capture("env LC_ALL= LC_MESSAGES= LANG=C '" + std::string(KLUENG_CLI_PATH) + "' print " +
                                      args + " --config '" + KLUENG_SOURCE_DIR + "' 2>&1 >/dev/null",
                                  &status);
  if (err) *err = out;
  return status;
}

std::string pdfText(const fs::path& pdf) { return capture("pdftotext -layout '" + pdf.string() + "' - 2>/dev/null"); }
std::string pdfInfo(const fs::path& pdf) { return capture("pdfinfo -l 9 '" + pdf.string() + "' 2>/dev/null"); }

fs::path scratch(const char* name) {
  const fs::path dir = fs::temp_directory_path() / ("klueng_cli_print_test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

const std::string kSample01 = std::string(KLUENG_SAMPLES_DIR) + "/01-step-shaft.txt";

// The drawing's own text without the list of the roughness the cuts leave (issue 39; read by its
// own test): the dimensions' tests look at the dimensions alone. A row's words are one space
// apart, the layout's columns two or more.
std::string withoutFinishList(std::string text) {
  static const std::regex heading("Roughness the cuts leave \\(theoretical, Ra = f²/32r\\)");
  static const std::regex row("(?:\\S+ )*\\S+: Ra [0-9.]+ µm \\(Rz [0-9.]+\\), line [0-9]+, f [0-9.]+ \\S+, R[0-9.]+");
  static const std::regex more("… and [0-9]+ more surfaces");
  for (const std::regex* r : {&heading, &row, &more}) text = std::regex_replace(text, *r, "");
  return text;
}

// The drawing sheet of a program we write, on the bar `stock` (--stock), as text;
// empty (with the CLI's messages in `err`) when print failed.
std::string drawingOf(const char* name, const std::string& program, const std::string& stock, std::string& err) {
  const fs::path prog = scratch((std::string(name) + ".nc").c_str());
  std::ofstream(prog) << program;
  const fs::path pdf = scratch((std::string(name) + ".pdf").c_str());
  if (print("'" + prog.string() + "' --sheet drawing --stock " + stock + " --lang en --pdf '" + pdf.string() + "'",
            &err) != 0)
    return {};
  return withoutFinishList(pdfText(pdf));
}

TEST(CliPrint, DrawingDimensionsSample01OnALandscapePage) {
  const fs::path pdf = scratch("01-drawing.pdf");
  std::string err;
  ASSERT_EQ(print("'" + kSample01 + "' --sheet drawing --lang en --pdf '" + pdf.string() + "'", &err), 0) << err;
  EXPECT_FALSE(fs::exists(pdf.string() + ".partial"));
  const std::string text = pdfText(pdf);
  // Every diameter, the chamfers and the corner radius, the chained steps and the overall length.
  for (const char* s :
       {"Part Drawing", "Ø30", "Ø40", "Ø46", "C3", "C1", "R2", "60", "Scale 1:1", "Inside corners: tool nose R0.8"})
    EXPECT_NE(text.find(s), std::string::npos) << s << "\n" << text;
  // The finished part only (issue 28 item 3): the Ø50 bar left in the chuck (Z-60 to Z-100) is
  // neither drawn nor dimensioned, and the overall length is the part's 60, not the bar's 100.
  for (const char* s : {"Ø50", "100"}) EXPECT_EQ(text.find(s), std::string::npos) << s << "\n" << text;
  const std::string info = pdfInfo(pdf);
  EXPECT_NE(info.find("Pages:           1"), std::string::npos) << info;
  EXPECT_NE(info.find("Page    1 size:  842 x 595 pts (A4)"), std::string::npos) << info;
}

// Issue 39 item 3: the drawing sheet lists the roughness each finished surface got from the cut
// that left it. Sample 01 finishes every surface at F0.1 with the R0.8 of offset 01:
// Ra = 0.1^2 / (32 * 0.8) * 1000 = 0.39 um, Rz = 0.1^2 / (8 * 0.8) * 1000 = 1.6 um.
TEST(CliPrint, TheDrawingListsTheRoughnessEachSurfaceGot) {
  const fs::path pdf = scratch("01-finish.pdf");
  std::string err;
  ASSERT_EQ(print("'" + kSample01 + "' --sheet drawing --lang en --pdf '" + pdf.string() + "'", &err), 0) << err;
  const std::string text = pdfText(pdf);
  for (const char* s :
       {"Roughness the cuts leave (theoretical, Ra = f²/32r)",
        "Ø30 Z-3…-19.2: Ra 0.39 µm (Rz 1.6), line 44, f 0.1 mm/rev, R0.8",
        "Ø46 Z-41…-60: Ra 0.39 µm (Rz 1.6), line 50, f 0.1 mm/rev, R0.8", "Face Z-40: Ra 0.39 µm (Rz 1.6), line 49"})
    EXPECT_NE(text.find(s), std::string::npos) << s << "\n" << text;
  // In Thai.
  ASSERT_EQ(print("'" + kSample01 + "' --sheet drawing --lang th --pdf '" + pdf.string() + "'", &err), 0) << err;
  const std::string thai = pdfText(pdf);
  EXPECT_NE(thai.find("Ra 0.39 ไมครอน (Rz 1.6) บรรทัด 44"), std::string::npos) << thai;
}

// Issue 28 item 3: a program printed with the part design it came from carries
// the design's tolerances after its diameters (an ISO fit, ±) and its roughness marks.
TEST(CliPrint, TheDesignsTolerancesAreWrittenAfterItsDiameters) {
  const fs::path design = scratch("shaft-tolerances.json");
  std::ofstream(design) << R"({"name": "Step shaft", "material": "aluminium", "stock": {"diameter": 50, "length": 100},
    "outside": [{"cylinder": 30, "length": 20, "chamfer": 3, "tolerance": "h7", "roughness": 1.6},
                {"cylinder": 40, "length": 20, "round": 2, "tolerance": 0.05},
                {"cylinder": 46, "length": 20, "chamfer": 1}]})";
  const fs::path pdf = scratch("shaft-tolerances.pdf");
  std::string err;
  ASSERT_EQ(print("'" + kSample01 + "' --sheet drawing --design '" + design.string() + "' --pdf '" + pdf.string() + "'",
                  &err),
            0)
      << err;
  const std::string text = withoutFinishList(pdfText(pdf));
  EXPECT_NE(text.find("Ø30 h7"), std::string::npos) << text;
  EXPECT_NE(text.find("Ø40 ±0.05"), std::string::npos) << text;
  EXPECT_NE(text.find("Ø46"), std::string::npos) << text;
  EXPECT_EQ(text.find("Ø46 "), std::string::npos) << text;    // no tolerance where the design has none
  EXPECT_NE(text.find("Ra 1.6"), std::string::npos) << text;  // the Ø30's surface finish mark
  EXPECT_EQ(text.find("Ra ", text.find("Ra 1.6") + 1), std::string::npos) << text;  // and only there
  // A design that cannot be read names its field, and the command exits 2.
  const fs::path bad = scratch("shaft-bad.json");
  std::ofstream(bad) << "{\"outside\": [{\"cylinder\": 30, \"length\": 20, \"tolerance\": \"zz9\"}]}";
  EXPECT_EQ(print("'" + kSample01 + "' --design '" + bad.string() + "' --pdf '" + pdf.string() + "'", &err), 2);
  EXPECT_NE(err.find("shaft-bad.json: error F182"), std::string::npos) << err;
  EXPECT_NE(err.find("outside[0].tolerance"), std::string::npos) << err;
}

// A cylinder running into a taper has no face between them: the chained lengths
// still say where the taper starts and ends (20, 20, 10 and 50 overall), and no
// radius callout comes from the compensated corners.
TEST(CliPrint, ATapersEndsAreDimensionedAlongTheAxis) {
  std::string err;
  const std::string text = drawingOf("taper-pin",
                                     "%\nO2001 (TAPER PIN 1:5)\nG21 G40 G99\nT0101\nG50 S2500\nG96 S200 M03\n"
                                     "G00 X34. Z2. M08\nG01 Z0. F0.15\nX-1.6\nG00 X34. Z2.\nG42 G00 X20. Z2.\n"
                                     "G01 Z-20. F0.15\nX28. Z-40.\nZ-50.\nX34.\nG40 G00 X100. Z100.\nM30\n%\n",
                                     "32x80", err);
  ASSERT_FALSE(text.empty()) << err;
  const std::string lengths = text.substr(0, text.find("Project"));
  for (const char* s : {"Ø20", "Ø28", "11.31°", " 10 ", " 20 "})
    EXPECT_NE(lengths.find(s), std::string::npos) << s << "\n" << text;
  EXPECT_NE(text.find(" 50\n"), std::string::npos) << text;  // the overall length on its own row
  EXPECT_EQ(std::count(lengths.begin(), lengths.end(), 'R'), 0) << text;
}

// A flange's 4 mm spigot is 2 mm on paper at 1:2: too short for a Ø line beside
// another, yet the drawing still gives its Ø (a drawing without it cannot be made).
TEST(CliPrint, AShortSpigotOnABigFlangeKeepsItsDiameter) {
  std::string err;
  const std::string text =
      drawingOf("flange",
                "%\nO3001 (FLANGE)\nG21 G40 G99\nT0101\nG50 S1500\nG96 S180 M03\nG00 X214. Z2. M08\n"
                "G01 Z0. F0.2\nX-1.6\nG00 X214. Z2.\nG42 G00 X150. Z2.\nG01 Z-4. F0.15\nX200.\nZ-20.\n"
                "X214.\nG40 G00 X300. Z100.\nM30\n%\n",
                "210x40", err);
  ASSERT_FALSE(text.empty()) << err;
  for (const char* s : {"Scale 1:2", "Ø150", "Ø200"}) EXPECT_NE(text.find(s), std::string::npos) << s << "\n" << text;
}

// A groove is placed by its near wall and its width is in its callout: the chain
// reads 10, 10, 20 (to each groove's right wall, then the end), not 10, 3, 7, 3, 17.
TEST(CliPrint, AGrooveIsPlacedByItsNearWall) {
  std::string err;
  const std::string text =
      drawingOf("grooves",
                "%\nO4001 (TWO GROOVES)\nG21 G40 G99\nT0101\nG96 S180 M03\nG50 S2500\nG00 X34. Z2. M08\n"
                "G01 Z0. F0.15\nX-1.6\nG00 X30. Z2.\nG01 Z-40.\nX34.\nG00 X100. Z100.\nT0404\n"
                "G97 S600 M03\nG00 X32. Z-13.\nG01 X24. F0.05\nG00 X32.\nZ-23.\nG01 X24.\nG00 X32.\n"
                "X100. Z100.\nM30\n%\n",
                "32x80", err);
  ASSERT_FALSE(text.empty()) << err;
  std::istringstream words(text);
  std::vector<std::string> numbers;
  for (std::string w; words >> w;)
    if (!w.empty() &&
        std::all_of(w.begin(), w.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      numbers.push_back(w);
  EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "10"), 2);
  EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "20"), 1);
  EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "40"), 1);  // overall
  for (const char* gone : {"7", "17"}) EXPECT_EQ(std::count(numbers.begin(), numbers.end(), gone), 0) << gone;
  EXPECT_EQ(std::count(numbers.begin(), numbers.end(), "3"), 2);  // only the callouts' "groove 3 × Ø24"
}

TEST(CliPrint, BothSheetsInThaiAndTheThreadCallout) {
  const fs::path pdf = scratch("02-both.pdf");
  std::string err;
  ASSERT_EQ(
      print("'" + std::string(KLUENG_SAMPLES_DIR) + "/02-thread.txt' --lang th --pdf '" + pdf.string() + "'", &err), 0)
      << err;
  const std::string text = pdfText(pdf);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\f'), 2);  // the listing, then the drawing
  for (const char* s : {"ชุดรหัส", "N130 G32 Z-30. F1.5", "เอกสารแสดงภาพชิ้นงาน", "M30×1.5", "Ø30"})
    EXPECT_NE(text.find(s), std::string::npos) << s << "\n" << text;
  // The Ø32 bar the program never touched (Z-40 to Z-80) is not the bolt.
  EXPECT_EQ(text.substr(text.find('\f')).find("Ø32"), std::string::npos) << text;
  const std::string info = pdfInfo(pdf);
  EXPECT_NE(info.find("Page    1 size:  595 x 842 pts (A4)"), std::string::npos) << info;
  EXPECT_NE(info.find("Page    2 size:  842 x 595 pts (A4)"), std::string::npos) << info;
}

TEST(CliPrint, StockOptionAndAProgramWithErrors) {
  // --stock as simulate takes it: the sheet's stock is Ø60 × 120; the drawing is still the
  // part alone, 60 long, without the Ø60 bar it was turned from.
  const fs::path pdf = scratch("01-stock.pdf");
  std::string err;
  ASSERT_EQ(print("'" + kSample01 + "' --stock 60x120 --pdf '" + pdf.string() + "'", &err), 0) << err;
  const std::string text = withoutFinishList(pdfText(pdf));
  const std::string drawing = text.substr(text.find('\f'));
  EXPECT_NE(text.find("120"), std::string::npos) << text;
  EXPECT_EQ(drawing.find("Ø60"), std::string::npos) << drawing;
  EXPECT_EQ(drawing.find("120"), std::string::npos) << drawing;
  EXPECT_NE(drawing.find("Ø46"), std::string::npos) << drawing;

  // Errors are printed GCC-style; the sheets still come out, the drawing says why it shows the bar.
  const fs::path bad = scratch("bad.nc");
  std::ofstream(bad) << "O0001\nN10 G01 X20. Z-5 F\nN20 M30\n";
  const fs::path badPdf = scratch("bad.pdf");
  EXPECT_EQ(print("'" + bad.string() + "' --pdf '" + badPdf.string() + "'", &err), 1);
  EXPECT_NE(err.find("bad.nc:2:"), std::string::npos) << err;
  EXPECT_NE(pdfText(badPdf).find("The program has errors"), std::string::npos);
}

TEST(CliPrint, BadCommandLinesExitTwo) {
  EXPECT_EQ(print("'" + kSample01 + "'"), 2);  // no --pdf
  const fs::path never = scratch("never.pdf");
  fs::remove(never);
  EXPECT_EQ(print("'" + kSample01 + "' --pdf '" + never.string() + "' --sheet poster"), 2);
  EXPECT_EQ(print("/no/such/file.nc --pdf '" + never.string() + "'"), 2);
  EXPECT_FALSE(fs::exists(never));
}

}  // namespace

namespace {

// Issue 14 (first step): klueng-cli generate writes a program that checks clean;
// a part that cannot be turned writes nothing and says why.
TEST(CliGenerate, StepShaftInEveryDialectAndAnUndercut) {
  for (const char* dialect : {"fanuc", "haas", "classic"}) {
    const fs::path out = scratch((std::string("gen-") + dialect + ".nc").c_str());
    int status = -1;
    const std::string err = capture("'" + std::string(KLUENG_CLI_PATH) + "' generate '" + KLUENG_SOURCE_DIR +
                                        "/resources/parts/step-shaft.json' --dialect " + dialect + " -o '" +
                                        out.string() + "' --config '" + KLUENG_SOURCE_DIR + "' 2>&1",
                                    &status);
    ASSERT_EQ(status, 0) << err;
    const std::string check = capture(
        "'" + std::string(KLUENG_CLI_PATH) + "' check '" + out.string() + "' --dialect " + dialect + " 2>&1", &status);
    EXPECT_EQ(status, 0) << dialect << "\n" << check;
  }
  const fs::path bad = scratch("undercut.json");
  std::ofstream(bad) << "{\"stock\": {\"diameter\": 50, \"length\": 100}, \"material\": \"steel\",\n"
                        " \"outside\": [{\"cylinder\": 30, \"length\": 10}, {\"cylinder\": 20, \"length\": 10}]}\n";
  const fs::path out = scratch("undercut.nc");
  fs::remove(out);
  int status = -1;
  const std::string err =
      capture("env LC_ALL= LANG=C '" + std::string(KLUENG_CLI_PATH) + "' generate '" + bad.string() + "' -o '" +
                  out.string() + "' --config '" + KLUENG_SOURCE_DIR + "' 2>&1",
              &status);
  EXPECT_EQ(status, 1);
  EXPECT_NE(err.find("error E501: Step 2 (Ø20.) is thinner"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out));
}

// A DXF half section written as a CAD program writes the simplest one: LINE
// entities (group codes 0/8/10/20/11/21) in an ENTITIES section.
std::string dxfOfLines(const std::vector<std::array<double, 4>>& lines) {
  std::string t = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
  for (const auto& l : lines)
    t += "0\nLINE\n8\nPART\n10\n" + std::to_string(l[0]) + "\n20\n" + std::to_string(l[1]) + "\n30\n0.0\n11\n" +
         std::to_string(l[2]) + "\n21\n" + std::to_string(l[3]) + "\n31\n0.0\n";
  return t + "0\nENDSEC\n0\nEOF\n";
}

TEST(CliGenerate, ADxfDrawingBecomesAProgramAndAnOpenOneWritesNothing) {
  // A Ø40 pin with C2 on a Ø30 spigot 25 long, 55 long in all, drawn with its face at X0.
  const std::vector<std::array<double, 4>> pin{{0, 0, 0, 13},      {0, 13, -2, 15},    {-2, 15, -25, 15},
                                               {-25, 15, -25, 20}, {-25, 20, -55, 20}, {-55, 20, -55, 0}};
  const fs::path dxf = scratch("pin.dxf");
  std::ofstream(dxf) << dxfOfLines(pin);
  const fs::path out = scratch("pin.nc");
  fs::remove(out);
  int status = -1;
  const std::string cli = "env LC_ALL= LANG=C '" + std::string(KLUENG_CLI_PATH) + "' ";
  std::string err = capture(cli + "generate '" + dxf.string() + "' --dialect haas --stock 45x90 -o '" + out.string() +
                                "' --config '" + KLUENG_SOURCE_DIR + "' 2>&1",
                            &status);
  ASSERT_EQ(status, 0) << err;
  std::ifstream in(out);
  const std::string program((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(program.find("\n145\n190\n"), std::string::npos) << program;   // the bar from --stock
  EXPECT_NE(program.find("G01 X30. Z-2."), std::string::npos) << program;  // the C2 chamfer
  EXPECT_NE(program.find("G01 X40. Z-55."), std::string::npos);
  std::string check = capture(cli + "check '" + out.string() + "' --dialect haas 2>&1", &status);
  EXPECT_EQ(status, 0) << check;
  // Without the spigot's line the outline is open: exit 2, the place named, nothing written.
  std::vector<std::array<double, 4>> open = pin;
  open.erase(open.begin() + 2);
  std::ofstream(dxf) << dxfOfLines(open);
  fs::remove(out);
  err = capture(
      cli + "generate '" + dxf.string() + "' -o '" + out.string() + "' --config '" + KLUENG_SOURCE_DIR + "' 2>&1",
      &status);
  EXPECT_EQ(status, 2);
  EXPECT_NE(err.find("error F189: " + dxf.string() +
                     ": the outline is open at X-2.000 Y15.000: the nearest other "
                     "end is 23.000 mm away"),
            std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

}  // namespace cli_print_test

// Its scratch folders go with the process: nothing left in /tmp after a run.
[[maybe_unused]] ::testing::Environment* const kCliPrintScratchCleanup =
    klueng::test::removeScratchFoldersAtExit({"klueng_cli_print_test-"});
