// The one display conversion of lengths (issue 28 item 4): mm kept inside,
// inches shown with a Haas control's decimals.
#include <gtest/gtest.h>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/messages.h"
#include "klueng/core/units.h"

namespace klueng::core {
namespace {

TEST(UnitFormat, MillimetresAreShownAsBefore) {
  const UnitFormat mm;
  EXPECT_EQ(mm.position(-12.5), "-12.500");
  EXPECT_EQ(mm.position(-0.0004), "0.000");  // never "-0.000"
  EXPECT_EQ(mm.size(30.0), "30");
  EXPECT_EQ(mm.size(28.16), "28.16");
  EXPECT_EQ(mm.feed(0.25, true), "0.250");
  EXPECT_EQ(mm.feed(120.0, false), "120.0");
  EXPECT_EQ(mm.withUnit(0.53, Lang::Th), "0.530 มม.");
  EXPECT_EQ(mm.feedUnit(true, Lang::En), "mm/rev");
}

TEST(UnitFormat, InchesHaveTheControlsDecimals) {
  const UnitFormat in(DisplayUnits::Inch);
  EXPECT_EQ(in.position(44.45), "1.7500");  // Ø1.75 stock
  EXPECT_EQ(in.position(-25.4), "-1.0000");
  EXPECT_EQ(in.position(-0.001), "0.0000");
  EXPECT_EQ(in.size(44.45), "1.750");  // an inch drawing's 3 decimals
  EXPECT_EQ(in.size(1.27), "0.050");
  EXPECT_EQ(in.feed(0.008 * 25.4, true), "0.0080");  // F0.008 in/rev
  EXPECT_EQ(in.feed(10.0 * 25.4, false), "10.00");   // F10. in/min
  EXPECT_DOUBLE_EQ(in.toMm(1.75), 44.45);
  EXPECT_EQ(in.withUnit(0.53, Lang::En), "0.0209 in");
  EXPECT_EQ(in.feedUnit(true, Lang::Th), "นิ้ว/รอบ");
  EXPECT_EQ(in.feedUnit(false, Lang::En), "in/min");
}

TEST(UnitFormat, AUnitArgumentReadsInTheMessagesLanguage) {
  Diagnostic d;
  d.code = codes::kPartGouge;
  d.args = {"0.0209", "-0.5000", "-0.7500", "-0.6000", "1.5000", UnitFormat(DisplayUnits::Inch).unitArg()};
  EXPECT_EQ(formatMessage(d, Lang::En)
                .rfind("Gouge 0.0209 in deep from Z-0.5000 to Z-0.7500 (deepest at Z-0.6000, Ø1.5000)", 0),
            0u)
      << formatMessage(d, Lang::En);
  EXPECT_NE(formatMessage(d, Lang::Th).find("ลึก 0.0209 นิ้ว จาก Z-0.5000"), std::string::npos)
      << formatMessage(d, Lang::Th);
  d.args.back() = UnitFormat().unitArg();
  EXPECT_NE(formatMessage(d, Lang::Th).find("ลึก 0.0209 มม. จาก"), std::string::npos);
  EXPECT_EQ(unitArgText("mm", Lang::En), nullptr);  // only the marked argument is a unit
}

}  // namespace
}  // namespace klueng::core
