#pragma once
// The units a run speaks (issue 28 item 4): those in force at its last block
// (a G20 program in inches, a Haas program without G20/G21 in the machine's
// power-on units); `powerOn` when no block ran. What the CLI's texts use when
// no --show-units is given, as the GUI's View ▸ Units shown ▸ Auto does.
#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/machine/timeline.h"
#include "klueng/core/units.h"

namespace klueng::core::machine {

DisplayUnits programUnits(const Timeline& timeline, gcode::InputUnits powerOn);

}  // namespace klueng::core::machine
