#pragma once
// The custom macro B variables a run keeps (Fanuc 0i-TF manual, "Types of
// variables" and "System variables"): locals #1-#33 per macro level, common
// #100-#199 and #500-#999 (kept between runs by the caller), the timers
// #3001/#3002, the part counters #3901/#3902 and the last T, N and M of the
// run (#4120 #4114 #4113). The variables that show the machine's state
// (offsets, modal codes, positions) are the interpreter's; the FlowLog record
// of reads and writes is the flow engine's. Private to machine.
#include <array>
#include <map>
#include <optional>
#include <vector>

#include "klueng/core/gcode/macro.h"

namespace klueng::core::machine {
class MachineSink;
}

namespace klueng::core::machine::detail {

using MacroLocals = std::array<gcode::MacroValue, 33>;

class MacroStore {
 public:
  MacroStore() : locals_(1) {}  // the main program's level

  // Whether the store keeps #n; then `out` is its value. `level`: the running
  // macro level (its locals); `clock`: the machining time so far (#3001 #3002).
  bool read(int n, int level, const MachineSink& clock, gcode::MacroValue& out) const;
  // Whether the store keeps #n; then it holds `v` from now on.
  bool write(int n, int level, const MachineSink& clock, gcode::MacroValue v);

  // A macro call's level, its locals starting as `arguments`: its index.
  int pushLevel(const MacroLocals& arguments);
  void popLevel();
  MacroLocals& locals(int level) { return locals_[static_cast<std::size_t>(level)]; }

  // #500-#999 from and back to the caller's keeping (a vacant one is erased).
  void loadPersistent(const std::map<int, double>& values);
  void savePersistent(std::map<int, double>& values) const;

  // What a block that ran leaves in #4120, #4114 and #4113 (nullopt: it had none).
  void noteBlock(std::optional<int> t, std::optional<int> n, std::optional<int> m);
  void partFinished() { partsMachined_ += 1.0; }  // #3901 counts finished parts

 private:
  std::vector<MacroLocals> locals_;                   // one per G65/G66 level (and the main's)
  std::array<gcode::MacroValue, 100> common_{};       // #100-#199
  std::array<gcode::MacroValue, 500> persistent_{};   // #500-#999
  double timerBase_ = 0.0;                            // #3001 counts from here (ms)
  double hourBase_ = 0.0;                             // #3002 (hours)
  double partsMachined_ = 0.0, partsRequired_ = 0.0;  // #3901 #3902
  int lastT_ = 0, lastM_ = 0, lastN_ = 0;             // #4120 #4113 #4114
};

}  // namespace klueng::core::machine::detail
