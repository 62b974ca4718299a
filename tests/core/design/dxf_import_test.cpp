// DXF drawings to part designs (issue 14): the tests draw with dxflib's own
// writer — sample 01's half section as lines and an arc, the same as one
// polyline in inches, the threaded bush's section with its bore — and read
// them back to the shipped designs; bad drawings name the place.
#include <dxflib/dl_dxf.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>

#include "design_test_util.h"
#include "klueng/core/design/dxf_import.h"

namespace klueng::core::design {
namespace {

// A drawing written by dxflib to a scratch file and read back as text.
class Sketch {
 public:
  explicit Sketch(int insunits = 4)
      : path_(std::filesystem::temp_directory_path() /
              ("klueng-dxf-" + std::to_string(::getpid()) + "-" + std::to_string(next_++) + ".dxf")) {
    writer_ = dxf_.out(path_.c_str(), DL_Codes::AC1015);
    dxf_.writeHeader(*writer_);
    writer_->dxfString(9, "$INSUNITS");
    writer_->dxfInt(70, insunits);
    writer_->sectionEnd();
    writer_->sectionEntities();
  }
  ~Sketch() { std::filesystem::remove(path_); }
  Sketch& line(double x1, double y1, double x2, double y2, const std::string& layer = "PROFILE",
               const std::string& linetype = "BYLAYER") {
    dxf_.writeLine(*writer_, DL_LineData(x1, y1, 0.0, x2, y2, 0.0), DL_Attributes(layer, 256, -1, linetype, 1.0));
    return *this;
  }
  Sketch& arc(double cx, double cy, double r, double a1, double a2, const std::string& layer = "PROFILE") {
    dxf_.writeArc(*writer_, DL_ArcData(cx, cy, 0.0, r, a1, a2), DL_Attributes(layer, 256, -1, "BYLAYER", 1.0));
    return *this;
  }
  // A polyline through (x, y, bulge) vertices.
  Sketch& polyline(const std::vector<std::array<double, 3>>& v, bool closed, const std::string& layer = "PROFILE") {
    dxf_.writePolyline(*writer_, DL_PolylineData(static_cast<int>(v.size()), 0, 0, closed ? 1 : 0),
                       DL_Attributes(layer, 256, -1, "BYLAYER", 1.0));
    for (const auto& p : v) dxf_.writeVertex(*writer_, DL_VertexData(p[0], p[1], 0.0, p[2]));
    dxf_.writePolylineEnd(*writer_);
    return *this;
  }
  Sketch& spline(double x, double y, const std::string& layer = "PROFILE") {
    dxf_.writeSpline(*writer_, DL_SplineData(3, 8, 4, 0, 8), DL_Attributes(layer, 256, -1, "BYLAYER", 1.0));
    for (int k = 0; k < 4; ++k) dxf_.writeControlPoint(*writer_, DL_ControlPointData(x + k, y + (k % 2), 0.0, 1.0));
    for (int k = 0; k < 8; ++k) dxf_.writeKnot(*writer_, DL_KnotData(k < 4 ? 0.0 : 1.0));
    return *this;
  }
  std::string text() {
    if (writer_) {
      writer_->sectionEnd();
      writer_->dxfEOF();
      writer_->close();
      delete writer_;
      writer_ = nullptr;
    }
    return slurp(path_.string());
  }

