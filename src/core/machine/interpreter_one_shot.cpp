// Group 00 one-shot codes: G04 dwell, G27/G28/G29/G30 reference point,
// G50 coordinate setting, G53 machine coordinates. G28/G30/G53 may share their
// block with G00/G01 where the profile allows it (the motion G becomes modal).
#include "machine/interpreter_impl.h"
#include "klueng/core/diagnostic_codes.h"

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

bool Interpreter::oneShot(const CodeWord& c) {
  const Word* w = c.word;
  switch (c.info->action) {
    case CodeAction::Dwell: return dwell(w);
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
