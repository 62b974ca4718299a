#pragma once
// Internal: a machine's code lookup, built once when the machine is registered
// from its family's column of the code table, its G-code system's renamings and
// its M-code list (machine_profile.cpp keeps one per machine).
#include <array>
#include <deque>
#include <string>

#include "klueng/core/gcode/code_table.h"

namespace klueng::core::gcode::detail {

struct CodeIndex {
  std::array<std::array<const CodeInfo*, kCodeNumbers>, 2> rows{};  // [G, M][number]
  std::deque<CodeInfo> renamed;   // rows of the system under their own numbers (stable addresses)
  std::deque<std::string> texts;  // their names and examples with the system's G numbers
};

void buildCodeIndex(const MachineProfile& profile, CodeIndex& out);
// numberInSystem and inSystemNumbers for a system (usable while a machine is registered).
int numberInSystemOf(int numberInA, GcodeSystem system);
std::string inSystemNumbers(std::string_view text, GcodeSystem system);
const CodeIndex& codeIndexOf(Dialect dialect);
// A registered machine by id (for `base =`), nullptr when none.
const MachineProfile* loadedMachine(std::string_view id);
// "fanuc, haas, classic, ...": the ids of the registered machines.
std::string loadedMachineIds();

}  // namespace klueng::core::gcode::detail
