#pragma once
// Where a comment ends, one rule for the parser, the editor's colours and the
// tool evidence read from comments (issue 26; docs/program-file.md): '('
// opens a comment that ends where its parentheses balance ("(n = Vc*1000/(pi*D))"
// is one comment) or at the end of the line; ';' comments to the line end.
#include <cstddef>
#include <string_view>

namespace klueng::core::gcode {

// The index of the ')' that closes the comment opened by the '(' at `open`;
// npos when the comment runs to the end of the line. UTF-8 or UTF-16 alike:
// no byte of a multi-byte character is a parenthesis.
template <class CharT>
constexpr std::size_t commentClose(std::basic_string_view<CharT> line, std::size_t open) {
  int depth = 0;
  for (std::size_t j = open; j < line.size(); ++j) {
    if (line[j] == CharT('('))
      ++depth;
    else if (line[j] == CharT(')') && --depth == 0)
      return j;
  }
  return std::basic_string_view<CharT>::npos;
}

}  // namespace klueng::core::gcode
