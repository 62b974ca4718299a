// ISO 286 limit deviations and ISO 2768-1 general tolerances (issue 28, item 2),
// against values printed in the standards' tables (ISO 286-2 tables 2-33).
#include <gtest/gtest.h>

#include "klueng/core/design/iso_fits.h"
#include "klueng/core/design/part_design.h"

namespace klueng::core::design {
namespace {

// Upper and lower deviation in µm, as the tables print them.
void expectFit(const char* fit, double size, int upper, int lower) {
  const auto t = isoFit(fit, size);
  ASSERT_TRUE(t) << fit << " Ø" << size;
  EXPECT_EQ(std::lround(t->upper * 1000.0), upper) << fit << " Ø" << size;
  EXPECT_EQ(std::lround(t->lower * 1000.0), lower) << fit << " Ø" << size;
  EXPECT_EQ(t->text, fit);
}

TEST(IsoFits, ShaftsFromTheTables) {
  expectFit("h7", 25, 0, -21);
  expectFit("g6", 20, -7, -20);
  expectFit("h6", 3, 0, -6);      // "up to and including 3"
  expectFit("h6", 3.001, 0, -8);  // the next range
  expectFit("f7", 50, -25, -50);
  expectFit("e8", 100, -72, -126);
  expectFit("d9", 12, -50, -93);
  expectFit("c11", 45, -130, -290);  // c splits at 40
  expectFit("k6", 40, 18, 2);
  expectFit("k9", 40, 62, 0);  // k outside grades 4-7: ei = 0
  expectFit("m6", 25, 21, 8);
  expectFit("n6", 60, 39, 20);
  expectFit("p6", 100, 59, 37);
  expectFit("r6", 70, 62, 43);  // r splits at 65
  expectFit("s6", 90, 93, 71);
  expectFit("s7", 450, 295, 232);
  expectFit("js6", 40, 8, -8);
  expectFit("h11", 500, 0, -400);
}

TEST(IsoFits, HolesFromTheTables) {
  expectFit("H7", 40, 25, 0);
  expectFit("H8", 25, 33, 0);
  expectFit("G7", 18, 24, 6);
  expectFit("F8", 30, 53, 20);
  expectFit("K7", 40, 7, -18);  // ES = -ei + Δ
  expectFit("K8", 40, 12, -27);
  expectFit("M7", 40, 0, -25);
  expectFit("M6", 25, -4, -17);
  expectFit("N7", 40, -8, -33);
  expectFit("N9", 40, 0, -62);  // N above IT8: ES = 0
  expectFit("N9", 2, -4, -29);  // up to 3 mm: ES = -4
  expectFit("P7", 40, -17, -42);
  expectFit("P9", 40, -26, -88);  // P above IT7: no Δ
  expectFit("S7", 100, -58, -93);
}

TEST(IsoFits, JsIsHalfTheGradeExactly) {
  const auto t = isoFit("JS7", 40);
  ASSERT_TRUE(t);
  EXPECT_DOUBLE_EQ(t->upper, 0.0125);
  EXPECT_DOUBLE_EQ(t->lower, -0.0125);
}

TEST(IsoFits, WhatTheTablesDoNotHoldIsRefused) {
  for (const char* bad : {"h0", "h19", "Js7", "x7", "j6", "h", "7", "h7a", "a11", "K2"})
    EXPECT_FALSE(isoFit(bad, 25)) << bad;
  EXPECT_FALSE(isoFit("h7", 0.0));
  EXPECT_FALSE(isoFit("h7", 500.5));
}

TEST(IsoFits, GeneralTolerancesOfIso2768) {
  EXPECT_DOUBLE_EQ(generalTolerance("m", 25)->upper, 0.2);
  EXPECT_DOUBLE_EQ(generalTolerance("m", 30.5)->lower, -0.3);
  EXPECT_DOUBLE_EQ(generalTolerance("f", 6)->upper, 0.05);
  EXPECT_DOUBLE_EQ(generalTolerance("c", 150)->upper, 1.2);
  EXPECT_EQ(generalTolerance("m", 25)->text, "ISO 2768-m");
  EXPECT_FALSE(generalTolerance("v", 2));  // no class v tolerance up to 3 mm
  EXPECT_FALSE(generalTolerance("x", 25));
}

TEST(PartTolerances, ReadFromJsonAndWrittenBack) {
  const std::string json = R"({
    "stock": { "diameter": 50, "length": 100 },
    "general_tolerance": "m",
    "outside": [
      { "cylinder": 30, "length": 20, "chamfer": 3, "tolerance": "h7", "length_tolerance": 0.1, "roughness": 1.6 },
      { "cylinder": 40, "length": 20, "tolerance": [0.02, -0.01], "length_tolerance": [0, -0.2] },
      { "cylinder": 46, "length": 20, "tolerance": 0.05 }
    ],
    "inside": [ { "bore": 20, "length": 10, "tolerance": "H7" } ]
  })";
  const auto part = readPartDesign(json, "t.json");
  ASSERT_TRUE(part.ok()) << (part.diagnostics.empty() ? "" : formatMessage(part.diagnostics[0], Lang::En));
  const PartDesign& p = *part.value;
  EXPECT_EQ(p.outside[0].tolerance.text, "h7");
  EXPECT_DOUBLE_EQ(p.outside[0].tolerance.lower, -0.021);
  EXPECT_EQ(p.outside[0].lengthTolerance.text, "±0.1");
  EXPECT_EQ(p.outside[1].tolerance.text, "+0.02/-0.01");
  EXPECT_EQ(p.outside[1].lengthTolerance.text, "0/-0.2");
  EXPECT_EQ(p.inside[0].tolerance.text, "H7");
  EXPECT_DOUBLE_EQ(p.inside[0].tolerance.upper, 0.021);
  const auto again = readPartDesign(writePartDesign(p), "again.json");
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(writePartDesign(*again.value), writePartDesign(p));
  EXPECT_EQ(again.value->outside[1].tolerance, p.outside[1].tolerance);
  EXPECT_DOUBLE_EQ(p.outside[0].roughness, 1.6);  // the finish mark's Ra, kept on the way back
  EXPECT_DOUBLE_EQ(again.value->outside[0].roughness, 1.6);
  EXPECT_DOUBLE_EQ(again.value->outside[1].roughness, 0.0);

