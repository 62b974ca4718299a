// Group 00 one-shot codes: G04 dwell, G27/G28/G29/G30 reference point,
// G50 coordinate setting, G53 machine coordinates. G28/G30/G53 may share their
// block with G00/G01 where the profile allows it (the motion G becomes modal).
#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"
#include <algorithm>

#include <fmt/format.h>

namespace klueng::core::machine::detail {

Vec2 Interpreter::referencePoint() const {
  const auto& m = setup_.machine;
  return Vec2(m.referenceZ, m.referenceX / 2.0) + mach_.workShift;
}

// G04: P as the profile reads it (Fanuc ms; Haas seconds with a decimal
// point, else ms), X or U in seconds.
bool Interpreter::dwell(const Word* w) {
  if (modal_.feedMode == FeedMode::PerRev && mach_.spindle == SpindleDir::Stopped)
    return raise(codes::kFeedPerRevSpindleStopped, w, {"G04"});
  double seconds = 0.0;
  if (const Word* p = find('P'))
    seconds = cycles::dwellSeconds(*p, profile_.dwellP);
  else if (const Word* x = find('X'))
    seconds = x->value;
  else if (const Word* uw = find('U'))
    seconds = uw->value;
  DwellCall d;
  d.seconds = std::max(0.0, seconds);
  fillDwell(d);
  sink_->dwell(d);
  return true;
}

// G28 (G30: the second reference point, which is the reference point of
// machine.cfg while it has no second one): only the axes given move, to the
// intermediate point, then to the reference point. Without axis words the
// profile decides: nothing moves (Fanuc), or X and Z go straight home (Haas).
bool Interpreter::referenceReturn(const Word* w) {
  const Vec2 ref = referencePoint();
  if (!hasAxisWords()) {
    if (profile_.bareG28 != gcode::BareG28::HomeAllAxes) return true;
    g28X_ = xOf(pos_);
    g28Z_ = zOf(pos_);
    if (!rapidTo(ref, w)) return false;
    mach_.positionCheck = true;
    return true;
  }
  const Vec2 via = axisTarget();
  if (movesX()) g28X_ = xOf(via);
  if (movesZ()) g28Z_ = zOf(via);
  if (!rapidTo(via, w)) return false;
  Vec2 home = pos_;
  if (movesX()) home.y() = xOf(ref);
  if (movesZ()) home.x() = zOf(ref);
  if (!rapidTo(home, w)) return false;
  mach_.positionCheck = true;
  return true;
}

// G10 P_ X_ Z_ R_ Q_ (U W C: added): the program writes an offset (Fanuc 16i/18i-TB Operator's
// Manual B-63524EN/01 §14.5.2; 0i-TF the same). P 10000+n is geometry offset n, P n its wear;
// this simulator keeps one row per offset, so wear changes X and Z (and C the radius), geometry
// everything. X and Z move no tool here (the path is the program's); R and Q steer the nose
// compensation. As with #2001-#2400, the new values count from the next T word. P0 (the work
// shift) and L2/L20 (work offsets) name what Klueng's work coordinates, the program's own, do not have.
bool Interpreter::dataSetting(const Word* w) {
  const Word* l = find('L');
  const Word* p = find('P');
  const int table = l ? l->code() : 0;
  if (!p || table == 2 || table == 20 || table == 50) return true;
  int number = p->code();
  const bool geometry = number > 10000 || table == 10;
  if (number > 10000) number -= 10000;
  if (number == 0) return true;
  if (number < 1 || number > static_cast<int>(offsets_.offsets.size()))
    return raise(codes::kNoSuchOffset, p,
                 {wordText(*p), fmt::format("{:02d}", number), fmt::format("{:02d}", offsets_.offsets.size())});
  io::Offset& o = offsets_.offsets[static_cast<std::size_t>(number - 1)];
  const double u = unit();
  if (const Word* x = find('X')) o.x = x->value * u;
  if (const Word* z = find('Z')) o.z = z->value * u;
  if (const Word* du = find('U')) o.x += du->value * u;
  if (const Word* dw = find('W')) o.z += dw->value * u;
  if (const Word* c = find('C')) o.r = std::max(0.0, o.r + c->value * u);
  if (const Word* r = find('R'); r && geometry) o.r = std::max(0.0, r->value * u);
  if (const Word* q = find('Q')) o.tip = std::clamp(q->code(), 0, 9);
  (void)w;
  return true;
}

// G52 X_ Z_: a local coordinate system whose zero lies at X Z of the work coordinates (Fanuc T
// series, "Local coordinate system"; Haas the same); G52 X0 Z0 cancels it, an axis not given keeps
// its shift. Absolute words are read from the local zero (offsetVector); the tool does not move and
// the path stays in the work coordinates the stock is placed in.
bool Interpreter::localCoordinates(const Word* w) {
  (void)w;
  const double u = unit();
  if (const Word* x = find('X')) localShift_.y() = x->value * u / 2.0;
  if (const Word* z = find('Z')) localShift_.x() = z->value * u;
  return true;
}

bool Interpreter::oneShot(const CodeWord& c) {
  const Word* w = c.word;
  switch (c.info->action) {
    case CodeAction::Dwell: return dwell(w);
    case CodeAction::DataSetting: return dataSetting(w);
    case CodeAction::LocalCoordinates: return localCoordinates(w);
    case CodeAction::ReferenceCheck: {
      if (!hasAxisWords()) return true;
      if (!rapidTo(axisTarget(), w)) return false;
      const Vec2 ref = referencePoint();
      if (movesX() && std::abs(xOf(pos_) - xOf(ref)) > kPositionTolerance)
        return raise(codes::kReferenceCheckFailed, w, {"X", num(2.0 * xOf(pos_)), num(2.0 * xOf(ref))});
      if (movesZ() && std::abs(zOf(pos_) - zOf(ref)) > kPositionTolerance)
        return raise(codes::kReferenceCheckFailed, w, {"Z", num(zOf(pos_)), num(zOf(ref))});
      mach_.positionCheck = true;
      return true;
    }
    case CodeAction::ReferenceReturn:
    case CodeAction::SecondReferenceReturn:
      return referenceReturn(w);  // G30 P2..P4 would pick among several points; there is one
    case CodeAction::ReturnFromReference: {
      // From the reference point via the G28 intermediate point to the target.
      if (!hasAxisWords()) return true;
      const Vec2 target = axisTarget();
      Vec2 via = pos_;
      if (movesX() && g28X_) via.y() = *g28X_;
      if (movesZ() && g28Z_) via.x() = *g28Z_;
      if (!rapidTo(via, w)) return false;
      return rapidTo(target, w);
    }
    case CodeAction::CoordinateSet: {
      // Coordinate setting: the tool's controlled point now reads X Z.
      if (!hasAxisWords()) return true;  // G50 S alone: the clamp, handled with the S word
      const Vec2 declared = axisTarget();
      mach_.workShift += declared - pos_;
      pos_ = declared;
      sink_->setPosition(pos_);
      return true;
    }
    case CodeAction::MachineCoordinates: {
      // Rapid to a position in machine coordinates (offsets ignored). Machine
      // zero is the reference point, as on the real controls: Fanuc sets the
      // machine coordinate system so that the reference position reads
      // parameter 1240 (0 as shipped); Haas machine zero is home. So
      // `G53 X0` retracts X to home and `G00 G53 X0 Z-2.` stops 2 in short of
      // home in Z (docs/dialects.md).
      if (!hasAxisWords()) return true;
      Vec2 target = pos_;
      const double u = unit();
      const Vec2 zero = referencePoint();
      if (const Word* x = find('X')) target.y() = x->value * u / 2.0 + xOf(zero);
      if (const Word* z = find('Z')) target.x() = z->value * u + zOf(zero);
      return rapidTo(target, w);
    }
    default: return raise(codes::kNotSupportedYet, w, {wordText(*w)});
  }
}

}  // namespace klueng::core::machine::detail
