// Programs, sequence numbers and call targets of a Program (program_index.h).
#include "klueng/core/gcode/program_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode {

namespace {

bool startsProgram(const Block& b) {
  return !b.words.empty() && b.words.front().letter == 'O' && b.words.front().expr < 0 &&
         !b.words.front().hasDecimalPoint;
}

int wholeOr(double v, int fallback) {
  if (!(std::abs(v) < 1e9)) return fallback;
  return static_cast<int>(std::lround(v));
}

// Sequence numbers come in ascending runs (N1 .. N9999, then N1 again): merging
// the runs costs n log(runs), a fraction of a full sort.
void sortRuns(std::vector<std::pair<int, int>>& v) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i] < v[i - 1]) starts.push_back(i);
  while (starts.size() > 1) {
    std::vector<std::size_t> merged;
    for (std::size_t r = 0; r < starts.size(); r += 2) {
      merged.push_back(starts[r]);
      if (r + 1 == starts.size()) break;
      const std::size_t end = r + 2 < starts.size() ? starts[r + 2] : v.size();
      std::inplace_merge(v.begin() + static_cast<std::ptrdiff_t>(starts[r]),
                         v.begin() + static_cast<std::ptrdiff_t>(starts[r + 1]),
                         v.begin() + static_cast<std::ptrdiff_t>(end));
    }
    starts = std::move(merged);
  }
}

}  // namespace

ProgramIndex::ProgramIndex(const Program& program) {
  const int n = static_cast<int>(program.blocks.size());
  blockCount_ = n;
  for (int i = 0; i < n; ++i) {
    const Block& b = program.blocks[static_cast<std::size_t>(i)];
    // Each block's words are an allocation of their own, and this loop reads
    // only the first of a block with an O or N word (most CAM blocks have
    // neither): ask for those of a few blocks ahead (it waits on memory).
    const auto readsWords = [](const Block& x) { return x.mayHave('O') || x.mayHave('N'); };
    if (i + 8 < n && readsWords(program.blocks[static_cast<std::size_t>(i + 8)]))
      __builtin_prefetch(program.blocks[static_cast<std::size_t>(i + 8)].words.data());
    const bool newFile = i == 0 || program.blocks[static_cast<std::size_t>(i - 1)].file != b.file;
    // A program starts at its O block, at the start of each file, and the
    // main file's first section may have no O number.
    const bool opens = b.mayHave('O') && startsProgram(b);
    if (newFile || opens) {
      if (!sections_.empty()) sections_.back().end = i;
      ProgramSection s;
      s.first = i;
      s.file = b.file;
      s.number = opens ? b.words.front().code() : 0;
      // A subprogram file without an O block is named by its file (set by the loader as its first O).
      sections_.push_back(s);
      sequences_.emplace_back();
    }
    if (b.mayHave('N') && !b.words.empty() && b.words.front().letter == 'N' && b.words.front().expr < 0)
      sequences_.back().emplace_back(b.words.front().code(), i);
  }
  if (!sections_.empty()) sections_.back().end = n;
  for (auto& numbers : sequences_) sortRuns(numbers);
  for (std::size_t s = 0; s < sections_.size(); ++s)
    if (sections_[s].number > 0) byNumber_.emplace(sections_[s].number, static_cast<int>(s));  // first one wins
}

const ProgramSection* ProgramIndex::program(int number) const {
  const auto it = byNumber_.find(number);
  return it == byNumber_.end() ? nullptr : &sections_[static_cast<std::size_t>(it->second)];
}

int ProgramIndex::sectionOf(int index) const {
  if (index < 0 || index >= blockCount_) return -1;
  // The sections follow each other and cover every block: the last one starting at or before it.
  const auto after = std::upper_bound(sections_.begin(), sections_.end(), index,
                                      [](int i, const ProgramSection& s) { return i < s.first; });
  return static_cast<int>(after - sections_.begin()) - 1;
}

int ProgramIndex::findSequence(int section, int n, int from) const {
  if (section < 0 || section >= static_cast<int>(sections_.size())) return -1;
  // Blocks numbered n, in program order: the first after `from`, else the first.
  const auto& numbers = sequences_[static_cast<std::size_t>(section)];
  const auto begin = std::lower_bound(numbers.begin(), numbers.end(), std::pair{n, std::numeric_limits<int>::min()});
  const auto end = std::upper_bound(begin, numbers.end(), std::pair{n, std::numeric_limits<int>::max()});
  if (begin == end) return -1;
  const auto after = std::upper_bound(begin, end, std::pair{n, from});
  return after != end ? after->second : begin->second;
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
      const CodeAction a = actionOf(w, dialect);
      if (a == CodeAction::SubprogramCall) m98 = true;
      if (a == CodeAction::MacroCall || a == CodeAction::MacroModalCall) macro = true;
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
