#pragma once
// The pieces of one program line an editor colours (issue 12: the GUI never
// lexes G-code itself): comments, block skip and tape marks, #variables,
// macro B keywords and address words. Positions are UTF-16 code units, as in
// the editor's text; everything that is not a token stays uncoloured.
#include <string_view>
#include <vector>

namespace klueng::core::gcode {

enum class DisplayTokenKind { Comment, Skip, Variable, MacroWord, Address };

struct DisplayToken {
  int start = 0;
  int length = 0;
  DisplayTokenKind kind = DisplayTokenKind::Address;
  char letter = 0;  // Address: the upper-case address letter (its kind: address_table.h)
};

std::vector<DisplayToken> displayTokens(std::u16string_view line);

// A custom macro B word: statement (IF, WHILE, GOTO, DO, END, THEN, POPEN ...),
// word operator (EQ ... MOD) or function (SIN ... BCD). Upper-case ASCII.
bool isMacroKeyword(std::string_view upperWord);

}  // namespace klueng::core::gcode