 private:
  static inline int next_ = 0;
  std::filesystem::path path_;
  DL_Dxf dxf_;
  DL_WriterA* writer_ = nullptr;
};

// Sample 01's half section, its face at X`right`, the axis at Y`axis`, scaled by `k` (1/25.4 for inches).
void drawStepShaft(Sketch& s, double right, double axis, double k = 1.0, bool closeAlongAxis = true) {
  const auto P = [&](double z, double r) { return std::pair{right + z * k, axis + r * k}; };
  const auto L = [&](double z1, double r1, double z2, double r2) {
    const auto [x1, y1] = P(z1, r1);
    const auto [x2, y2] = P(z2, r2);
    s.line(x1, y1, x2, y2);
  };
  L(0, 0, 0, 12);      // the face
  L(0, 12, -3, 15);    // C3
  L(-3, 15, -20, 15);  // Ø30
  L(-20, 15, -20, 18);
  const auto [cx, cy] = P(-22, 18);
  s.arc(cx, cy, 2 * k, 0.0, 90.0);  // R2, from (-20, 18) round to (-22, 20)
  L(-22, 20, -40, 20);              // Ø40
  L(-40, 20, -40, 22);
  L(-40, 22, -41, 23);  // C1
  L(-41, 23, -60, 23);  // Ø46
  L(-60, 23, -60, 0);   // the left end
  if (closeAlongAxis) L(-60, 0, 0, 0);
}

void expectSameSteps(const std::vector<OutsideStep>& got, const std::vector<OutsideStep>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_EQ(got[k].kind, want[k].kind) << k;
    EXPECT_DOUBLE_EQ(got[k].diameter, want[k].diameter) << k;
    EXPECT_DOUBLE_EQ(got[k].length, want[k].length) << k;
    EXPECT_EQ(got[k].edge, want[k].edge) << k;
    EXPECT_DOUBLE_EQ(got[k].edgeSize, want[k].edgeSize) << k;
  }
}

TEST(DxfImport, Sample01sSectionReadsAsTheStepShaftDesign) {
  Sketch s;
  drawStepShaft(s, 160.0, 40.0);
  s.line(90.0, 40.0, 170.0, 40.0, "AXES", "CENTER");  // the centre line, longer than the part
  s.line(100.0, 20.0, 160.0, 20.0, "DIMENSIONS");     // a dimension line below: another layer
  const std::string text = s.text();
  // Two layers with lines: the user must pick one.
  const auto unpicked = importDxf(text, "shaft.dxf");
  ASSERT_FALSE(unpicked.ok());
  EXPECT_EQ(unpicked.diagnostics.at(0).code, "F187");
  EXPECT_EQ(formatMessage(unpicked.diagnostics[0], Lang::En),
            "shaft.dxf: the drawing has lines on several layers (DIMENSIONS, PROFILE): choose the layer of the part's "
            "outline");
  EXPECT_EQ(dxfOutlineLayers(text), (std::vector<std::string>{"DIMENSIONS", "PROFILE"}));
  DxfImportOptions options;
  options.layer = "PROFILE";
  const auto design = importDxf(text, "shaft.dxf", options);
  ASSERT_TRUE(design.ok()) << (design.diagnostics.empty() ? "" : formatMessage(design.diagnostics[0], Lang::En));
  expectSameSteps(design.value->outside, stepShaft().outside);
  EXPECT_TRUE(design.value->inside.empty());
  EXPECT_EQ(design.value->name, "shaft");
  // The bar: the next 5 mm above Ø46 + 2, and 60 mm + 15 grip + 5, in 5 mm.
  EXPECT_DOUBLE_EQ(design.value->stockDiameter, 50.0);
  EXPECT_DOUBLE_EQ(design.value->stockLength, 80.0);
  // And it generates a program that cuts the drawing (the generator's own test proves the cut).
  EXPECT_TRUE(generateProgram(*design.value, {}));
}

TEST(DxfImport, OnePolylineInInchesWithABulgeReadsTheSame) {
  const double k = 1.0 / 25.4;
  // Without a centre line the axis is the outline's lowest Y; drawn right to left, open along the axis.
  const double tq = std::tan(M_PI / 8.0);  // a quarter arc's bulge, counter-clockwise
  std::vector<std::array<double, 3>> v;
  for (const auto& [z, r, bulge] : std::vector<std::array<double, 3>>{{0, 0, 0},
                                                                      {0, 12, 0},
                                                                      {-3, 15, 0},
                                                                      {-20, 15, 0},
                                                                      {-20, 18, tq},
                                                                      {-22, 20, 0},
                                                                      {-40, 20, 0},
                                                                      {-40, 22, 0},
                                                                      {-41, 23, 0},
                                                                      {-60, 23, 0},
                                                                      {-60, 0, 0}})
    v.push_back({3.0 + z * k, 1.0 + r * k, bulge});
  Sketch s(1);
  s.polyline(v, false);
  const auto design = importDxf(s.text(), "shaft-in.dxf");
  ASSERT_TRUE(design.ok()) << formatMessage(design.diagnostics.at(0), Lang::En);
  expectSameSteps(design.value->outside, stepShaft().outside);
  ASSERT_EQ(design.diagnostics.size(), 1u);  // a note: inches to millimetres
  EXPECT_EQ(design.diagnostics[0].code, "I180");
  EXPECT_EQ(formatMessage(design.diagnostics[0], Lang::En),
            "shaft-in.dxf: the drawing is in inches: sizes multiplied by 25.4 to millimetres");
}

TEST(DxfImport, TheThreadedBushsSectionReadsWithItsGrooveAndBore) {
  // A closed loop: face, outside with the relief groove, left end, bore back to the face.
  Sketch s;
  const auto L = [&](double z1, double r1, double z2, double r2) { s.line(100 + z1, r1, 100 + z2, r2); };
  s.line(40, 0, 110, 0, "0", "CENTER");
  L(0, 11, 0, 13.5), L(0, 13.5, -1.5, 15), L(-1.5, 15, -24, 15);          // C1.5 and Ø30
  L(-24, 15, -24, 13.5), L(-24, 13.5, -28, 13.5), L(-28, 13.5, -28, 15);  // groove 4 wide to Ø27
  L(-28, 15, -28, 22), L(-28, 22, -29, 23), L(-29, 23, -50, 23);          // C1 and Ø46
  L(-50, 23, -50, 9), L(-50, 9, -30, 9), L(-30, 9, -30, 10), L(-30, 10, -1, 10), L(-1, 10, 0, 11);  // the bore
  const auto design = importDxf(s.text(), "bush.dxf");
  ASSERT_TRUE(design.ok()) << formatMessage(design.diagnostics.at(0), Lang::En);
  const auto bush = readPartDesign(slurp(KLUENG_SOURCE_DIR "/resources/parts/threaded-bush.json"), "b.json");
  ASSERT_TRUE(bush.ok());
  expectSameSteps(design.value->outside, bush.value->outside);
  expectSameSteps(design.value->inside, bush.value->inside);
  ASSERT_EQ(design.value->grooves.size(), 1u);
  EXPECT_DOUBLE_EQ(design.value->grooves[0].z, -24.0);
  EXPECT_DOUBLE_EQ(design.value->grooves[0].width, 4.0);
  EXPECT_DOUBLE_EQ(design.value->grooves[0].diameter, 27.0);
  EXPECT_DOUBLE_EQ(design.value->stockBore, 16.0);  // 2 mm under the Ø18 bore
  EXPECT_DOUBLE_EQ(design.value->stockDiameter, 50.0);
}

// The first diagnostic's code and English text of a drawing.
std::pair<std::string, std::string> firstProblem(const std::string& text, const DxfImportOptions& options = {}) {
  const auto r = importDxf(text, "p.dxf", options);
  EXPECT_FALSE(r.ok());
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::Error) return {d.code, formatMessage(d, Lang::En)};
  return {};
}

