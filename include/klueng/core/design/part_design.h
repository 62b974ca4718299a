#pragma once
// From drawing to program (issue 14): a turned part described as its outside
// steps from the right face toward the chuck, read from a JSON file
// (docs/parts.md), and the complete program that turns it, written in the
// chosen dialect — Fanuc 0i-TF two-block G71/G70, Haas one-block G71/G70, or
// plain G01 passes for the classic 1999 rules — with the spindle speed from a
// material × tool-material cutting-speed table (S = 1000·Vc / (π·D)) and every
// number explained in a comment.
//
//   const auto design = readPartDesign(text, "shaft.json");   // diagnostics name file, line, column
//   const auto program = generateProgram(*design.value, options);  // nullopt + why when it cannot be turned
//
// Outside cylinders, tapers and arcs, each with a chamfer or a round at its
// right-hand edge, grooves and threads on the cylinders; bore steps inside a
// tube, cut with the boring bar.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/cut/inspection.h"
#include "klueng/core/gcode/code_table.h"
#include "klueng/core/geometry.h"
#include "klueng/core/io/result.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

namespace klueng::core::design {

enum class StepKind { Cylinder, Taper, Arc };
enum class EdgeBreak { None, Chamfer, Round };

// One step of the outside (or of the bore), from its right end (nearer the
// face) leftward.
struct OutsideStep {
  StepKind kind = StepKind::Cylinder;
  double diameter = 0.0;             // mm: the cylinder's, or the taper's or arc's at its left end
  double length = 0.0;               // mm along Z
  EdgeBreak edge = EdgeBreak::None;  // at the step's right-hand corner (the one away from the axis outside)
  double edgeSize = 0.0;             // chamfer C (45°) or round R, mm
  double radius = 0.0;               // an arc's R
  bool concave = false;              // an arc hollowed into the part (G02 outside) rather than bulging out of it
  // The drawing's tolerances (issue 28): on a cylinder's or bore's Ø (± or an
  // ISO 286 class such as h7, H7), and on the step's length (±); none when empty.
  cut::Tolerance tolerance = {};
  cut::Tolerance lengthTolerance = {};
  double roughness = 0.0;  // Ra µm on the step's surface: the drawing's finish mark; 0 when none
};
using BoreStep = OutsideStep;  // inside: cylinders and tapers, getting no wider toward the chuck

// A groove cut into a cylinder step with the grooving tool (T04, 3 mm blade).
struct Groove {
  double z = 0.0;         // its right wall (Z <= 0)
  double width = 0.0;     // mm along Z, at least the blade's width
  double diameter = 0.0;  // at its bottom
};

// An outside ISO metric thread on a cylinder (major Ø = the cylinder's), cut
// with the 60° threading tool (T03): G76 on Fanuc and Haas, G32 passes classic.
struct Thread {
  double z = 0.0;       // its right end (Z <= 0)
  double length = 0.0;  // mm along Z
  double pitch = 0.0;   // mm
};

struct PartDesign {
  std::string name = "Part";
  std::string material = "steel";        // a row of the cutting-speed table
  std::string toolMaterial = "carbide";  // hss or carbide
  double stockDiameter = 0.0;            // mm
  double stockLength = 0.0;
  double stockBore = 0.0;  // mm; 0 = a solid bar, else a tube's hole
  std::vector<OutsideStep> outside;
  std::vector<BoreStep> inside;  // bored from the right face inward
  std::vector<Groove> grooves;
  std::vector<Thread> threads;
  bool partOff = false;          // cut the part off the bar at its left end (parting tool T07)
  std::string generalTolerance;  // ISO 2768-1 class (f, m, c, v) for the sizes without their own; empty: none
  double length() const;         // of the turned part (the steps)
};

// The largest part design (JSON) or drawing (DXF) read: a lathe part's half
// section is kilobytes; a 90 MB drawing took 16 s and 1.1 GB to refuse (issue 29).
inline constexpr std::size_t kMaxPartFileBytes = 16u * 1024u * 1024u;
// The largest size a design may give (the largest stock a program's header holds), and
// the longest name or material (they are written into the program's header).
inline constexpr double kMaxPartSize = 9999.999;
inline constexpr double kMaxStockDiameter = 2000.0;
inline constexpr double kMaxStockLength = 5000.0;
inline constexpr std::size_t kMaxPartTextChars = 200;
// A part design's or drawing's bytes: F101 no such file, F102 a folder or
// unreadable, F103 over kMaxPartFileBytes (a device such as /dev/zero stops there).
io::ReadResult<std::string> readPartFile(const std::string& path);

// JSON (docs/parts.md); F180-F182 diagnostics with the JSON's line and column.
io::ReadResult<PartDesign> readPartDesign(const std::string& text, const std::string& fileName);
// The same JSON back (readPartDesign(writePartDesign(p)) == p).
std::string writePartDesign(const PartDesign& part);

// The drawing's toleranced dimensions for inspection (cut/inspection.h): each
// cylinder's and bore's Ø with its tolerance, each step's length with its own;
// the ones without take the general tolerance (`general`, or the design's
// general_tolerance when empty) when there is one, else are left out.
std::vector<cut::DrawnDimension> drawnDimensions(const PartDesign& part, const std::string& general = {});

// The drawing's roughness marks (each step's `roughness`) for the cutting-data warning W332
// (cut/cutting_data.h): a step's Z range and diameters (a taper's or arc's from the step before).
std::vector<cut::FinishMark> finishMarks(const PartDesign& part);

// ISO metric external thread: radial height per mm of pitch.
inline constexpr double kIsoThreadHeight = 0.6134;

// The outside cylinder holding all of Z [zLeft, zRight] (clear of its right
// edge break when `clearOfEdge`), or nullptr: where a groove or thread sits.
const OutsideStep* cylinderUnder(const PartDesign& part, double zRight, double zLeft, bool clearOfEdge = false);

// The drawing's outline as polylines (z, radius) from the face (Z0) leftward:
// the outside with its grooves, and the bore (empty when solid); arcs in
// short chords. For previews; a part that cannot be turned is drawn as far as
// its steps go.
struct ThreadMark {
  double zRight = 0.0, zLeft = 0.0;
  double major = 0.0, minor = 0.0;  // radii
  double pitch = 0.0;
};
struct PartOutline {
  std::vector<Vec2> outside;
  std::vector<Vec2> bore;
  std::vector<ThreadMark> threads;  // those on a cylinder
};
PartOutline partOutline(const PartDesign& part);

// Cutting speed Vc, m/min, by material and tool material (the thesis's table).
struct CuttingSpeed {
  std::string material;
  double hss = 0.0;
  double carbide = 0.0;
};
// The shipped table (resources/parts/cutting_speeds.cfg), or `path`'s; "material | hss | carbide" lines.
io::ReadResult<std::vector<CuttingSpeed>> readCuttingSpeeds(const std::string& path = {});
// S = 1000 · Vc / (π · D), rpm.
double spindleRpm(double cuttingSpeed, double diameter);
// The table's row a job's material text names ("Aluminium 6061", "เหล็ก S45C"),
// English or Thai; empty when none does.
std::string cuttingSpeedRow(const std::string& material, const std::vector<CuttingSpeed>& table);

struct GenerateOptions {
  gcode::Dialect dialect = gcode::Dialect::Fanuc;
  Lang lang = Lang::En;              // the comments' language
  io::MachineConfig machine;         // its max_spindle_rpm clamps G50
  std::vector<CuttingSpeed> speeds;  // empty: the shipped table
};

struct GeneratedProgram {
  std::string text;           // a Klueng program file: 6-line job header, then the G-code
  double cuttingSpeed = 0.0;  // Vc used, m/min
  int spindleLimit = 0;       // G50 S
};

// The program, or nullopt with the reasons (D-codes, English/Thai) when the part
// cannot be turned this way: a step thinner than the one before it (an undercut
// the turning tool cannot reach), an edge break larger than its step, a part
// longer than the bar or wider than it, an unknown material, a groove narrower
// than the blade, off its cylinder or deeper than the part, an arc whose ends
// are further apart than its diameter, a bore the boring bar cannot reach or
// in a solid bar.
std::optional<GeneratedProgram> generateProgram(const PartDesign& part, const GenerateOptions& options,
                                                std::vector<Diagnostic>* why = nullptr);

}  // namespace klueng::core::design
