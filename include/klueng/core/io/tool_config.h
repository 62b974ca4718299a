#pragma once
// tools.cfg and offset.cfg (SPEC 11) and the machine parameter file.
#include <array>
#include <string>
#include <string_view>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

struct ToolLibrary;

// Turret stations: a machine has 1..kMaxStations (machine.cfg turret_stations,
// default kDefaultTurretStations). tools.cfg must have the seed's 8 lines;
// lines 9..stations are optional.
constexpr int kMaxStations = 24;
constexpr int kDefaultTurretStations = 12;
constexpr int kSeedToolLines = 8;
constexpr int kToolCount = kMaxStations;  // every array and loop over stations
// Offset rows 01..64; offset.cfg must have the seed's 16 lines, 17..64 are optional (0 0 0 0).
constexpr int kOffsetCount = 64;
constexpr int kSeedOffsetLines = 16;
constexpr double kSeedPixelsPerMm = 2.0;  // SPEC 11: a plain bitmap is drawn at 2 px/mm
constexpr std::string_view kLibraryPrefix = "library:";
// A tool is at most 500 mm each way: 1000 pixels at the seed's 2 px/mm, and in
// proportion at a library bitmap's own resolution. A larger bitmap is a setup
// error (F139, machine/setup_files.h), not a tool.
constexpr int kMaxToolBitmapPixels = 1000;
constexpr int maxToolBitmapPixels(double pixelsPerMm) {
  return static_cast<int>(kMaxToolBitmapPixels * pixelsPerMm / kSeedPixelsPerMm);
}

struct ToolTable {
  // Line n of tools.cfg for station n ([0] = station 01), as written: a bitmap
  // file name, `library:ID` (a tool of the library, docs/tools.md), or empty = none.
  std::array<std::string, kMaxStations> bitmap;
  // For `library:ID` lines: the library bitmap's path (empty while unresolved),
  // its resolution, nose radius and tip. Plain bitmaps: empty / 2 px/mm.
  std::array<std::string, kMaxStations> libraryPath;
  std::array<double, kMaxStations> pixelsPerMm = filledPixelsPerMm();
  // The tool's cutting material as the line says it, after ` | `: `hss`, `carbide`,
  // `coated-carbide` (`01-turning.bmp | material=hss`); empty = the library tool's, else not
  // known (issue 39: the cutting speeds are judged by it). Tool Select edits it.
  std::array<std::string, kMaxStations> material;
  int stations = kDefaultTurretStations;  // turret size the table was read for
  std::string folder;                     // folder of tools.cfg, to resolve relative names
  // Bitmaps that exist but do not decode (machine/setup_files.h sets them): no tool there.
  std::array<bool, kMaxStations> bitmapUnreadable{};
  // Tools Klueng guessed from a program (machine/tool_inference.h), not chosen by
  // the user: their holders touching the stock or chuck are warnings, not alarms.
  std::array<bool, kMaxStations> guessed{};
  bool isGuess(int tool) const {
    return tool >= 1 && tool <= kMaxStations && guessed[static_cast<std::size_t>(tool - 1)];
  }
  // Stations that hold or stop the bar (a bar puller, a bar stop: "(BARPULER)", "(BAR STOP)"): they
  // go into the bar with the spindle stopped, so their moves remove nothing and touch nothing.
  std::array<bool, kMaxStations> holdsBar{};
  bool isBarHolder(int tool) const {
    return tool >= 1 && tool <= kMaxStations && holdsBar[static_cast<std::size_t>(tool - 1)];
  }
  // Of those, the pullers (a bar stop only stands in the bar's way).
  std::array<bool, kMaxStations> pullsBarOut{};
  bool pullsBar(int tool) const { return isBarHolder(tool) && pullsBarOut[static_cast<std::size_t>(tool - 1)]; }
  std::string bitmapPath(int tool) const;  // resolved path, empty if none
  double pixelsPerMmOf(int tool) const;    // 2 for a plain bitmap
  std::string libraryId(int tool) const;   // the ID of a `library:ID` line, else empty
  // Station `tool` becomes the library tool (line `library:ID`).
  void setLibraryTool(int tool, const std::string& id, const std::string& path, double pixelsPerMm);
  static std::array<double, kMaxStations> filledPixelsPerMm() {
    std::array<double, kMaxStations> a{};
    a.fill(kSeedPixelsPerMm);
    return a;
  }
};

struct Offset {
  double x = 0.0;  // X offset, diameter
  double z = 0.0;
  double r = 0.0;  // nose radius
  int tip = 0;     // imaginary tip 0..9
  bool operator==(const Offset&) const = default;
};

struct OffsetTable {
  std::array<Offset, kOffsetCount> offsets;                              // [0] = offset 01
  const Offset& at(int number) const { return offsets.at(number - 1); }  // number 1..64
  Offset& at(int number) { return offsets.at(number - 1); }
};