TEST(DxfImport, BadDrawingsSayWhatAndWhere) {
  EXPECT_EQ(firstProblem("").first, "F184");
  EXPECT_EQ(firstProblem("  \n\n").first, "F184");
  EXPECT_EQ(firstProblem("hello, this is a letter\n").first, "F185");
  EXPECT_EQ(firstProblem(std::string("AutoCAD Binary DXF\r\n\x1a\0", 22)).second,
            "p.dxf is not an ASCII DXF drawing: it is a binary file (save the drawing as ASCII DXF)");
  // Found by fuzz_design: a polyline's vertex count dxflib would allocate before reading (14 GB here).
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90\n462000000\n10\n0\n20\n0\n0\nENDSEC\n"
                         "0\nEOF\n")
                .second,
            "p.dxf is not an ASCII DXF drawing: line 10 says 462000000 points (group 90), more than the file holds: it "
            "is corrupt");
  // The same with the code written "90?" (dxflib reads its leading number) and a count past a long.
  EXPECT_EQ(
      firstProblem("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90?\n622222222222222222222\n0\nENDSEC\n").first,
      "F185");
  // Found by fuzz_design: a count behind 40 leading zeros (dxflib reads the whole line: 7.8 GB).
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90\n" + std::string(40, '0') +
                         "244839779\n0\nENDSEC\n")
                .second,
            "p.dxf is not an ASCII DXF drawing: line 10 says 244839779 points (group 90), more than the file "
            "holds: it is corrupt");
  // Found by fuzz_design: dxflib starts an entity at group 9 too ("9x0" is 9), and reads a code as an int
  // (4294967296 is 0); a polyline so begun asked for 14.8 GB.
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n9x0\nLWPOLYLINE\n8\nPART\n90\n555555555555552\n0\nENDSEC\n").second,
            "p.dxf is not an ASCII DXF drawing: line 10 says 555555555555552 points (group 90), more than the file "
            "holds: it is corrupt");
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n4294967296\nLWPOLYLINE\n8\nPART\n90\n462000000\n0\nENDSEC\n").first,
            "F185");
  // dxflib throws reading a "999" comment of just "dxflib" (it takes the version from position 7).
  EXPECT_EQ(firstProblem("999\ndxflib\n0\nSECTION\n2\nENTITIES\n0\nENDSEC\n0\nEOF\n").second,
            "p.dxf is not an ASCII DXF drawing: dxflib could not read it");
  // A negative count that dxflib's int makes 1,294,967,296.
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90\n-3000000000\n0\nENDSEC\n").first,
            "F185");
  // A layer name of 3,000 characters: dxflib would read on forever (its lines hold 1,023).
  EXPECT_EQ(firstProblem("0\nSECTION\n2\nENTITIES\n0\nLINE\n8\n" + std::string(3000, 'P') +
                         "\n10\n0\n20\n0\n11\n10\n21\n0\n0\nENDSEC\n0\nEOF\n")
                .second,
            "p.dxf is not an ASCII DXF drawing: line 8 is 3000 characters long (a DXF line holds one code or one "
            "value): it is corrupt");
  {  // In Thai the reason is Thai too.
    const auto read = importDxf("0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nPART\n90\n99999999\n0\nENDSEC\n", "p.dxf");
    ASSERT_FALSE(read.diagnostics.empty());
    EXPECT_EQ(formatMessage(read.diagnostics[0], Lang::Th),
              "p.dxf ไม่ใช่แบบ DXF แบบข้อความ (ASCII): บรรทัด 10 ระบุจำนวนจุด 99999999 (กลุ่ม 90) มากกว่าที่ไฟล์มีอยู่: "
              "ไฟล์เสียหาย");
  }
  {  // Truncated in the middle of an entity: a corrupt file, no crash, no design.
    Sketch s;
    drawStepShaft(s, 60, 0);
    const std::string whole = s.text();
    const auto cut = importDxf(whole.substr(0, whole.size() / 2), "p.dxf");
    EXPECT_FALSE(cut.ok());
    EXPECT_FALSE(cut.diagnostics.empty());
  }
  {  // The Ø40 line missing: open at its two ends.
    Sketch s;
    s.line(60, 0, 60, 12).line(60, 12, 57, 15).line(57, 15, 40, 15).line(40, 15, 40, 18).arc(38, 18, 2, 0, 90);
    s.line(20, 20, 20, 22).line(20, 22, 19, 23).line(19, 23, 0, 23).line(0, 23, 0, 0);
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F190");  // the first loose end is the arc's
    EXPECT_EQ(text,
              "p.dxf: the arc R2.000 ending at X38.000 Y20.000 does not meet its neighbours: the nearest line "
              "ends 18.000 mm away");  // the loose end of the Ø40's shoulder
  }
  {  // The arc drawn 0.3 mm too far left: it meets neither the face nor the Ø40 line.
    Sketch s;
    s.line(60, 0, 60, 12).line(60, 12, 57, 15).line(57, 15, 40, 15).line(40, 15, 40, 18).arc(37.7, 18, 2, 0, 90);
    s.line(38, 20, 20, 20).line(20, 20, 20, 22).line(20, 22, 19, 23).line(19, 23, 0, 23).line(0, 23, 0, 0);
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F189");  // the face's top end comes first, 0.3 from the arc's start
    EXPECT_EQ(text, "p.dxf: the outline is open at X40.000 Y18.000: the nearest other end is 0.300 mm away");
  }
  {  // A spline on the outline's layer.
    Sketch s;
    drawStepShaft(s, 60, 0);
    s.spline(10, 30);
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F188");
    EXPECT_EQ(text.substr(0, 46), "p.dxf: a spline on layer \"PROFILE\" near X10.00");
  }
  {  // Millimetre numbers in a drawing that says metres: a part 46 m across.
    Sketch s(6);
    drawStepShaft(s, 60, 0);
    EXPECT_EQ(firstProblem(s.text()).second,
              "p.dxf: in metres the part would be Ø46000.000 mm and 60000.000 mm long: the drawing's units look wrong "
              "(set $INSUNITS or scale it)");
  }
  {  // Metres without units: 0.046 across.
    Sketch s(0);
    drawStepShaft(s, 0.06, 0, 0.001);
    EXPECT_EQ(firstProblem(s.text()).first, "F192");
  }
  {  // A unit that is no length (3 = miles is one, 11 = ångström another): refused by number.
    Sketch s(3);
    drawStepShaft(s, 60, 0);
    EXPECT_EQ(firstProblem(s.text()).second,
              "p.dxf: the drawing's units ($INSUNITS 3) are not a length Klueng can turn");
  }
  {  // A layer with nothing on it.
    Sketch s;
    drawStepShaft(s, 60, 0);
    DxfImportOptions options;
    options.layer = "OUTLINE";
    EXPECT_EQ(firstProblem(s.text(), options).second,
              "p.dxf: there are no lines or arcs on layer \"OUTLINE\" (layers with lines: PROFILE)");
  }
  {  // A hatch line from a corner: three lines meet there.
    Sketch s;
    drawStepShaft(s, 60, 0);
    s.line(40, 18, 30, 10);
    EXPECT_EQ(firstProblem(s.text()).first, "F193");
  }
  {  // Found by fuzz_design: a cone down to the axis is no step of a turned part (it was a Ø0 taper).
    Sketch s;
    s.line(100, 0, 100, 13).line(100, 13, 98, 15).line(98, 15, 0, 0);
    EXPECT_EQ(firstProblem(s.text()).second,
              "p.dxf: the outline comes down to the axis at X0.000 Y0.000 before the part's left end: no step of a "
              "turned part is Ø0");
  }
  {  // Running back toward the face: an undercut drawn as such.
    Sketch s;
    s.line(60, 0, 60, 15).line(60, 15, 40, 15).line(40, 15, 45, 20).line(45, 20, 0, 20).line(0, 20, 0, 0);
    EXPECT_EQ(firstProblem(s.text()).second,
              "p.dxf: the outline runs back toward the right-hand face at X40.000 Y15.000: a turned profile runs one "
              "way along the axis");
  }
}

