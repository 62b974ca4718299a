// Grading against the teacher's drawing (issue 28, item 2): sample 01's part
// with tolerances on its diameters and lengths, and students' programs that cut
// it within them, beyond them, exactly at a limit and a micron past it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "design_test_util.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/io/tool_library.h"

namespace klueng::core::design {
namespace {

namespace fs = std::filesystem;

// Sample 01's drawing: Ø30 h7 (0/-0.021) × 20 ±0.1, Ø40 js6 (±0.008), Ø46 [0, -0.05] × 20 ±0.1.
const char* kDrawing = R"({
  "stock": { "diameter": 50, "length": 100 },
  "outside": [
    { "cylinder": 30, "length": 20, "chamfer": 3, "tolerance": "h7", "length_tolerance": 0.1 },
    { "cylinder": 40, "length": 20, "round": 2, "tolerance": "js6" },
    { "cylinder": 46, "length": 20, "chamfer": 1, "tolerance": [0, -0.05], "length_tolerance": 0.1 }
  ]
})";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

class DrawingGrading : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("klueng-drawing-grading-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    sample_ = slurp(KLUENG_SAMPLES_DIR "/01-step-shaft.txt");
    ASSERT_FALSE(sample_.empty());
    const auto part = readPartDesign(kDrawing, "drawing.json");
    ASSERT_TRUE(part.ok());
    against_.hasDrawing = true;
    against_.drawing = drawnDimensions(*part.value);
    ASSERT_EQ(against_.drawing.size(), 5u);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void student(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  std::map<std::string, job::ClassRow> grade() {
    const machine::MachineSetup setup = machine::loadMachineSetup(KLUENG_SOURCE_DIR).setup;
    job::JobInput request;
    request.setup = setup;
    request.stations = setup.tools.stations;
    std::map<std::string, job::ClassRow> rows;
    for (job::ClassRow& r : job::gradeClass(dir_.string(), against_, request)) rows[r.file] = std::move(r);
    return rows;
  }
  fs::path dir_;
  std::string sample_;
  job::GradeAgainst against_;
};

// measured value and verdict of dimension k
void expectMeasured(const job::ClassRow& r, std::size_t k, double mm, cut::Verdict v) {
  ASSERT_LT(k, r.inspection.size()) << r.file;
  const cut::InspectedDimension& d = r.inspection[k];
  ASSERT_TRUE(d.measured) << r.file << " " << cut::dimensionLabel(d.drawn, Lang::En);
  EXPECT_DOUBLE_EQ(*d.measured, mm) << r.file << " " << cut::dimensionLabel(d.drawn, Lang::En);
  EXPECT_EQ(d.verdict, v) << r.file << " " << cut::dimensionLabel(d.drawn, Lang::En) << " " << *d.measured;
}

TEST_F(DrawingGrading, OneInOneOutOneAtTheLimit) {
  student("in.nc", sample_);
  // Ø40 cut 0.02 small (js6 allows 0.008), the first shoulder 0.3 deep (20.3 against 20 ±0.1).
  student("out.nc",
          replaced(replaced(sample_, "N380 G03 X40. Z-22.", "N380 G03 X39.98 Z-22."), "N360 Z-20.", "N360 Z-20.3"));
  // Ø46 exactly at its lower limit 45.95, Ø40 at js6's lower limit 39.992: in.
  student("limit.nc", replaced(replaced(sample_, "N410 X46. Z-41.\nN420 Z-60.", "N410 X45.95 Z-41.\nN420 Z-60."),
                               "N380 G03 X40. Z-22.", "N380 G03 X39.992 Z-22."));
  // A taper where the Ø40 cylinder should be: no Ø40 on the part, out.
  student("taper.nc", replaced(sample_, "N390 G01 Z-40.", "N390 G01 X39.98 Z-40."));
  // A micron under it: out.
  student("micron.nc", replaced(sample_, "N410 X46. Z-41.\nN420 Z-60.", "N410 X45.949 Z-41.\nN420 Z-60."));
  student("typo.nc", replaced(sample_, "N100 G01 Z-59.8", "N100 G01 Y-59.8"));
  const auto rows = grade();
  ASSERT_EQ(rows.size(), 6u);

  const job::ClassRow& in = rows.at("in.nc");
  EXPECT_TRUE(in.pass);
  expectMeasured(in, 0, 30.0, cut::Verdict::In);  // h7's upper limit is the nominal: in
  expectMeasured(in, 1, 20.0, cut::Verdict::In);
  expectMeasured(in, 2, 40.0, cut::Verdict::In);
  expectMeasured(in, 3, 46.0, cut::Verdict::In);
  expectMeasured(in, 4, 20.0, cut::Verdict::In);
  EXPECT_DOUBLE_EQ(in.inspection[0].lowerLimit(), 29.979);
  EXPECT_DOUBLE_EQ(in.inspection[0].upperLimit(), 30.0);

  const job::ClassRow& out = rows.at("out.nc");
  EXPECT_FALSE(out.pass);
  expectMeasured(out, 0, 30.0, cut::Verdict::In);
  expectMeasured(out, 1, 20.3, cut::Verdict::Out);
  expectMeasured(out, 2, 39.98, cut::Verdict::Out);
  expectMeasured(out, 3, 46.0, cut::Verdict::In);

  const job::ClassRow& limit = rows.at("limit.nc");
  EXPECT_TRUE(limit.pass);
  expectMeasured(limit, 2, 39.992, cut::Verdict::In);
  expectMeasured(limit, 3, 45.95, cut::Verdict::In);
  EXPECT_DOUBLE_EQ(limit.inspection[3].lowerLimit(), 45.95);

  const job::ClassRow& micron = rows.at("micron.nc");
  EXPECT_FALSE(micron.pass);
  expectMeasured(micron, 3, 45.949, cut::Verdict::Out);

  const job::ClassRow& taper = rows.at("taper.nc");
  EXPECT_FALSE(taper.pass);
  EXPECT_EQ(taper.inspection[2].verdict, cut::Verdict::Missing);
  EXPECT_EQ(taper.inspection[3].verdict, cut::Verdict::In);

  // A program that does not run has none of the drawing's dimensions.
  const job::ClassRow& typo = rows.at("typo.nc");
  EXPECT_FALSE(typo.pass);
  ASSERT_EQ(typo.inspection.size(), 5u);
  for (const auto& d : typo.inspection) EXPECT_EQ(d.verdict, cut::Verdict::Missing);

  std::vector<job::ClassRow> list;
  for (const auto& [name, row] : rows) list.push_back(row);
  const std::string csv = job::classCsv(list, true);
  EXPECT_NE(csv.find("feature,nominal_mm,tolerance,lower_mm,upper_mm,measured_mm,verdict\n"), std::string::npos);
  EXPECT_NE(csv.find("\nlimit.nc,pass,0,,,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",Ø46,46.000,0/-0.05,45.950,46.000,45.950,in\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",Ø40,40.000,js6 (±0.008),39.992,40.008,39.980,out\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",L20 (Z0/Z-20),20.000,±0.1,19.900,20.100,20.300,out\n"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\ntypo.nc,fail,1,E"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",Ø30,30.000,h7 (0/-0.021),29.979,30.000,,missing\n"), std::string::npos) << csv;
}

TEST_F(DrawingGrading, AMissingFeatureIsOut) {
  // The drawing has a bore the students' solid shaft does not.
  against_.drawing.push_back(
      {cut::DimensionKind::Diameter, cut::FeatureSide::Inside, 20.0, {0.021, 0.0, "H7"}, 0.0, -10.0});
  student("in.nc", sample_);
  const auto rows = grade();
  const job::ClassRow& r = rows.at("in.nc");
  EXPECT_FALSE(r.pass);
  ASSERT_EQ(r.inspection.size(), 6u);
  EXPECT_EQ(r.inspection[5].verdict, cut::Verdict::Missing);
  EXPECT_FALSE(r.inspection[5].measured);
  EXPECT_EQ(cut::dimensionLabel(r.inspection[5].drawn, Lang::En), "Ø20 bore");
  EXPECT_EQ(cut::verdictName(r.inspection[5].verdict, Lang::Th), "ไม่มีบนชิ้นงาน");
}

}  // namespace
}  // namespace klueng::core::design
