#pragma once
// Machine files on disk (issue 27): the user's machines folders, a file named
// on the command line, and the machine.cfg keys a machine file holds.
// gcode/machine_file.h reads the profile keys; this part reads files, checks
// the machine.cfg keys as machine.cfg's own reader does, and registers them.
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/gcode/machine_file.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::core::machine {

struct MachineFileResult {
  std::optional<gcode::MachineDefinition> machine;  // none when the file has an error
  std::vector<Diagnostic> diagnostics;              // located in the file; args[0] its name
};

// Reads and checks one machine file (profile keys and machine.cfg keys); does not register it.
MachineFileResult readMachineFile(const std::string& path);

// The machines folders, in the order they apply (a later file with the same
// id overrides): <user data folder>/machines, then <configDir>/machines when
// configDir is another folder. Missing folders are skipped.
std::vector<std::string> machineFolders(const std::string& configDir);

// Reads every *.machine file of the folders (sorted by name) and registers the
// good ones; the shipped files (built in) are never written. Returns the
// diagnostics of the bad ones, each with its file.
std::vector<SetupDiagnostic> loadMachineFolders(const std::vector<std::string>& folders);

// `--machine NAME|FILE`: a loaded machine's id, or a .machine file (read,
// checked and registered). nullopt with the diagnostics that say why.
std::optional<gcode::Dialect> resolveMachine(const std::string& nameOrFile, std::vector<SetupDiagnostic>& diagnostics);

// The machine a program names at its head, `(MACHINE: romi-gl240m)`
// (io::machineNamedIn; Job details writes it): a loaded machine. nullopt when it
// names none, or one that is not loaded; then `warnings` gets F205 at the id.
std::optional<gcode::Dialect> machineOfProgram(const io::ProgramFile& file, std::vector<Diagnostic>& warnings);

// The machine.cfg keys a machine file holds override the setup's (its rapids,
// travel, chuck ...); keys it leaves out keep the setup's values.
io::MachineConfig withMachineKeys(const io::MachineConfig& setup, const gcode::MachineProfile& machine);

}  // namespace klueng::core::machine
