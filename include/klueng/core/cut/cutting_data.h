#pragma once
// Cutting data that teaches (issue 39): the numbers of every cut of a recorded
// run, and the warnings a teacher would give about them (docs/cutting-data.md).
//
//   CuttingDataOptions options = cuttingDataOptions(header.material, setup, shippedMaterials());
//   CuttingData data = measureCuts(timeline, CutSetup::from(header, setup), options);
//
// The numbers come from the run Klueng already records (no second
// interpretation): S and the diameter give the cutting speed (the interpreter
// has applied G96/G97 and the G50/G92 clamp to every move's rpm), F and the rpm
// the feed per revolution, and the stock each move really removes the depth of
// cut (a CutSimulator run with a RemovalTally attached). Computed on demand
// only: a plain `simulate` never pays for it.
//
// Formulas (Sandvik Coromant, "Turning — formulas and definitions"; Kienzle):
//   Vc = pi * D * n / 1000               m/min (D the diameter cut, n rpm)
//   f  = feed / n                        mm/rev (G32 threads: the lead)
//   ap = along Z: the median radial cut of the stock columns the move touched;
//        along X: removed section area / radial length engaged      mm
//   h  = f * sin(kr)                     mm, kr = kEnteringAngleDeg (95 degrees)
//   b  = ap / sin(kr)                    mm, the chip's width
//   Q  = Vc * ap * f                     cm^3/min
//   Rz = f^2 / (8 r) * 1000              um (r the nose radius; none for a sharp tool)
//   Ra ~ Rz / 4 = f^2 / (32 r) * 1000    um
//   kc = kc1.1 * h^-mc                   N/mm^2 (Kienzle)
//   Fc = kc * ap * f                     N  (= kc * b * h)
//   Pc = Fc * Vc / 60000                 kW
//   M  = Fc * D / 2000                   N*m
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/cut/cut_simulator.h"
#include "klueng/core/cut/part_features.h"
#include "klueng/core/diagnostic.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/machine/timeline.h"
#include "klueng/core/units.h"

namespace klueng::core::io {
struct ToolLibrary;
}

