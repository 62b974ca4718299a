#include "klueng/core/messages.h"

#include <gtest/gtest.h>

#include <set>

#include "klueng/core/geometry.h"

namespace klueng::core {
namespace {

TEST(Messages, EveryCodeIsUniqueAndHasBothLanguages) {
  std::set<std::string_view> seen;
  for (const auto& m : allMessages()) {
    EXPECT_TRUE(seen.insert(m.code).second) << "duplicate code " << m.code;
    EXPECT_FALSE(m.en.empty()) << m.code;
    EXPECT_FALSE(m.th.empty()) << m.code;
    EXPECT_NE(m.en, m.th) << m.code << " has no real Thai text";
  }
}

TEST(Messages, UnknownCodeFallsBackToCodeAndArgs) {
  Diagnostic d{Severity::Error, "Z999", {3, 4, 1}, {"X", "5"}};
  EXPECT_EQ(formatMessage(d, Lang::En), "Z999 X 5");
}

TEST(Geometry, TipVectorsFollowTheSpecGrid) {
  EXPECT_EQ(tipVector(3), Vec2(-1, -1));  // outside turning tool
  EXPECT_EQ(tipVector(2), Vec2(-1, 1));   // boring bar
  EXPECT_EQ(tipVector(8), Vec2(0, -1));
  EXPECT_EQ(tipVector(0), Vec2(0, 0));
  EXPECT_EQ(tipVector(9), Vec2(0, 0));
  EXPECT_EQ(tipVector(5), Vec2(1, 0));
}

}  // namespace
}  // namespace klueng::core