// Found by fuzz_design: a polyline with a tiny bulge became an arc of R1.5 km,
// which the part file then refused to read back.
TEST(DxfImport, AnArcFlatterThanTheRoundingIsALineAndAHugeOneIsRefused) {
  {  // Bulge 1e-5 over 30.07 mm: it bows 0.00015 mm, a taper from Ø20 to Ø24.
    Sketch s;
    s.polyline({{100, 0, 0}, {100, 10, 0}, {80, 10, 1e-5}, {50, 12, 0}, {50, 0, 0}}, false);
    const auto read = importDxf(s.text(), "p.dxf");
    ASSERT_TRUE(read.ok()) << (read.diagnostics.empty() ? "" : formatMessage(read.diagnostics[0], Lang::En));
    ASSERT_EQ(read.value->outside.size(), 2u);
    EXPECT_EQ(read.value->outside[1].kind, StepKind::Taper);
    EXPECT_DOUBLE_EQ(read.value->outside[1].diameter, 24.0);
    EXPECT_DOUBLE_EQ(read.value->outside[1].length, 30.0);
    const auto again = readPartDesign(writePartDesign(*read.value), "again.json");
    EXPECT_TRUE(again.ok());
  }
  {  // Bulge 4e-4: R = c(1 + b^2)/(4b) is over 10 km and it bows 0.006 mm: not a line, not a radius to hold.
    Sketch s;
    s.polyline({{100, 0, 0}, {100, 10, 0}, {80, 10, 4e-4}, {50, 12, 0}, {50, 0, 0}}, false);
    const double c = std::hypot(30.0, 2.0), b = 4e-4;
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F197");
    EXPECT_EQ(text, fmt::format("p.dxf: the arc R{:.3f} ending at X50.000 Y12.000 is over 10000 mm, the largest radius "
                                "a part design holds: draw it as a line, or check the drawing's units",
                                c * (1 + b * b) / (4 * b)));
  }
  {  // Found by fuzz_design: an arc in a bore became an arc step the part file cannot hold.
    Sketch s;
    s.line(-5, 0, 45, 0, "CENTER");
    s.polyline({{40, 8, 0}, {40, 20, 0}, {0, 20, 0}, {0, 8, 0.1}}, true);  // the bore dips 2 mm toward the axis
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F198");
    EXPECT_EQ(text,
              "p.dxf: the bore has an arc R101.000 ending at X0.000 Y8.000: a part design bores cylinders and "
              "tapers (with a chamfer or round at their mouth) only");
  }
}

