#pragma once
// The one way to read a machine setup from its folder (issue 12): machine.cfg
// (optional: SPEC 1 defaults when absent; first, because its turret size bounds
// the tool table), tools.cfg, offset.cfg and, when asked, the tool bitmaps.
// The GUI, the CLI and the reports all read a setup through this.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/image.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::machine {

// A diagnostic with the file it belongs to (a cfg file or a bitmap).
struct SetupDiagnostic {
  std::string file;
  Diagnostic diagnostic;
};

struct LoadedSetup {
  std::string dir;     // where the files came from
  MachineSetup setup;  // defaults for what could not be read
  std::vector<SetupDiagnostic> diagnostics;
  bool unreadable = false;     // tools.cfg or offset.cfg could not be read at all (F101-F103)
  bool toolTableRead = false;  // tools.cfg was read: T words are checked against its bitmaps
  // The decoded bitmaps, when asked for ([0] = tool 01).
  std::array<std::optional<io::RgbImage>, io::kToolCount> bitmaps;
  bool hasErrors() const;
  // For gcode::CheckOptions::toolsWithBitmap: the stations whose bitmap file
  // exists (machine::toolsWithBitmap), or nullopt when no tool table was read.
  std::optional<std::vector<int>> toolsWithBitmap() const;
};

// True for "the file could not be read at all" (missing, a folder, no access, too large, a
// named pipe or a device refused unopened, a path too long to open).
bool isUnreadable(const Diagnostic& d);

// Reads the setup from findConfigDir(explicitDir). Every bitmap is decoded
// (one that does not decode is no tool); `readBitmaps` keeps the images.
LoadedSetup loadMachineSetup(const std::string& explicitDir = {}, bool readBitmaps = false);

// The stations whose bitmap (tools.cfg line or library tool) names an existing
// file: the T words the check accepts (E305). The one meaning for the editor,
// a run, the CLI and the reports.
std::vector<int> toolsWithBitmap(const MachineSetup& setup);

}  // namespace klueng::core::machine