  // Every Ø and length, the untoleranced ones (Ø46's length, the bore's) by ISO 2768-m.
  const auto dims = drawnDimensions(p);
  ASSERT_EQ(dims.size(), 8u);
  EXPECT_EQ(dims[0].kind, cut::DimensionKind::Diameter);
  EXPECT_DOUBLE_EQ(dims[0].zRight, -3.0);  // clear of the C3
  EXPECT_DOUBLE_EQ(dims[0].zLeft, -20.0);
  EXPECT_EQ(dims[5].kind, cut::DimensionKind::Length);
  EXPECT_EQ(dims[5].tolerance.text, "ISO 2768-m");
  EXPECT_DOUBLE_EQ(dims[5].tolerance.upper, 0.2);
  EXPECT_EQ(dims[6].side, cut::FeatureSide::Inside);
  // Without the general tolerance only the toleranced ones.
  PartDesign own = p;
  own.generalTolerance.clear();
  EXPECT_EQ(drawnDimensions(own).size(), 6u);
}

TEST(PartTolerances, BadTolerancesNameTheirField) {
  const auto bad = [](const std::string& step, const std::string& field) {
    const auto part =
        readPartDesign(R"({ "stock": { "diameter": 50, "length": 100 }, "outside": [ )" + step + " ] }", "b.json");
    ASSERT_FALSE(part.ok()) << step;
    ASSERT_FALSE(part.diagnostics.empty());
    EXPECT_EQ(part.diagnostics[0].code, "F182");
    EXPECT_EQ(part.diagnostics[0].args[1], field) << step;
  };
  bad(R"({ "cylinder": 30, "length": 20, "tolerance": "x9" })", "outside[0].tolerance");
  bad(R"({ "cylinder": 30, "length": 20, "tolerance": [-0.1, 0.1] })", "outside[0].tolerance");
  bad(R"({ "cylinder": 30, "length": 20, "tolerance": -0.1 })", "outside[0].tolerance");
  bad(R"({ "cylinder": 30, "length": 20, "length_tolerance": "h7" })", "outside[0].length_tolerance");
  bad(R"({ "taper": 30, "length": 20, "tolerance": "h7" })", "outside[0].tolerance");
}

}  // namespace
}  // namespace klueng::core::design
