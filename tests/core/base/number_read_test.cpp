// The core's one number reader (issue 41): the strtod reading the WebAssembly build uses reads
// every text as std::from_chars does on the desktop, value, end and error alike.
#include "klueng/core/number_read.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace klueng::core {
namespace {

struct Read {
  double value = -7.0;  // untouched unless read
  long used = 0;
  std::errc ec{};
};

Read byStrtod(const std::string& text) {
  Read r;
  const auto res = detail::readDoubleByStrtod(text.data(), text.data() + text.size(), r.value);
  r.used = res.ptr - text.data();
  r.ec = res.ec;
  return r;
}

#if defined(__cpp_lib_to_chars)
Read byFromChars(const std::string& text) {
  Read r;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), r.value);
  r.used = res.ptr - text.data();
  r.ec = res.ec;
  return r;
}

void expectSame(const std::string& text) {
  const Read a = byStrtod(text);
  const Read b = byFromChars(text);
  EXPECT_EQ(a.used, b.used) << text;
  EXPECT_EQ(a.ec, b.ec) << text;
  if (std::isnan(b.value))
    EXPECT_TRUE(std::isnan(a.value)) << text;
  else
    EXPECT_EQ(a.value, b.value) << text;  // bit-exact: the same correctly rounded double
}

TEST(NumberRead, StrtodReadingIsFromChars) {
  for (const char* text : {"0",
                           "12.5",
                           "-12.5",
                           ".5",
                           "5.",
                           "-.5",
                           "12.5E-1X",
                           "1e",
                           "1e+",
                           "1e-x",
                           "+1",
                           " 1",
                           "-",
                           ".",
                           "",
                           "x",
                           "0x10",
                           "1e-400",
                           "4e-320",
                           "1e400",
                           "-1e400",
                           "1e-310",
                           "0e-999",
                           "inf",
                           "-INF",
                           "infinity",
                           "Infinit",
                           "nan",
                           "NaN(abc)",
                           "nan(",
                           "nan(a-b)",
                           "1.7976931348623157e308",
                           "2.2250738585072014e-308",
                           "0.1000000000000000055511151231257827",
                           "123456789012345678901234567890",
                           "00012.50000",
                           "1,5",
                           "3.14.15"})
    expectSame(text);
}

TEST(NumberRead, StrtodReadingIsFromCharsOnRandomNumbers) {
  std::mt19937_64 random(41);
  std::uniform_int_distribution<int> digit(0, 9), length(1, 20), exponent(-330, 330);
  for (int i = 0; i < 20000; ++i) {
    std::string text = random() % 2 ? "-" : "";
    const int whole = length(random), fraction = length(random) - 1;
    for (int k = 0; k < whole; ++k) text += static_cast<char>('0' + digit(random));
    if (fraction > 0) text += '.';
    for (int k = 0; k < fraction; ++k) text += static_cast<char>('0' + digit(random));
    if (random() % 3 == 0) text += "e" + std::to_string(exponent(random));
    expectSame(text);
  }
}
#endif

TEST(NumberRead, ReadsTheNumberAndStopsAfterIt) {
  const std::string text = "-0.25X1";
  double v = 0.0;
  const auto r = readDouble(text.data(), text.data() + text.size(), v);
  EXPECT_EQ(r.ec, std::errc{});
  EXPECT_EQ(r.ptr, text.data() + 5);
  EXPECT_EQ(v, -0.25);
  const Read refused = byStrtod("+1");
  EXPECT_EQ(refused.ec, std::errc::invalid_argument);
  EXPECT_EQ(refused.used, 0);
  EXPECT_EQ(refused.value, -7.0);
  const Read huge = byStrtod("1e400");
  EXPECT_EQ(huge.ec, std::errc::result_out_of_range);
  EXPECT_EQ(huge.used, 5);
  EXPECT_EQ(huge.value, -7.0);
}

}  // namespace
}  // namespace klueng::core
