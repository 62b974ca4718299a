#pragma once
// tools.cfg and offset.cfg (SPEC 11) and the machine parameter file.
#include <array>
#include <string>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

constexpr int kToolCount = 8;
constexpr int kOffsetCount = 16;

struct ToolTable {
  // bitmap file name of tool 01..08 ([0] = tool 01), as written; empty = none.
  std::array<std::string, kToolCount> bitmap;
  std::string folder;  // folder of tools.cfg, to resolve relative names
  std::string bitmapPath(int tool) const;  // resolved path, empty if none
};

struct Offset {
  double x = 0.0;   // X offset, diameter
  double z = 0.0;
  double r = 0.0;   // nose radius
  int tip = 0;      // imaginary tip 0..9
};

struct OffsetTable {
  std::array<Offset, kOffsetCount> offsets;  // [0] = offset 01
  const Offset& at(int number) const { return offsets.at(number - 1); }  // number 1..16
};

struct MachineConfig {
  double rapidX = 4000.0;        // mm/min (radial axis; diameter values move at this rate in radius)
  double rapidZ = 8000.0;        // mm/min
  double maxSpindleRpm = 3000.0;
  double referenceX = 0.0;       // diameter, work coordinates at start
  double referenceZ = 300.0;
  double startX = 0.0;           // tool start position (diameter)
  double startZ = 300.0;
  double travelXMin = -1000.0;   // diameter
  double travelXMax = 1000.0;
  double travelZMin = -1000.0;
  double travelZMax = 1000.0;
  double chuckGrip = 15.0;       // mm of stock held by the jaws
  double chuckJawHeight = 20.0;  // radial size of the jaws outside the stock, mm
  // Through-hole of the spindle and chuck body (diameter, mm): a drill or boring
  // bar passing the part's left end inside it is not a chuck collision. 40 mm is
  // the through-hole of a 160 mm three-jaw chuck on a school lathe; 0 = none.
  double spindleBore = 40.0;
  int turretStations = 12;       // tool stations on the turret, 1..24
};

// Line n = bitmap of tool 0n (empty line = no bitmap); lines after 8 are ignored
// (warning F107). readToolTable also reports bitmaps that do not exist (F121).
ReadResult<ToolTable> readToolTable(const std::string& path);
ReadResult<ToolTable> parseToolTable(std::string_view text, const std::string& folder, const std::string& fileName);
std::string formatToolTable(const ToolTable& t);

// Line n = `X Z R T` of offset n; a bad row stays 0 0 0 0 and is reported.
ReadResult<OffsetTable> readOffsetTable(const std::string& path);
ReadResult<OffsetTable> parseOffsetTable(std::string_view text, const std::string& fileName);
std::string formatOffsetTable(const OffsetTable& t);

// machine.cfg: `key = value` lines, '#' comments; unknown keys and bad values are errors.
// Keys: rapid_x rapid_z max_spindle_rpm reference_x reference_z start_x start_z
// travel_x_min travel_x_max travel_z_min travel_z_max chuck_grip chuck_jaw_height
// spindle_bore turret_stations (a whole number 1..24, F147 otherwise).
// Missing keys keep MachineConfig's defaults (SPEC 1).
ReadResult<MachineConfig> readMachineConfig(const std::string& path);
ReadResult<MachineConfig> parseMachineConfig(std::string_view text, const std::string& fileName);
std::string formatMachineConfig(const MachineConfig& m);

// The folder holding tools.cfg/offset.cfg/machine.cfg: explicit dir if given,
// else $KLUENG_DATA_DIR, else the per-user copy if it holds a tools.cfg,
// else the shipped folder.
std::string findConfigDir(const std::string& explicitDir = {});

// $XDG_DATA_HOME/klueng, or ~/.local/share/klueng; empty when neither is known.
std::string userConfigDir();
// The folder of the shipped defaults (the repository top in a build tree).
std::string shippedConfigDir();
// Creates the per-user copy from the shipped defaults (cfg files and the
// bitmaps tools.cfg names), copying only what is missing, so a read-only
// install still has a writable tool table. Returns the folder, or empty and
// fills error.
std::string ensureUserConfigDir(std::string* error = nullptr);

}  // namespace klueng::core::io
