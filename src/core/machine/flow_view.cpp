// Queries over the program flow record (flow_view.h).
#include "klueng/core/machine/flow_view.h"

#include <algorithm>
#include <map>

namespace klueng::core::machine {

std::vector<WatchedVariable> variablesAt(const Timeline& timeline, int snapshot, int since) {
  std::vector<WatchedVariable> out;
  if (snapshot < 0 || snapshot >= static_cast<int>(timeline.snapshots.size())) return out;
  const FlowLog& flow = timeline.flow;
  const int stackIndex = timeline.snapshots[static_cast<std::size_t>(snapshot)].callStack;
  int locals = 0;
  if (stackIndex >= 0 && stackIndex < static_cast<int>(flow.stacks.size()) &&
      !flow.stacks[static_cast<std::size_t>(stackIndex)].empty())
    locals = std::max(0, flow.stacks[static_cast<std::size_t>(stackIndex)].back().locals);
  std::map<int, WatchedVariable> seen;
  for (const VariableWrite& w : flow.writes) {
    if (w.snapshot > snapshot) break;  // in execution order
    if (w.localFrame >= 0 && w.localFrame != locals) continue;
    WatchedVariable& v = seen[w.number];
    v.number = w.number;
    v.value = w.value;
    v.vacant = w.vacant;
    v.changed = since >= 0 && w.snapshot > since;
  }
  out.reserve(seen.size());
  for (const auto& [n, v] : seen) out.push_back(v);
  return out;
}

std::optional<WordValue> wordValueAt(const Timeline& timeline, int snapshot, int file, int line, int column) {
  std::optional<WordValue> found;
  for (const WordValue& v : timeline.flow.wordValues) {
    if (v.snapshot > snapshot) break;
    if (v.file == file && v.line == line && v.column == column) found = v;
  }
  return found;
}

int nextSnapshotAtLevel(const Timeline& timeline, int from, int level) {
  const int n = static_cast<int>(timeline.snapshots.size());
  for (int j = std::max(0, from + 1); j < n; ++j)
    if (timeline.snapshots[static_cast<std::size_t>(j)].callLevel <= level) return j;
  return -1;
}

}  // namespace klueng::core::machine