// A taper polyline whose one bulge (group 42) is written as `bulge`, and the
// file line that holds it. (Text, not a double: dxflib's writer prints a real
// with %f into a fixed buffer, so it cannot write 1e300 itself.)
std::pair<std::string, int> withBulge(const std::string& bulge) {
  Sketch s;
  s.polyline({{100, 0, 0}, {100, 10, 0}, {80, 10, 0.25}, {50, 12, 0}, {50, 0, 0}}, false);
  std::string text = s.text();
  std::size_t at = 0;
  int line = 1;
  for (std::size_t next; (next = text.find('\n', at)) != std::string::npos; at = next + 1, ++line) {
    std::string_view code(text.data() + at, next - at);
    while (!code.empty() && code.front() == ' ') code.remove_prefix(1);
    if (line % 2 == 1 && code == "42") {
      const std::size_t value = next + 1, valueEnd = text.find('\n', value);
      text.replace(value, valueEnd - value, bulge);
      return {text, line + 1};
    }
  }
  ADD_FAILURE() << "the sketch has no bulge";
  return {text, 0};
}

// Found by fuzz_design: a bulge too big for a double (dxflib reads -1e405 as
// -1.8e308) made an arc of radius NaN, written to the part file as null.
TEST(DxfImport, ABulgeOrCoordinateBeyondADoubleIsRefusedAtItsLine) {
  const auto [text, line] = withBulge("-1e405");
  const auto [id, message] = firstProblem(text);
  EXPECT_EQ(id, "F185");
  EXPECT_EQ(message, fmt::format("p.dxf is not an ASCII DXF drawing: line {} holds -1e405, which is not a finite "
                                 "number: it is corrupt",
                                 line));
  // A decimal comma is read as dxflib reads it: "1,5e999" is beyond a double too.
  EXPECT_EQ(firstProblem(withBulge("1,5e999").first).first, "F185");
  EXPECT_EQ(firstProblem(withBulge("nan").first).first, "F185");
}

