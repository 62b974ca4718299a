#include "klueng/core/machine/timeline.h"
#include "klueng/core/machine/program_units.h"

#include <algorithm>
#include <cmath>

namespace klueng::core::machine {

namespace {

// The ramps of a move, never longer together than the move itself.
struct Profile {
  double total, up, down, peak;  // peak: path fraction per second while cruising
};

Profile profileOf(const Move& m) {
  Profile p{m.tEnd - m.tStart, std::max(0.0, double(m.rampUp)), std::max(0.0, double(m.rampDown)), 0.0};
  if (p.up + p.down > p.total) {
    const double scale = p.up + p.down > 0.0 ? p.total / (p.up + p.down) : 0.0;
    p.up *= scale;
    p.down *= scale;
  }
  p.peak = 1.0 / (p.total - (p.up + p.down) / 2.0);
  return p;
}

}  // namespace

double Move::fractionAt(double t) const {
  const double tau = t - tStart;
  if (tEnd <= tStart) return tau >= 0.0 ? 1.0 : 0.0;
  if (tau <= 0.0) return 0.0;
  if (tau >= tEnd - tStart) return 1.0;
  if (rampUp <= 0.0f && rampDown <= 0.0f) return tau / (tEnd - tStart);
  const Profile p = profileOf(*this);
  if (tau < p.up) return p.peak * tau * tau / (2.0 * p.up);
  if (tau <= p.total - p.down) return p.peak * (tau - p.up / 2.0);
  const double rest = p.total - tau;
  return std::clamp(1.0 - p.peak * rest * rest / (2.0 * p.down), 0.0, 1.0);
}

double Move::timeAt(double fraction) const {
  const double s = std::clamp(fraction, 0.0, 1.0);
  if (tEnd <= tStart) return tEnd;
  if (rampUp <= 0.0f && rampDown <= 0.0f) return tStart + s * (tEnd - tStart);
  const Profile p = profileOf(*this);
  const double upPart = p.peak * p.up / 2.0, downPart = p.peak * p.down / 2.0;
  double tau;
  if (s <= upPart)
    tau = std::sqrt(2.0 * p.up * s / p.peak);
  else if (s <= 1.0 - downPart)
    tau = s / p.peak + p.up / 2.0;
  else
    tau = p.total - std::sqrt(2.0 * p.down * (1.0 - s) / p.peak);
  return tStart + std::clamp(tau, 0.0, p.total);
}

int Timeline::moveAt(double t) const {
  if (moves.empty() || t < moves.front().tStart) return -1;
  auto it = std::upper_bound(moves.begin(), moves.end(), t, [](double time, const Move& m) { return time < m.tEnd; });
  if (it == moves.end()) return static_cast<int>(moves.size()) - 1;
  return static_cast<int>(it - moves.begin());
}

RecordMove RecordMoveList::unpack(std::size_t i, const Point* start, const Point* centre) const {
  const Packed& p = moves_[i];
  RecordMove m;
  m.path.start = start ? Vec2(start->z, start->x) : Vec2(moves_[i - 1].endZ, moves_[i - 1].endX);
  m.path.end = Vec2(p.endZ, p.endX);
  m.path.centre = centre ? Vec2(centre->z, centre->x) : Vec2(0.0, 0.0);
  m.path.kind = (p.flags & kArc) ? Segment::Kind::Arc : Segment::Kind::Line;
  m.path.ccw = (p.flags & kCcw) != 0;
  m.line = p.line;
  m.blockIndex = p.blockIndex;
  m.file = p.file;
  m.tool = p.tool;
  m.offset = p.offset;
  m.kind = p.kind;
  m.spindle = p.spindle;
  return m;
}

RecordMove RecordMoveList::operator[](std::size_t i) const {
  const auto of = [i](const std::vector<Point>& list) {
    return &*std::lower_bound(list.begin(), list.end(), i, [](const Point& p, std::size_t k) { return p.move < k; });
  };
  const std::uint8_t flags = moves_[i].flags;
  return unpack(i, (flags & kOwnStart) ? of(starts_) : nullptr, (flags & kCentre) ? of(centres_) : nullptr);
}

RecordMove RecordMoveList::const_iterator::operator*() const {
  const std::uint8_t flags = list_->moves_[i_].flags;
  return list_->unpack(i_, (flags & kOwnStart) ? &list_->starts_[start_] : nullptr,
                       (flags & kCentre) ? &list_->centres_[centre_] : nullptr);
}

RecordMoveList::const_iterator& RecordMoveList::const_iterator::operator++() {
  const std::uint8_t flags = list_->moves_[i_].flags;
  if (flags & kOwnStart) ++start_;
  if (flags & kCentre) ++centre_;
  ++i_;
  return *this;
}

Move Timeline::recordedMove(std::size_t i) const {
  if (!moves.empty()) return moves[i];
  Move m = recordMoves[i].move();
  if (i < recordSpeeds.size()) {
    const MoveSpeeds& s = recordSpeeds[i];
    m.tStart = i > 0 ? recordSpeeds[i - 1].tEnd : 0.0;
    m.tEnd = s.tEnd;
    m.feed = s.feed;
    m.rpm = s.rpm;
    m.rpmEnd = s.rpmEnd;
    m.lead = s.lead;
    m.rampUp = s.rampUp;
    m.rampDown = s.rampDown;
  }
  return m;
}

std::vector<ToolTime> Timeline::timeByTool() const {
  std::vector<ToolTime> out;
  for (const Move& m : moves) {
    const double seconds = m.tEnd - m.tStart;
    if (seconds <= 0.0) continue;
    auto it = std::find_if(out.begin(), out.end(), [&m](const ToolTime& t) { return t.tool == m.tool; });
    if (it == out.end())
      out.push_back({m.tool, seconds});
    else
      it->seconds += seconds;
  }
  return out;
}

Vec2 Timeline::positionAt(double t) const {
  const int i = moveAt(t);
  if (i < 0) return moves.empty() ? Vec2(Vec2::Zero()) : moves.front().path.start;
  const Move& m = moves[static_cast<std::size_t>(i)];
  return m.path.pointAt(m.fractionAt(t));
}

Move mirroredAcrossCentre(const Move& in) {
  Move m = in;
  for (Vec2* p : {&m.path.start, &m.path.end, &m.path.centre, &m.noseCentre}) p->y() = -p->y();
  m.path.ccw = !m.path.ccw;
  return m;
}

CutSide sideOfCuts(const Timeline& timeline) {
  constexpr double kOffCentre = 0.005;  // radius, mm
  double below = 0.0, above = 0.0;
  timeline.forEachMove([&](const auto& m) {
    if (m.kind != MoveKind::Line && m.kind != MoveKind::Arc && m.kind != MoveKind::Thread) return;
    const double mid = (m.path.start.y() + m.path.end.y()) / 2.0;
    if (mid < -kOffCentre)
      below += m.path.length();
    else if (mid > kOffCentre)
      above += m.path.length();
  });
  if (below > above && below >= 1.0) return CutSide::Beyond;
  return above > below && above >= 1.0 ? CutSide::Front : CutSide::None;
}

DisplayUnits programUnits(const Timeline& timeline, gcode::InputUnits powerOn) {
  if (timeline.snapshots.empty()) return powerOn == gcode::InputUnits::Inch ? DisplayUnits::Inch : DisplayUnits::Mm;
  return timeline.snapshots.back().modal.units == Units::Inch ? DisplayUnits::Inch : DisplayUnits::Mm;
}

}  // namespace klueng::core::machine
