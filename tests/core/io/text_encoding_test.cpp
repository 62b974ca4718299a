#include "klueng/core/io/text_encoding.h"

#include <gtest/gtest.h>

namespace klueng::core::io {
namespace {

TEST(TextEncoding, AcceptsAsciiAndThaiUtf8) {
  EXPECT_TRUE(isValidUtf8(""));
  EXPECT_TRUE(isValidUtf8("G01 X20. Z-5."));
  EXPECT_TRUE(isValidUtf8("กลึง (ปาดหน้า)"));
  EXPECT_TRUE(isValidUtf8("\xF0\x9F\x94\xA7"));  // a 4-byte emoji
}

TEST(TextEncoding, RejectsMalformedUtf8) {
  EXPECT_FALSE(isValidUtf8("\xC0\xAF"));          // overlong '/'
  EXPECT_FALSE(isValidUtf8("\xE0\x80\xAF"));      // overlong
  EXPECT_FALSE(isValidUtf8("\xED\xA0\x80"));      // UTF-16 surrogate
  EXPECT_FALSE(isValidUtf8("\xF4\x90\x80\x80"));  // above U+10FFFF
  EXPECT_FALSE(isValidUtf8("abc\xE0\xB8"));       // cut short at the end
  EXPECT_FALSE(isValidUtf8("\xA1\xC5\xD6\xA7"));  // TIS-620 bytes of "กลึง"
  EXPECT_FALSE(isValidUtf8("\x80"));
}

TEST(TextEncoding, ConvertsTis620ThaiToUtf8) {
  // "กลึง" in TIS-620: ก=A1 ล=C5 ึ=D6 ง=A7
  EXPECT_EQ(tis620ToUtf8("\xA1\xC5\xD6\xA7"), "กลึง");
  EXPECT_EQ(tis620ToUtf8("N10 \xA1"), "N10 ก");
  EXPECT_EQ(tis620ToUtf8("\xF0\xF9"), "๐๙");  // Thai digits 0 and 9
}

TEST(TextEncoding, ConvertsWindows874ExtrasAndMarksUndefinedBytes) {
  EXPECT_EQ(tis620ToUtf8("\x80"), "€");
  EXPECT_EQ(tis620ToUtf8("\x93x\x94"), "“x”");
  EXPECT_EQ(tis620ToUtf8("\x85"), "…");
  EXPECT_EQ(tis620ToUtf8("\x81"), "\xEF\xBF\xBD");  // undefined: U+FFFD
  EXPECT_EQ(tis620ToUtf8("\xDB"), "\xEF\xBF\xBD");
  EXPECT_EQ(tis620ToUtf8("\xFF"), "\xEF\xBF\xBD");
  EXPECT_EQ(tis620ToUtf8("\xA0"), "\xC2\xA0");
}

TEST(TextEncoding, CountsCodePoints) {
  EXPECT_EQ(utf8Length(""), 0);
  EXPECT_EQ(utf8Length("X20"), 3);
  EXPECT_EQ(utf8Length("กลึง"), 4);
  EXPECT_EQ(utf8Length("a\xF0\x9F\x94\xA7z"), 3);
  EXPECT_EQ(utf8Length("\xFF\xFEz"), 3);  // invalid bytes count one each
}

}  // namespace
}  // namespace klueng::core::io