TEST(DxfImport, AHugeFiniteBulgeIsAnArcTooLargeNotANumberlessOne) {
  for (const char* bulge : {"1e300", "-1.7e308"}) {
    const auto read = importDxf(withBulge(bulge).first, "p.dxf");
    ASSERT_FALSE(read.ok()) << bulge;
    const std::string message = formatMessage(read.diagnostics[0], Lang::En);
    EXPECT_EQ(read.diagnostics[0].code, std::string("F197")) << message;
    EXPECT_EQ(message.find("nan"), std::string::npos) << message;
    EXPECT_EQ(message.find("inf"), std::string::npos) << message;
  }
}

// Issue 42 item 6: the messages of a bad drawing read as sentences with sane numbers:
// no "- mm away", no "Øinf", no 300-digit number, and a drawing of 100,000 layers
// does not make a message of 789 KB.
TEST(DxfImport, MessagesSayNumbersSanelyAndStayShort) {
  {  // One loose end and no other left to join it to.
    Sketch s;
    s.line(60, 0, 60, 12).line(60, 12, 0, 12).line(0, 12, 0, 5);
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F189");
    EXPECT_EQ(text, "p.dxf: the outline is open at X0.000 Y5.000: no other loose line end is left to join it to");
    Sketch t;
    t.line(60, 0, 60, 12).line(60, 12, 0, 12).line(0, 12, 0, 5);
    const auto read = importDxf(t.text(), "p.dxf");
    ASSERT_FALSE(read.diagnostics.empty());
    EXPECT_EQ(formatMessage(read.diagnostics[0], Lang::Th),
              "p.dxf: รูปร่างไม่ปิดที่ X0.000 Y5.000: ไม่มีปลายเส้นอื่นที่ยังไม่ต่อเหลืออยู่ให้ต่อเข้าด้วยกัน");
  }
  // Sizes of 250 digits, and past what a double holds once in mm (written by hand: dxflib's
  // writer overflows its buffer on such numbers).
  for (const char* k : {"e250", "e305"}) {
    std::string dxf = "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n6\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n";
    const auto line = [&](const std::string& x1, const std::string& y1, const std::string& x2, const std::string& y2) {
      dxf += "0\nLINE\n8\nPROFILE\n10\n" + x1 + "\n20\n" + y1 + "\n11\n" + x2 + "\n21\n" + y2 + "\n";
    };
    const std::string w = std::string("6") + k, h = std::string("2") + k;
    line(w, "0", w, h);
    line(w, h, "0", h);
    line("0", h, "0", "0");
    line("0", "0", w, "0");
    dxf += "0\nENDSEC\n0\nEOF\n";
    const auto [code, text] = firstProblem(dxf);
    EXPECT_EQ(code, "F192") << text;
    EXPECT_EQ(text.find("inf"), std::string::npos) << text;
    EXPECT_EQ(text.find("0000000000"), std::string::npos) << text;
    EXPECT_LT(text.size(), 200u) << text;
  }
  {  // Thai names the units in Thai.
    Sketch s(6);
    drawStepShaft(s, 60, 0);
    const auto read = importDxf(s.text(), "p.dxf");
    ASSERT_FALSE(read.diagnostics.empty());
    EXPECT_EQ(formatMessage(read.diagnostics[0], Lang::Th).find("metres"), std::string::npos);
  }
  {  // 100,000 layers, each with a line: the message lists some and says how many were left out.
    Sketch s;
    for (int i = 0; i < 100000; ++i) s.line(0, i, 1, i, "LAYER-" + std::to_string(i));
    const auto [code, text] = firstProblem(s.text());
    EXPECT_EQ(code, "F187");
    EXPECT_LT(text.size(), 2000u);
    EXPECT_NE(text.find("characters left out"), std::string::npos) << text.substr(0, 300);
  }
}

}  // namespace
}  // namespace klueng::core::design
