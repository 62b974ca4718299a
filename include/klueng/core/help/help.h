#pragma once
// Help that teaches (issue 11): for every code of the code table a worked
// example — a whole program that shows the code at work and runs clean on a
// Ø50 x 100 bar with the shipped tools (a test runs every one) — and a search
// over the codes' names, explanations, examples and the words teachers use
// ("roughing", "กลึงปอกหยาบ"), in English and Thai.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "klueng/core/comp/segment.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::core::machine {

// The G-code of the worked example (no job header); empty when the dialect has no such code.
std::string workedExample(char letter, int number, gcode::Dialect dialect);
// Subprogram files the example calls (name, text), to put beside it in its folder.
std::vector<std::pair<std::string, std::string>> workedExampleFiles(char letter, int number, gcode::Dialect dialect);

// The moves a code's worked example makes (for a picture of them): the example
// run with the default machine; empty when the dialect has no such code.
std::vector<Segment> workedExamplePath(char letter, int number, gcode::Dialect dialect,
                                       std::vector<bool>* rapid = nullptr);

struct HelpHit {
  char letter = 'G';
  int number = 0;
  int score = 0;  // higher first: the code itself, then its name, then the rest
};
// The codes of `dialect` whose help holds every word of `query` (case does not
// matter), best first.
std::vector<HelpHit> searchHelp(std::string_view query, gcode::Dialect dialect);

}  // namespace klueng::core::machine
