#pragma once
// The programs of a Program (issue 9): a file may hold its main program and
// subprograms (O blocks), and subprogram files found in its folder are
// appended after it (Block::file). The index finds a program by its O number,
// a block by its N number within one program, and reads a call's P and L.
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::gcode {

struct ProgramSection {
  int number = 0;  // O number (0 = the unnumbered start of the main file)
  int first = 0;   // blocks [first, end): the O block is `first` when there is one
  int end = 0;
  int file = 0;
};

class ProgramIndex {
 public:
  explicit ProgramIndex(const Program& program);
  // The section of an O number (the first one, when a number repeats); nullptr when none.
  const ProgramSection* program(int number) const;
  // Index of the section holding block `index`.
  int sectionOf(int index) const;
  const ProgramSection& section(int i) const { return sections_[static_cast<std::size_t>(i)]; }
  std::span<const ProgramSection> sections() const { return sections_; }
  // The block with sequence number n in section `section`: the first after
  // `from` (as a control searches forward first), else the first from the
  // section's start; -1 when none.
  int findSequence(int section, int n, int from = -1) const;

 private:
  std::vector<ProgramSection> sections_;
  int blockCount_ = 0;  // (a section's blocks are found by a search: no table of 4 bytes a block)
  std::unordered_map<int, int> byNumber_;
  // Per section: (N, block index), sorted; a flat array, not a node per block
  // (issue 13: the index is built for every check of a 100,000-block program).
  std::vector<std::vector<std::pair<int, int>>> sequences_;
};

// A call's program number and repeat count (M98 P L, M97 P L, G65 P L).
// Fanuc packs the repeats into P: M98 P31000 = 3 x O1000 (profile
// packedSubprogramRepeats); L, when given, is the repeat count.
struct CallTarget {
  int number = 0;  // O number (M98, G65, G66) or N number (M97)
  int repeats = 1;
};
CallTarget callTarget(double p, std::optional<double> l, bool packedRepeats);

// The O numbers a program calls with constant P (M98, G65, G66), for loading
// subprogram files; `packedRepeats` as above.
std::vector<int> calledPrograms(const Program& program, Dialect dialect);

}  // namespace klueng::core::gcode