namespace klueng::core::cut {

// The entering angle assumed for h and b: the 95-degree holders (PCLNR/PDJNR style) of
// the library's turning inserts. sin(95 deg) = 0.9962, so h is within 0.4 % of f.
inline constexpr double kEnteringAngleDeg = 95.0;

enum class ToolMaterial { Unknown, Hss, Carbide, CoatedCarbide };
std::string_view toolMaterialId(ToolMaterial m);  // "hss", "carbide", "coated-carbide", "" for Unknown
bool parseToolMaterialId(std::string_view id, ToolMaterial& out);

// A row of resources/parts/materials.cfg.
struct Material {
  std::string id;                  // "s45c"
  std::vector<std::string> names;  // how a job header may name it (lower case): "s45c", "1045", ...
  std::string nameEn;
  std::string nameTh;
  double hssMin = 0.0, hssMax = 0.0;          // Vc range, m/min, with an HSS tool
  double carbideMin = 0.0, carbideMax = 0.0;  // and with carbide (coated carbide: the same)
  double kc11 = 0.0;                          // N/mm^2 at h = 1 mm; 0 = not known: no force or power
  double mc = 0.0;
  std::string source;
  int line = 0;
};

struct MaterialTable {
  std::vector<Material> rows;
  // The row a job header's material names (any of its names, case and spaces ignored), else the row
  // of a name the header holds, the earliest in its row's list ("Steel S45C" -> s45c, not the
  // generic "steel" late in ss400's list); nullptr when none.
  const Material* find(std::string_view headerMaterial) const;
  std::string idList() const;  // "s45c, ss400, ..."
};

// `id | names (comma separated) | English | Thai | HSS min-max | carbide min-max | kc1.1 | mc | source`.
// A bad line is F173 (fields) / F174 (a number or range), and left out.
io::ReadResult<MaterialTable> parseMaterials(std::string_view text, const std::string& fileName);
io::ReadResult<MaterialTable> readMaterials(const std::string& path);
std::string shippedMaterialsPath();       // resources/parts/materials.cfg of the shipped data
const MaterialTable& shippedMaterials();  // read once

// A roughness mark of the drawing (a part design step's `roughness`, design::finishMarks): the Ra
// in um the surface of [zLeft, zRight] between diameters dMin and dMax must not exceed.
struct FinishMark {
  bool inside = false;  // a bore's surface
  double zLeft = 0.0, zRight = 0.0;
  double dMin = 0.0, dMax = 0.0;  // mm; a cylinder's both its diameter
  double ra = 0.0;                // um
};

// What the run's numbers are judged against.
struct CuttingDataOptions {
  const Material* material = nullptr;  // nullptr: no Vc range, no force or power
  std::array<ToolMaterial, io::kToolCount> toolMaterial{};
  std::array<double, io::kToolCount> edgeLength{};  // mm of the insert's cutting edge; 0 = not known
  // The library tool's nose radius, mm: used when the station's offset row says R 0.
  std::array<double, io::kToolCount> noseRadius{};
  // A drill's diameter, mm (its Vc is at its rim, not at the path on the axis); 0 = not a drill.
  std::array<double, io::kToolCount> drillDiameter{};
  double spindlePowerKw = 0.0;   // machine.cfg spindle_power_kw; 0 = not known
  double spindleTorqueNm = 0.0;  // spindle_torque_nm
  double chuckMaxRpm = 0.0;      // chuck_max_rpm
  // A finishing cut (ap <= finishingDepth) that leaves Ra above this (um) is W332. 3.2 um (N8,
  // the usual turned-finish mark) where no mark of `finishMarks` lies under the cut.
  double finishRa = 3.2;
  double finishingDepth = 0.5;
  std::vector<FinishMark> finishMarks;    // the drawing's marks: each wins over finishRa on its surface
  DisplayUnits units = DisplayUnits::Mm;  // the program's: numbers in warnings, ft/min under inch
  int warningsPerCode = 20;               // at most so many of one code (one per block)
  // The check (issue 39 item 1): warnings only, no CutNumbers kept. The moves that cannot warn
  // whatever depth they cut are not measured: the stock is cut only as far as the last move that
  // could warn, and not at all when none could (a sound 100,000-block program costs one pass over
  // its moves, no cut).
  bool warningsOnly = false;
  // Only the moves before this one (a record's first alarm: the real run stops there).
  std::size_t moveEnd = std::numeric_limits<std::size_t>::max();
};

// The facts of the run's tools from the library their `library:ID` lines name
// (a plain bitmap's material is not known), machine.cfg's limits, the material row.
CuttingDataOptions cuttingDataOptions(const std::string& headerMaterial, const io::ToolTable& tools,
                                      const io::MachineConfig& machine, const MaterialTable& materials,
                                      const io::ToolLibrary* library = nullptr);

// The Ra a finishing cut at path diameter `diameter` from Z `zA` to `zB` must not exceed: the
// drawing's mark under it (`mark` set), else options.finishRa.
double finishLimit(const CuttingDataOptions& options, bool inside, double diameter, double zA, double zB,
                   const FinishMark** mark = nullptr);

// One cutting move (Line, Arc, Thread with the spindle turning and material removed).
struct CutNumbers {
  std::size_t move = 0;
  int line = 0, file = 0, blockIndex = 0, tool = 0;
  double tStart = 0.0, tEnd = 0.0;
  double diameter = 0.0;                                    // mm, the largest the move cuts at (its path's)
  double rpm = 0.0;                                         // at that diameter
  double vc = 0.0;                                          // m/min there
  double feed = 0.0;                                        // f, mm/rev
  double depth = 0.0;                                       // ap, mm
  double chipWidth = 0.0;                                   // b, mm
  double chipThickness = 0.0;                               // h, mm
  double removalRate = 0.0;                                 // Q, cm^3/min
  double noseRadius = 0.0;                                  // mm
  std::optional<double> rz, ra;                             // um; none for a sharp tool or a thread
  double kc = 0.0, force = 0.0, power = 0.0, torque = 0.0;  // N/mm^2, N, kW, N*m; 0 without kc1.1
  bool thread = false;
  bool inside = false;        // the cut was in a bore (its path nearer the bore than the outside)
  bool facing = false;        // its path runs more along X than along Z (facing, grooving, parting)
  double z0 = 0.0, z1 = 0.0;  // its path's ends, Z mm
  double d0 = 0.0, d1 = 0.0;  // and diameters, mm
};

// The roughness each finished surface got (issue 39 item 4): a feature of the finished part
// (cut/part_features.h) and the cut that left it, the last one to reach its surface.
struct SurfaceFinish {
  bool inside = false;
  double zLeft = 0.0, zRight = 0.0;  // the surface's extent (a face: zLeft == zRight)
  double dMin = 0.0, dMax = 0.0;     // its diameters
  int line = 0, file = 0;            // the block that left it
  double feed = 0.0, noseRadius = 0.0;
  double ra = 0.0, rz = 0.0;  // um
  bool face = false;
};

struct CuttingData {
  std::vector<CutNumbers> cuts;      // in run order
  std::vector<Diagnostic> warnings;  // W330-W336 on their blocks, in run order
  std::vector<Diagnostic> notes;     // I330 (material not known), I331 (no material named)
  bool stoppedByAlarm = false;
  // Per stock column, the cut (index into `cuts`) that last reached its outside / its bore's
  // surface; -1 none. Filled unless warningsOnly.
  std::vector<int> lastOutside, lastInside;
  // The cuts of one block (file, line), merged: the largest of each number (the first cut's
  // block fields); nullopt when the line cuts nothing.
  std::optional<CutNumbers> ofLine(int file, int line) const;
};

CuttingData measureCuts(const machine::Timeline& timeline, const CutSetup& setup, const CuttingDataOptions& options);

// The check's cutting-data warnings (issue 39 item 1) from the run the check records (the tool
// inference's record, machine::recordRun): measured up to the record's first alarm, with the tools
// the job chose, warnings only (CuttingDataOptions::warningsOnly). The record follows the programmed
// path: under G41/G42 the depths are the uncompensated path's (within the nose radius).
std::vector<Diagnostic> checkCuttingData(const machine::Timeline& record, const io::JobHeader& header,
                                         const machine::MachineSetup& setup, DisplayUnits units,
                                         std::vector<FinishMark> finishMarks = {});
// The moves of a record before its first alarm's block (all without an alarm).
std::size_t movesBeforeAlarm(const machine::Timeline& record);

// The Ra each surface of the finished part got, from a measured run (`data` with lastOutside /
// lastInside) and the stock it left (or a crop of it: the same Z): the feature's surface, when a
// cut with a nose radius left it (threads, and surfaces a sharp tool or a drill left, have none).
std::optional<SurfaceFinish> surfaceFinishOf(const CuttingData& data, const Stock& stock, const PartFeature& f);
// The same for every feature of partFeatures(stock), outside then inside.
std::vector<SurfaceFinish> surfaceFinishes(const CuttingData& data, const Stock& stock);

// measureCuts of a job's run with the shipped materials and library (what the reports, the Part
// panel and class grading measure): the tools, the machine's limits and the header's material.
CuttingData measureRun(const machine::Timeline& timeline, const io::JobHeader& header,
                       const machine::MachineSetup& setup, DisplayUnits units,
                       std::vector<FinishMark> finishMarks = {});

// The per-block CSV of `klueng-cli simulate --cutting-data` (units in the column names).
std::string formatCuttingDataCsv(const CuttingData& data, DisplayUnits units);

// Theoretical roughness of a feed f (mm/rev) with nose radius r (mm), um: Rz = f^2/(8r), Ra ~ f^2/(32r).
double roughnessRz(double feed, double noseRadius);
double roughnessRa(double feed, double noseRadius);
// Kienzle: kc = kc1.1 * h^-mc, N/mm^2.
double specificCuttingForce(double kc11, double mc, double h);

}  // namespace klueng::core::cut
