#pragma once
// Machine files (issue 27): a machine is a text file of `key = value` lines,
// the style of machine.cfg, so a teacher edits one in any editor and a bad line
// is named by file, line and key (docs/dialects.md, "Machine files"). This part
// reads the profile keys; the machine.cfg keys it finds (rapids, travel, chuck
// ...) are left for machine/machine_files.h, which reads them as machine.cfg does.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/machine_profile.h"

namespace klueng::core::gcode {

// A machine as read, owning its texts (MachineProfile only views them).
struct MachineDefinition {
  std::string id, nameEn, nameTh, letters, file, text;
  std::vector<int> oneShots, mCodes, errorsAsWarnings;
  MachineProfile profile{};  // its string views and spans are set when it is registered
  // Keys that are not profile keys, in file order: machine.cfg's, or mistakes.
  struct OtherKey {
    std::string key;
    int line = 0;
  };
  std::vector<OtherKey> otherKeys;
};

struct MachineFileRead {
  std::optional<MachineDefinition> machine;  // none when the file has an error
  std::vector<Diagnostic> diagnostics;       // ranges: line and column in the file; args[0] the file name
};

// Reads a machine file's text. `base = ID` starts from a loaded machine, so a
// file may hold only what differs; without it every profile key is needed.
MachineFileRead parseMachineFile(std::string_view text, const std::string& fileName);

// Adds a machine to the registry, or replaces the one with its id (a user's
// fanuc.machine overrides the shipped one); returns its place. A replaced
// profile stays alive, so a check running on another thread keeps its copy.
Dialect registerMachine(MachineDefinition machine);

// The shipped machine files built into the program (resources/machines, in
// menu order): name and text. Generated at build time from the same files.
struct ShippedMachineFile {
  std::string_view name;
  std::string_view text;
};
std::vector<ShippedMachineFile> shippedMachineFiles();

}  // namespace klueng::core::gcode
