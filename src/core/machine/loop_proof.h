#pragma once
// The proof that a run loops for ever (issue 42 item 6). The block, time and move
// limits (A132, A133, A151) stop a long run but prove nothing: a finite WHILE of
// 70,000 turns meets them too. A loop is endless when the run comes back by a
// backward jump (GOTO, END, M99) to the same state it was in before: the same
// block and call stack, the same macro variables, modal state, offsets and
// position. What the run does next depends on nothing else, so it would repeat
// that stretch for ever. The states at the backward jumps are compared with
// Brent's cycle check: one saved state, replaced at every power of two of jumps,
// each new state compared with it. A loop is found within a few of its own turns;
// a run of any length keeps two states, never more.
//
// Cheap for loops that end: a quick key (a hash of the variables kept up to date
// as they are written, the block, the position) tells most states apart, and the
// whole state is written out only when the keys agree or a state is to be saved.
// Private to machine.
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "klueng/core/gcode/macro.h"

namespace klueng::core::machine::detail {

// Mixes one more 64-bit word into a hash (splitmix64's finaliser).
inline std::uint64_t mixHash(std::uint64_t h, std::uint64_t w) {
  std::uint64_t z = h ^ (w + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

inline std::uint64_t bitsOf(double d) {
  std::uint64_t w = 0;
  std::memcpy(&w, &d, sizeof w);
  return w;
}

// A run's state written as 64-bit words (doubles by their bits: the same state
// writes the same words).
class RunStateWords {
 public:
  void clear() { words_.clear(); }
  void add(std::uint64_t w) { words_.push_back(w); }
  void add(std::int64_t w) { words_.push_back(static_cast<std::uint64_t>(w)); }
  void add(int w) { add(static_cast<std::int64_t>(w)); }
  void add(bool w) { add(static_cast<std::uint64_t>(w)); }
  void add(double d) { words_.push_back(bitsOf(d)); }
  void add(const gcode::MacroValue& v) {
    add(v.vacant);
    add(v.value);
  }
  bool operator==(const RunStateWords&) const = default;

 private:
  std::vector<std::uint64_t> words_;
};

class LoopProof {
 public:
  // At a backward jump: true when the run was in this state before (it loops for ever).
  // `quick` is a key of the state (the same state, the same key); `writeState(RunStateWords&)`
  // writes the whole state, and is called only when it is needed.
  template <class WriteState>
  bool seenBefore(std::uint64_t quick, WriteState&& writeState) {
    const bool mayMatch = haveSaved_ && quick == savedQuick_;
    const bool save = !haveSaved_ || ++steps_ >= power_;
    if (!mayMatch && !save) return false;
    now_.clear();
    writeState(now_);
    if (mayMatch && now_ == saved_) return true;
    if (save) {
      std::swap(saved_, now_);
      savedQuick_ = quick;
      haveSaved_ = true;
      power_ *= 2;
      steps_ = 0;
    }
    return false;
  }

 private:
  RunStateWords saved_, now_;
  std::uint64_t savedQuick_ = 0;
  bool haveSaved_ = false;
  long long power_ = 1;  // Brent: the saved state is replaced when `steps_` reaches this
  long long steps_ = 0;  // jumps since it was saved
};

}  // namespace klueng::core::machine::detail
