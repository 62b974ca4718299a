// Chamfer, corner R and angle on G01 (Fanuc 0i-TF manual, "Chamfering and
// corner R" and "Direct drawing dimension programming"): what the block asks
// for. The corner itself is cut by the corner stage (corner_stage.cpp), which
// holds the G01 until the next block's move; `,A a` gives a G01 by its angle
// from the +Z axis (counter-clockwise) and one end coordinate.
#include <numbers>

#include "klueng/core/diagnostic_codes.h"
#include "machine/interpreter_impl.h"

namespace klueng::core::machine::detail {

// The controlled point after the stage has cut a corner (as the cut moves it).
bool Interpreter::cornerCut(const CornerStage::Cut& cut) {
  if (cut.restart) pos_ = *cut.restart;
  if (cut.pieceEnd) moved(*cut.pieceEnd);
  return cut.ok;
}

bool Interpreter::holdCorner(const Segment& path, const Word* where) {
  const Word* c = chamferWord();
  const Word* w = c ? c : cornerWord();
  CornerRequest request;
  request.kind = c ? 'C' : 'R';
  request.size = std::abs(w->value) * unit();
  request.where = w->range;
  request.text = w->comma ? "," + w->text() : w->text();
  MotionCall toCorner;
  toCorner.kind = MoveKind::Line;
  toCorner.path = path;
  fillCall(toCorner, where);
  if (!cornerCut(corners_->hold(toCorner, request))) return false;
  moved(path.end);  // the program goes on from the virtual corner
  return true;
}

bool Interpreter::feedMoveAfterCorner(MoveKind kind, const Segment& path, const Word* where) {
  if (!corners_->heldBefore(blockIndex_)) return feedMove(kind, path, where);
  MotionCall m;
  m.kind = kind;
  m.path = path;
  fillCall(m, where);
  if (!cornerCut(corners_->follow(m))) return false;
  moved(path.end);
  return true;
}

// ,A: the missing end coordinate of a G01 from its angle to the +Z axis.
bool Interpreter::angleTarget(Vec2& target) {
  const Word* a = commaWord('A');
  if (!a) return true;
  const double angle = a->value * std::numbers::pi / 180.0;
  const Vec2 dir(std::cos(angle), std::sin(angle));  // (z, x radius)
  const bool x = movesX(), z = movesZ();
  const auto unreachable = [&]() { return raise(codes::kAngleUnreachable, a, {"," + a->text()}); };
  if (x && !z) {
    if (std::abs(dir.y()) < 1e-9) return unreachable();
    const double t = (xOf(target) - xOf(pos_)) / dir.y();
    target = Vec2(zOf(pos_) + t * dir.x(), xOf(target));
  } else if (z && !x) {
    if (std::abs(dir.x()) < 1e-9) return unreachable();
    const double t = (zOf(target) - zOf(pos_)) / dir.x();
    target = Vec2(zOf(target), xOf(pos_) + t * dir.y());
  } else if (!x && !z) {
    return unreachable();
  }
  return true;
}

}  // namespace klueng::core::machine::detail
