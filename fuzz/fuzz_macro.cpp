// libFuzzer target: macro B expressions and program flow through the whole
// front of the pipeline — parse, check, interpret — with small endless-loop
// limits so a loop ends fast. The interpreter runs whatever the check says:
// it must stay safe on programs the check refuses. Every diagnostic must have
// a message in both languages.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string_view>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/messages.h"

using namespace klueng::core;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 20000) return 0;  // big inputs test the parser's limits, not the flow (fuzz_gcode has them)
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const gcode::Program program = gcode::parse(text, 1);
  for (const gcode::Block& b : program.blocks)
    for (const gcode::Word& w : b.words)
      if (w.expr >= static_cast<int>(program.expressions.size())) std::abort();

  const gcode::Dialect dialect = size % 3 == 0 ? gcode::Dialect::Haas : gcode::Dialect::Fanuc;
  gcode::CheckOptions check;
  check.dialect = dialect;
  for (const Diagnostic& d : gcode::check(program, check))
    if (!findMessage(d.code)) std::abort();

  machine::MachineSetup setup;
  setup.machine.maxBlocks = 2000;  // endless loops end after 20,000 moves (A151): fast under ASan
  setup.machine.maxRunTime = 3600.0;
  setup.machine.maxSpindleRpm = 3000.0;
  std::map<int, double> persistent{{500, 1.0}};
  machine::RunOptions run;
  run.dialect = dialect;
  run.persistentVariables = &persistent;
  const machine::Timeline t = machine::interpret(program, setup, run);
  if (t.alarm && !findMessage(t.alarm->code)) std::abort();
  for (const Diagnostic& n : t.flow.notices)
    if (!findMessage(n.code)) std::abort();
  for (const machine::StateSnapshot& s : t.snapshots)
    if (s.callStack < 0 || s.callStack >= static_cast<int>(t.flow.stacks.size())) std::abort();
  for (int n = 0; n < 1000; ++n)
    if (persistent.count(n) && (n < 500 || n > 999)) std::abort();
  return 0;
}
