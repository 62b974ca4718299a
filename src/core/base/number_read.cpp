#include "klueng/core/number_read.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

namespace klueng::core {

namespace {

bool isDigitChar(char c) { return c >= '0' && c <= '9'; }
char lowerAscii(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// True when [p, last) starts with `word` (lower case), letters in either case.
bool startsWithWord(const char* p, const char* last, const char* word) {
  for (; *word; ++p, ++word)
    if (p == last || lowerAscii(*p) != *word) return false;
  return true;
}

}  // namespace

namespace detail {

std::from_chars_result readDoubleByStrtod(const char* first, const char* last, double& value) {
  const char* p = first;
  const bool negative = p != last && *p == '-';
  if (negative) ++p;
  if (p != last && (lowerAscii(*p) == 'i' || lowerAscii(*p) == 'n')) {
    if (startsWithWord(p, last, "infinity") || startsWithWord(p, last, "inf")) {
      p += startsWithWord(p, last, "infinity") ? 8 : 3;
      value = negative ? -HUGE_VAL : HUGE_VAL;
      return {p, std::errc{}};
    }
    if (startsWithWord(p, last, "nan")) {
      p += 3;
      // nan(n-char-sequence): taken only when the bracket closes.
      if (p != last && *p == '(') {
        const char* q = p + 1;
        while (q != last && (isDigitChar(*q) || (lowerAscii(*q) >= 'a' && lowerAscii(*q) <= 'z') || *q == '_')) ++q;
        if (q != last && *q == ')') p = q + 1;
      }
      value = negative ? -NAN : NAN;
      return {p, std::errc{}};
    }
    return {first, std::errc::invalid_argument};
  }
  std::size_t mantissaDigits = 0;
  while (p != last && isDigitChar(*p)) ++p, ++mantissaDigits;
  if (p != last && *p == '.') {
    ++p;
    while (p != last && isDigitChar(*p)) ++p, ++mantissaDigits;
  }
  if (mantissaDigits == 0) return {first, std::errc::invalid_argument};
  if (p != last && lowerAscii(*p) == 'e') {
    const char* q = p + 1;
    if (q != last && (*q == '+' || *q == '-')) ++q;
    if (q != last && isDigitChar(*q)) {
      while (q != last && isDigitChar(*q)) ++q;
      p = q;
    }
  }
  // strtod reads the very span the grammar took (its own end is where the span ends); the
  // WebAssembly build's locale is "C", so the point is '.'.
  const std::string span(first, p);
  errno = 0;
  const double v = std::strtod(span.c_str(), nullptr);
  // As from_chars: a number past the largest double or one that reads as 0 is out of range (a
  // subnormal is read).
  if (errno == ERANGE && (std::isinf(v) || v == 0.0)) return {p, std::errc::result_out_of_range};
  value = v;
  return {p, std::errc{}};
}

}  // namespace detail

std::from_chars_result readDouble(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars)
  return std::from_chars(first, last, value);
#else
  return detail::readDoubleByStrtod(first, last, value);
#endif
}

}  // namespace klueng::core
