#pragma once
// The stock of a program that does not say (SPEC 2 ext; docs/program-file.md,
// "Stock for a plain file"): the interpreter runs without stock and the bar is
// read from what the program does to it.
//
//   Ø      the first approach: the tool's position at the start of the first
//          block that feeds, starting off the centre and in front of the face
//          (Z >= 0), that is not inside work (a facing or cycle start sits
//          just above the bar: the largest standard bar not above it; a first
//          cut that turns along -Z sits inside the bar: the smallest bar above it).
//          Bar sizes: metric programs the mm series of kMetricBarSizes, inch
//          programs (G20 at that block) steps of 1/8 in. The bar is never
//          smaller than a plain outside pass along -Z behind the face: the
//          smallest bar above the largest such pass (I159) when it is.
//   length the deepest Z reached while feeding + cutOffMargin + the chuck grip
//          (machine.cfg chuck_grip), so the cut never reaches the jaws; rounded
//          up to 5 mm (1/4 in).
//   bore   a pass along -Z inside the part that the tool leaves through the
//          hole — toward the centre behind the face, never back up to the
//          pass, then out along Z in front of the face below it (inside work;
//          a neck or taper on the outside is not) — before any drilling on
//          centre: tube stock, bore =
//          the smallest such pass diameter less 1 mm (1/16 in), rounded down to
//          a whole mm (1/16 in).
//
// Pure core, no Qt. Every number comes with the file line of the block that
// decided it, and stockNotes() turns that into notes (I150-I157) for the user.
#include <optional>
#include <string>
#include <span>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/program.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::machine {

// Round bar diameters (mm) a school's store carries (EN 10060 / ISO preferred sizes).
inline constexpr double kMetricBarSizes[] = {3,   4,   5,   6,   8,   10,  12,  14,  16,  18,  20,  22,  25,  28, 30,
                                             32,  35,  38,  40,  45,  50,  55,  60,  65,  70,  75,  80,  85,  90, 95,
                                             100, 110, 120, 125, 130, 140, 150, 160, 180, 200, 220, 250, 280, 300};

struct InferenceOptions {
  double cutOffMarginMm = 5.0;  // a 3 mm parting blade plus clearance, left of the deepest Z
};

struct StockInference {
  bool found = false;     // false: no approach outside the centre (keep the defaults)
  bool inch = false;      // sizes below are in inch (G20 at the deciding block)
  double diameter = 0.0;  // bar size, in the unit above
  double length = 0.0;
  double bore = 0.0;              // 0 = solid bar
  double approachDiameter = 0.0;  // the diameter that decided Ø, in the unit above
  // A plain outside pass larger than the approach's bar (a CAM lead-in): Ø is
  // the smallest bar above it and diameterLine its block; 0 = the approach decided.
  double largestTurnedDiameter = 0.0;
  int diameterLine = 0;     // file line of the approach block (the one before the first cut)
  bool cycleStart = false;  // that block is a canned cycle (G70-G76, G90, G92, G94)
  double deepestZ = 0.0;    // deepest Z reached while feeding, in the unit above
  int lengthLine = 0;
  double insidePassDiameter = 0.0;  // smallest inside pass before any drilling; 0 = none
  int boreLine = 0;
  // The program only works inside (every approach is within the bore): Ø is
  // one bar size above the largest diameter it cuts plus a wall.
  bool outsideFromInside = false;
  double largestCutDiameter = 0.0;  // in the unit above
  double cutOffMargin = 0.0;        // margin and chuck grip added to the length, in the unit above
  double chuckGrip = 0.0;
  // The bar the program's own comment names ("(MATERIAL: 2.25"OD X 1.5"ID X 2.32"L BRONZE TUBING)",
  // "(STOCK: DIA 50 X 100)"): it wins over the approach; 0 = no such comment.
  int commentLine = 0;
  std::string commentText;  // the comment, at most 60 characters, for the note

  // Writes the sizes into `h` (units, diameter, length, bore; stockSource = Inferred).
  void applyTo(io::JobHeader& h) const;
};

// A comment that names the bar (a word such as MATERIAL, STOCK, BAR, TUBING, BLANK with a diameter,
// and perhaps a bore and a length: `2.25"OD X 1.5"ID X 2.32"L`, `DIA 50 X 100`, `Ø32x60`): its sizes
// replace the inferred ones (in `r`'s unit), and `r.commentLine` says where. True when one did.
bool readStockComment(StockInference& r, std::string_view gcode, int firstLine);

// Runs `program` with `setup` and `options` (no stock: no cut alarms) and
// infers the stock. An alarm that stops the run leaves what ran before it.
StockInference inferStock(const gcode::Program& program, const MachineSetup& setup, const RunOptions& options = {},
                          const InferenceOptions& inference = {});
// The same from a run already recorded (the one the tools were read from: issue 26).
StockInference inferStock(const gcode::Program& program, const Timeline& recorded, const MachineSetup& setup,
                          const InferenceOptions& inference = {});

// Largest bar of the series not above d (smallest above d when `above`).
double metricBarSize(double diameterMm, bool above = false);
double inchBarSize(double diameterInch, bool above = false);

// The notes that tell the user where `stock` came from (stock.stockSource):
// I150 command line, I151 Job details, I152/I153/I158/I159 (+ I157 length, I154 bore)
// inferred — the deciding block quoted from `gcode` (the program's G-code,
// file line `firstLine` first) —, I155 default, I156 header. Severity Warning,
// range.line = the deciding block's line (0 when none); the CLI prints them
// as "note:", the GUI in its status bar.
std::vector<Diagnostic> stockNotes(const io::JobHeader& stock, const StockInference* inference, std::string_view gcode,
                                   int firstLine);

// inferStock on G-code text, parsed here and read as a Job reads it (lengths
// without a decimal point: point_reading.h, `chosenCalculatorInput` being the
// file's own choice). The editor's stock of a plain file as it is loaded.
StockInference inferStockFromText(std::string_view gcode, int firstLine, const MachineSetup& setup,
                                  const RunOptions& options, std::optional<bool> chosenCalculatorInput = std::nullopt);

}  // namespace klueng::core::machine
