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
};

ReadResult<ToolTable> readToolTable(const std::string& path);
ReadResult<ToolTable> parseToolTable(std::string_view text, const std::string& folder, const std::string& fileName);
std::string formatToolTable(const ToolTable& t);

ReadResult<OffsetTable> readOffsetTable(const std::string& path);
ReadResult<OffsetTable> parseOffsetTable(std::string_view text, const std::string& fileName);
std::string formatOffsetTable(const OffsetTable& t);

// machine.cfg: `key = value` lines, '#' comments; unknown keys and bad values are errors.
ReadResult<MachineConfig> readMachineConfig(const std::string& path);
ReadResult<MachineConfig> parseMachineConfig(std::string_view text, const std::string& fileName);
std::string formatMachineConfig(const MachineConfig& m);

// The folder holding tools.cfg/offset.cfg/machine.cfg: explicit dir if given,
// else $KLUENG_DATA_DIR, else a per-user copy (~/.local/share/klueng, created
// from the shipped defaults), else the shipped folder.
std::string findConfigDir(const std::string& explicitDir = {});

}  // namespace klueng::core::io