struct MachineConfig {
  double rapidX = 4000.0;  // mm/min (radial axis; diameter values move at this rate in radius)
  double rapidZ = 8000.0;  // mm/min
  // Axis accelerations, mm/s² (X radial): every move speeds up and slows down
  // at these as the control plans it (issue 11). 0 = off: moves start and stop
  // at once, the time is length / feed as the textbooks compute it.
  double accelX = 0.0;
  double accelZ = 0.0;
  double maxSpindleRpm = 3000.0;
  // What the spindle can give and the chuck allows (issue 39, cutting data): the motor's
  // rating in kW, its largest torque in N*m, the chuck's highest permitted rpm. 0 = not
  // known (the machine file or machine.cfg does not say): that check is not made.
  double spindlePowerKw = 0.0;
  double spindleTorqueNm = 0.0;
  double chuckMaxRpm = 0.0;
  double referenceX = 0.0;  // diameter, work coordinates at start
  double referenceZ = 300.0;
  double startX = 0.0;  // tool start position (diameter)
  double startZ = 300.0;
  double travelXMin = -1000.0;  // diameter
  double travelXMax = 1000.0;
  double travelZMin = -1000.0;
  double travelZMax = 1000.0;
  double chuckGrip = 15.0;       // mm of stock held by the jaws
  double chuckJawHeight = 20.0;  // radial size of the jaws outside the stock, mm
  // Through-hole of the spindle and chuck body (diameter, mm): a drill or boring
  // bar passing the part's left end inside it is not a chuck collision. 40 mm is
  // the through-hole of a 160 mm three-jaw chuck on a school lathe; 0 = none.
  double spindleBore = 40.0;
  int turretStations = 12;  // tool stations on the turret, 1..24
  // The tools work beyond the centre line (programmed in negative X: rear tool
  // posts, many hobby and Russian lathes): the cut mirrors them onto the front,
  // where the same bar is cut the same way (a plain program's run decides it).
  bool toolsBeyondCentre = false;
  // A length written without a decimal point (X30, G71 U1250): true = whole mm
  // or inches (calculator-type input, Fanuc parameter 3401#0 DPI = 1); false =
  // least input increments (X30 = 0.030 mm), as a standard Fanuc or Haas reads
  // it (gcode/decimal_point.h). A plain program's numbers decide it for that
  // program (machine/job_file.h); this setting breaks ties.
  bool calculatorInput = true;
  // A program that loops without end stops with an alarm (issue 9): after this
  // many blocks run again by a loop, a jump or a call (max_blocks), or after
  // this much simulated machining time in seconds (max_run_time).
  int maxBlocks = 200000;
  double maxRunTime = 36000.0;
  bool operator==(const MachineConfig&) const = default;
};

// Line n = bitmap of station n (empty line = no bitmap), or `library:ID`; at
// least 8 lines (F120), lines after `stations` are ignored (warning F107).
// `library:ID` lines are resolved against `library` (the shipped one when
// null; F123 for an unknown ID). readToolTable also reports bitmaps that do
// not exist (F121).
ReadResult<ToolTable> readToolTable(const std::string& path, int stations = kDefaultTurretStations,
                                    const ToolLibrary* library = nullptr);
ReadResult<ToolTable> parseToolTable(std::string_view text, const std::string& folder, const std::string& fileName,
                                     int stations = kDefaultTurretStations, const ToolLibrary* library = nullptr);
// At least 8 lines, up to the last station with a tool.
std::string formatToolTable(const ToolTable& t);

// Line n = `X Z R T` of offset n; a bad row stays 0 0 0 0 and is reported.
// At least 16 lines (F130); rows 17..64 are optional; later lines F107.
ReadResult<OffsetTable> readOffsetTable(const std::string& path);
ReadResult<OffsetTable> parseOffsetTable(std::string_view text, const std::string& fileName);
// 16 rows, and more up to the last row that is not 0 0 0 0.
std::string formatOffsetTable(const OffsetTable& t);

// machine.cfg: `key = value` lines, '#' comments; unknown keys and bad values are errors.
// Keys: rapid_x rapid_z accel_x accel_z max_spindle_rpm reference_x reference_z start_x start_z
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
// The folder of the shipped defaults: <prefix>/share/klueng beside the running
// program's bin/ when installed, the repository top in a build tree.
std::string shippedConfigDir();
// The shipped cutting-speed table (resources/parts/cutting_speeds.cfg) the program generator reads.
std::string shippedCuttingSpeedsPath();
// The sample programs shipped with Klueng: samples/ in the shipped folder when
// installed, resources/samples in a build tree; empty when neither is there.
std::string samplesDir(const std::string& shippedDir = shippedConfigDir());
// <prefix>/share/klueng for a program at <prefix>/bin/NAME, when it holds a
// tools.cfg; empty otherwise.
std::string installedDataDir(const std::string& executable);
// Creates the per-user copy from the shipped defaults (cfg files and the
// bitmaps tools.cfg names), copying only what is missing, so a read-only
// install still has a writable tool table. Returns the folder, or empty and
// fills error.
std::string ensureUserConfigDir(std::string* error = nullptr);

}  // namespace klueng::core::io
