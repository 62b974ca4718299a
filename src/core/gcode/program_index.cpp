// Programs, sequence numbers and call targets of a Program (program_index.h).
#include "klueng/core/gcode/program_index.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode {

namespace {

bool startsProgram(const Block& b) {
  return !b.words.empty() && b.words.front().letter == 'O' && b.words.front().expr < 0 && !b.words.front().hasDecimalPoint;
}

int wholeOr(double v, int fallback) {
  if (!(std::abs(v) < 1e9)) return fallback;
  return static_cast<int>(std::lround(v));
}

}  // namespace

ProgramIndex::ProgramIndex(const Program& program) {
  const int n = static_cast<int>(program.blocks.size());
  sectionOfBlock_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const Block& b = program.blocks[static_cast<std::size_t>(i)];
    const bool newFile = i == 0 || program.blocks[static_cast<std::size_t>(i - 1)].file != b.file;
    // A program starts at its O block, at the start of each file, and the
    // main file's first section may have no O number.
    if (newFile || startsProgram(b)) {
      if (!sections_.empty()) sections_.back().end = i;
      ProgramSection s;
      s.first = i;
      s.file = b.file;
      s.number = startsProgram(b) ? b.words.front().code() : 0;
      // A subprogram file without an O block is named by its file (set by the loader as its first O).
      sections_.push_back(s);
      sequences_.emplace_back();
    }
    sectionOfBlock_[static_cast<std::size_t>(i)] = static_cast<int>(sections_.size()) - 1;
    if (!b.words.empty() && b.words.front().letter == 'N' && b.words.front().expr < 0)
      sequences_.back().emplace(b.words.front().code(), i);
  }
  if (!sections_.empty()) sections_.back().end = n;
  for (std::size_t s = 0; s < sections_.size(); ++s)
    if (sections_[s].number > 0) byNumber_.emplace(sections_[s].number, static_cast<int>(s));  // first one wins
}

const ProgramSection* ProgramIndex::program(int number) const {
  const auto it = byNumber_.find(number);
  return it == byNumber_.end() ? nullptr : &sections_[static_cast<std::size_t>(it->second)];
}

int ProgramIndex::sectionOf(int index) const {
  if (index < 0 || index >= static_cast<int>(sectionOfBlock_.size())) return -1;
  return sectionOfBlock_[static_cast<std::size_t>(index)];
}

int ProgramIndex::findSequence(int section, int n, int from) const {
  if (section < 0 || section >= static_cast<int>(sections_.size())) return -1;
  const auto range = sequences_[static_cast<std::size_t>(section)].equal_range(n);
  int after = -1, first = -1;
  for (auto it = range.first; it != range.second; ++it) {
    const int b = it->second;
    if (first < 0 || b < first) first = b;
    if (b > from && (after < 0 || b < after)) after = b;
  }
  return after >= 0 ? after : first;
}

CallTarget callTarget(double p, std::optional<double> l, bool packedRepeats) {
  CallTarget t;
  const int value = wholeOr(p, 0);
  t.number = value;
  if (packedRepeats && !l && value > 9999) {
    t.repeats = value / 10000;
    t.number = value % 10000;
  }
  if (l) t.repeats = std::max(0, wholeOr(*l, 1));
  return t;
}

std::vector<int> calledPrograms(const Program& program, Dialect dialect) {
  const bool packed = machineProfile(dialect).flow.packedRepeats;
  std::set<int> numbers;
  for (const Block& b : program.blocks) {
    const Word* p = b.find('P');
    if (!p || p->expr >= 0) continue;
    bool m98 = false, macro = false;
    for (const Word& w : b.words) {
      if (w.letter == 'M' && w.expr < 0 && w.code() == 98) m98 = true;
      if (w.letter == 'G' && w.expr < 0 && (w.code() == 65 || w.code() == 66) && !w.hasDecimalPoint) macro = true;
    }
    if (!m98 && !macro) continue;
    const Word* l = b.find('L');
    const CallTarget t = callTarget(p->value, l && l->expr < 0 ? std::optional<double>(l->value) : std::nullopt,
                                    packed && m98 && !macro);
    if (t.number > 0) numbers.insert(t.number);
  }
  return {numbers.begin(), numbers.end()};
}

}  // namespace klueng::core::gcode
