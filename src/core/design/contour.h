#pragma once
// The generator's geometry and text helpers (internal to core/design): a part
// design's outside or bore as the finished contour's moves, and the block writer.
#include <string>
#include <vector>

#include "klueng/core/design/part_design.h"
#include "klueng/core/gcode/machine_profile.h"

namespace klueng::core::design::detail {

inline constexpr double kFinishFeed = 0.1;  // mm/rev, every finishing pass

// What a contour move draws, for its comment in the program.
enum class MoveNote { None, Face, Chamfer, Round, Cylinder, Taper, Arc };

// One move of the finished contour, to (x diameter, z).
struct ContourMove {
  double x = 0.0, z = 0.0;
  bool arc = false;
  bool clockwise = false;  // G02 (seen with X up, Z right); else G03
  double radius = 0.0;
  double centreZ = 0.0, centreR = 0.0;  // arc centre (z, radius)
  MoveNote note = MoveNote::None;
  double noteSize = 0.0;  // chamfer C, round R, a cylinder's length
};

// The contour from the face (x0 at Z0) leftward; inside, from the bore's mouth.
struct Contour {
  double side = 1.0;  // +1 outside (diameters grow toward the chuck), -1 the bore (they shrink)
  double x0 = 0.0;
  std::vector<ContourMove> moves;
  double smallestX() const;
  double largestX() const;
};

Contour outsideContour(const PartDesign& part, std::vector<Diagnostic>& why);
Contour boreContour(const PartDesign& part, std::vector<Diagnostic>& why);  // empty moves: no bore

// Z where the contour first reaches Ø d going left (outside: grows to d; the
// bore: shrinks to d), or the contour's end.
double zAtDiameter(const Contour& contour, double d);

// "30." for whole millimetres, "30.25" otherwise, as lathe programs are written.
std::string num(double v);
// Free text (a part's name, its material) made safe inside a program comment
// and on one header line: parentheses become brackets, control characters spaces.
std::string commentText(const std::string& text);

// "30", "22.5", "0": as messages and labels write sizes.
std::string plain(double v);
Diagnostic problem(const char* code, std::vector<std::string> args);

struct Words {
  bool thai;
  const char* pick(const char* en, const char* th) const { return thai ? th : en; }
};

class Writer {
 public:
  // Blocks numbered N{step}, N{2 step}, ... (10 as programs are written by hand).
  // G words are written as system A numbers them and come out as `machine`'s
  // G-code system numbers them (G50 -> G92, G32 -> G33 in system B), through the
  // code table's renamed rows.
  explicit Writer(bool numbered, int step = 10, gcode::Dialect machine = gcode::Dialect::Fanuc)
      : numbered_(numbered), step_(step), n_(step), machine_(machine) {}
  void block(const std::string& words, const std::string& comment = {});
  void raw(const std::string& line) { text_ += line + "\n"; }
  long long next() const { return n_; }
  int step() const { return step_; }
  // The last block's number (0 before the first).
  long long last() const { return n_ - step_; }
  const std::string& text() const { return text_; }

 private:
  bool numbered_;
  int step_;
  long long n_;
  gcode::Dialect machine_;
  std::string text_;
};

// The finishing contour's blocks: G01 Z0 at the finishing feed, the moves, out to exitX.
void contourBlocks(Writer& w, const Contour& contour, double exitX, const Words& t);

}  // namespace klueng::core::design::detail
