// Help search (issue 11): every word of the query must be in a code's help —
// its code, names, examples, explanation or the words teachers use for it.
#include <algorithm>
#include <cctype>
#include <string>

#include "klueng/core/help/help.h"

namespace klueng::core::machine {

namespace {

// Lower-case ASCII letters; Thai and digits stay as they are.
std::string folded(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::vector<HelpHit> searchHelp(std::string_view query, gcode::Dialect dialect) {
  std::vector<std::string> terms;
  std::string term;
  for (char c : folded(query) + " ") {
    if (c == ' ' || c == '\t' || c == ',') {
      if (!term.empty()) terms.push_back(term);
      term.clear();
    } else {
      term += c;
    }
  }
  std::vector<HelpHit> hits;
  if (terms.empty()) return hits;
  // The machine's own rows, under its G-code system's numbers (G33 in system B).
  std::vector<const gcode::CodeInfo*> rows;
  for (const gcode::CodeInfo& a : gcode::codeTable()) {
    if (!a.in(dialect)) continue;
    if (const gcode::CodeInfo* own =
            gcode::findCode(a.letter, gcode::numberInSystem(a.letter, a.number, dialect), dialect);
        own && own->action == a.action)
      rows.push_back(own);
  }
  for (const gcode::CodeInfo& s : gcode::systemOnlyRows())
    if (const gcode::CodeInfo* own = gcode::findCode(s.letter, s.number, dialect); own && own->action == s.action)
      rows.push_back(own);
  for (const gcode::CodeInfo* ownRow : rows) {
    const gcode::CodeInfo& row = *ownRow;
    const std::string code = folded(gcode::codeWord(row));
    const std::string names = folded(std::string(row.nameEn) + " " + std::string(row.nameTh));
    const std::string rest =
        folded(std::string(row.exampleEn) + " " + std::string(row.exampleTh) + " " + std::string(row.says.en) + " " +
               std::string(row.says.th) + " " + std::string(row.keywords));
    int score = 0;
    bool all = true;
    for (const std::string& t : terms) {
      // "g1" finds G01 as the control reads it.
      const bool isCode =
          t == code || (t.size() >= 2 && t[0] == code[0] && t.find_first_not_of("0123456789", 1) == std::string::npos &&
                        std::stoi(t.substr(1, 6)) == row.number);
      if (isCode)
        score += 100;
      else if (names.find(t) != std::string::npos)
        score += 10;
      else if (rest.find(t) != std::string::npos)
        score += 1;
      else
        all = false;
    }
    if (all && std::none_of(hits.begin(), hits.end(),
                            [&row](const HelpHit& h) { return h.letter == row.letter && h.number == row.number; }))
      hits.push_back({row.letter, row.number, score});
  }
  std::stable_sort(hits.begin(), hits.end(), [](const HelpHit& a, const HelpHit& b) { return a.score > b.score; });
  return hits;
}

}  // namespace klueng::core::machine
