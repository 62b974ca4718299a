#pragma once
// The custom macro B variables a run keeps (Fanuc 0i-TF manual, "Types of
// variables" and "System variables"): locals #1-#33 per macro level, common
// #100-#199 and #500-#999 (kept between runs by the caller), the timers
// #3001/#3002, the part counters #3901/#3902 and the last T, N and M of the
// run (#4120 #4114 #4113). The variables that show the machine's state
// (offsets, modal codes, positions) are the interpreter's; the FlowLog record
// of reads and writes is the flow engine's. Private to machine.
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "klueng/core/gcode/macro.h"
#include "machine/loop_proof.h"

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
  // A level's locals start again as `values` (each pass of G65 ... L).
  void resetLocals(int level, const MacroLocals& values);

  // #500-#999 from and back to the caller's keeping (a vacant one is erased).
  void loadPersistent(const std::map<int, double>& values);
  void savePersistent(std::map<int, double>& values) const;

  // What a block that ran leaves in #4120, #4114 and #4113 (nullopt: it had none).
  void noteBlock(std::optional<int> t, std::optional<int> n, std::optional<int> m);
  void partFinished() { partsMachined_ += 1.0; }  // #3901 counts finished parts

  // For the proof of an endless loop (loop_proof.h): the variables as state words (the locals
  // of every level, the common and persistent ones the run wrote, the counters, the last T N M).
  void writeState(RunStateWords& out) const;
  // The program has read the timers (#3001 #3002): its state includes the clock, no loop repeats it.
  bool clockRead() const { return clockRead_; }
  // A hash of #1-#33 (every level), #100-#199 and #500-#999, kept up to date as they change:
  // the same values, the same hash.
  std::uint64_t valuesHash() const { return valuesHash_; }

 private:
  std::vector<MacroLocals> locals_;                   // one per G65/G66 level (and the main's)
  std::array<gcode::MacroValue, 100> common_{};       // #100-#199
  std::array<gcode::MacroValue, 500> persistent_{};   // #500-#999
  double timerBase_ = 0.0;                            // #3001 counts from here (ms)
  double hourBase_ = 0.0;                             // #3002 (hours)
  double partsMachined_ = 0.0, partsRequired_ = 0.0;  // #3901 #3902
  int lastT_ = 0, lastM_ = 0, lastN_ = 0;             // #4120 #4113 #4114
  mutable bool clockRead_ = false;
  std::uint64_t valuesHash_ = 0;  // the XOR of valueHash() over every variable (a vacant 0 adds nothing)
  static std::uint64_t valueHash(std::uint64_t slot, const gcode::MacroValue& v);
  void setValue(gcode::MacroValue& at, std::uint64_t slot, gcode::MacroValue v) {
    valuesHash_ ^= valueHash(slot, at) ^ valueHash(slot, v);
    at = v;
  }
  // The key of a variable in the hash: #1-#33 of a level, #100-#199 and #500-#999 by number.
  static std::uint64_t localSlot(int level, int index) {
    return (1ull << 40) | (static_cast<std::uint64_t>(level) << 6) | static_cast<std::uint64_t>(index);
  }
  static std::uint64_t globalSlot(int n) { return (2ull << 40) | static_cast<std::uint64_t>(n); }
  // #100-#199 and #500-#999 written by the run (indexes into common_ then persistent_, 0-599),
  // in the order first written: the others hold what they held at the start.
  std::vector<short> written_;
  std::array<bool, 600> isWritten_{};
  void noteWritten(int slot) {
    if (isWritten_[static_cast<std::size_t>(slot)]) return;
    isWritten_[static_cast<std::size_t>(slot)] = true;
    written_.push_back(static_cast<short>(slot));
  }
};

}  // namespace klueng::core::machine::detail
