#pragma once
// What a debugger shows of program flow at one step (issue 9): the macro
// variables as they are after a snapshot, with those the last step changed,
// and the value an expression word had the last time its line ran. Pure
// queries over Timeline::flow, for the GUI's variable watch and tooltips.
#include <optional>
#include <vector>

#include "klueng/core/machine/timeline.h"

namespace klueng::core::machine {

struct WatchedVariable {
  int number = 0;
  double value = 0.0;
  bool vacant = false;
  bool changed = false;  // written after `since` (by the step just taken)
};

// The variables set at `snapshot` (locals of the running macro level, then
// common and system variables written so far), sorted by number; `changed`
// marks writes by snapshots after `since` (-1: none marked).
std::vector<WatchedVariable> variablesAt(const Timeline& timeline, int snapshot, int since = -1);

// The value the expression word at (file, line, column) had the last time it
// ran at or before `snapshot`; nullopt when it has not run.
std::optional<WordValue> wordValueAt(const Timeline& timeline, int snapshot, int file, int line, int column);

// The next snapshot after `from` whose call level is at most `level` (Step
// Over: level = the current one; Step Out: one less); -1 when none.
int nextSnapshotAtLevel(const Timeline& timeline, int from, int level);

}  // namespace klueng::core::machine
