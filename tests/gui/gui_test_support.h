#pragma once
// Helpers shared by the GUI tests and the performance probe.
#include <string>

#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::gui_test {

// The shipped tools.cfg, offset.cfg and machine.cfg (or $KLUENG_DATA_DIR's).
inline core::machine::MachineSetup loadSetup() {
  const std::string dir = core::io::findConfigDir(KLUENG_SOURCE_DIR);
  core::machine::MachineSetup s;
  s.tools = *core::io::readToolTable(dir + "/tools.cfg").value;
  s.offsets = *core::io::readOffsetTable(dir + "/offset.cfg").value;
  s.machine = *core::io::readMachineConfig(dir + "/machine.cfg").value;
  return s;
}

}  // namespace klueng::gui_test
