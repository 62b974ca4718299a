// Display tokens of a program line (display_tokens.h).
#include "klueng/core/gcode/display_tokens.h"

#include <string>

#include "klueng/core/gcode/comment.h"

namespace klueng::core::gcode {

namespace {

bool isAsciiLetter(char16_t c) { return (c >= u'A' && c <= u'Z') || (c >= u'a' && c <= u'z'); }
bool isAsciiDigit(char16_t c) { return c >= u'0' && c <= u'9'; }
char upper(char16_t c) { return static_cast<char>(c >= u'a' && c <= u'z' ? c - u'a' + u'A' : c); }

}  // namespace

std::vector<DisplayToken> displayTokens(std::u16string_view line) {
  std::vector<DisplayToken> out;
  const int n = static_cast<int>(line.size());
  const auto add = [&](int start, int end, DisplayTokenKind kind, char letter = 0) {
    out.push_back({start, end - start, kind, letter});
  };
  int i = 0;
  while (i < n) {
    const char16_t c = line[static_cast<std::size_t>(i)];
    if (c == u'(') {
      const std::size_t close = commentClose(line, static_cast<std::size_t>(i));
      const int end = close == std::u16string_view::npos ? n : static_cast<int>(close) + 1;
      add(i, end, DisplayTokenKind::Comment);
      i = end;
    } else if (c == u';') {
      add(i, n, DisplayTokenKind::Comment);
      break;
    } else if (c == u'/' || c == u'%') {
      add(i, i + 1, DisplayTokenKind::Skip);
      ++i;
    } else if (c == u'#') {
      int end = i + 1;
      while (end < n && isAsciiDigit(line[static_cast<std::size_t>(end)])) ++end;
      add(i, end, DisplayTokenKind::Variable);
      i = end;
    } else if (isAsciiLetter(c) && i + 1 < n && isAsciiLetter(line[static_cast<std::size_t>(i + 1)])) {
      // Two letters in a row: a macro word, or letters that are no word at all.
      int end = i + 1;
      while (end < n && isAsciiLetter(line[static_cast<std::size_t>(end)])) ++end;
      std::string word;
      for (int k = i; k < end; ++k) word += upper(line[static_cast<std::size_t>(k)]);
      if (isMacroKeyword(word)) {
        add(i, end, DisplayTokenKind::MacroWord);
        i = end;
      } else {
        ++i;
      }
    } else if (isAsciiLetter(c)) {
      int end = i + 1;
      while (end < n) {
        const char16_t d = line[static_cast<std::size_t>(end)];
        if (!isAsciiDigit(d) && d != u'.' && d != u'-' && d != u'+') break;
        ++end;
      }
      add(i, end, DisplayTokenKind::Address, upper(c));
      i = end;
    } else {
      ++i;
    }
  }
  return out;
}

}  // namespace klueng::core::gcode
