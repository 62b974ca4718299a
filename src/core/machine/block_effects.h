#pragma once
// What a block's T, F, S and M words do, and which blocks may run at all: on
// the machine during a run (the interpreter itself), or as part of a G70-G73
// profile being read (profile_capture.h), where they are recorded for the
// cycle instead. The interpreter reads every block the same way and hands
// these words to whichever is in force. Private to machine.
#include <cstddef>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/gcode/program.h"

namespace klueng::core::machine::detail {

// A G or M word of the running block with its code table row.
struct CodeWord {
  const gcode::Word* word;
  const gcode::CodeInfo* info;
};

class BlockEffects {
 public:
  virtual ~BlockEffects() = default;
  // Whether moves are checked against the travel and the feed/spindle state
  // (a profile is a shape: the cycle checks the moves it makes from it).
  virtual bool checksMoves() const = 0;
  // The block's codes, before anything of it takes effect (false: refused).
  virtual bool blockAllowed(const CodeWord* motion, const CodeWord* cycle, const CodeWord* oneShot,
                            const CodeWord* single) = 0;
  virtual bool tool(const gcode::Word& t) = 0;
  virtual void feed(double mm) = 0;  // the block's F, already in mm
  // `coordinateSet`: the S of a G50 block (the spindle speed clamp).
  virtual bool speed(const gcode::Word& s, bool coordinateSet) = 0;
  // The block's M codes, sorted by phase: how many of them run (false: refused).
  virtual bool mCodes(const CodeWord* ms, std::size_t& count) = 0;
};

}  // namespace klueng::core::machine::detail
