// The profile of G70-G73 and the roughing and pecking machinery shared by
// the Fanuc and Haas forms (see cycles_internal.h).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "machine/cycles_internal.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine::cycles::detail {

std::optional<CycleAlarm> readProfile(const CycleInput& in, const Block& cycle, bool withFeed, Profile& out) {
  if (in.readProfile) return (*in.readProfile)(cycle, in.gWord, withFeed, out);
  const Word* pw = cycle.find('P');
  return alarmAt(codes::kNoProfileBlock, pw, cycle,
                 {in.gWord ? "G" + in.gWord->number : "G7x", "P", pw ? pw->number.str() : ""});
}

void movesOnly(Profile& p) {
  std::vector<Step> moves;
  std::vector<int> blocks;
  for (std::size_t i = 0; i < p.moves.size(); ++i)
    if (p.moves[i].kind != StepKind::Compensation) {
      moves.push_back(p.moves[i]);
      blocks.push_back(p.blockOf[i]);
    }
  p.moves = std::move(moves);
  p.blockOf = std::move(blocks);
}

namespace {

// ---- G71 / G72 stock removal (in the frame where passes run along the first coordinate) --

// Points along a piece, for the monotony check of arcs.
std::vector<Vec2> samples(const Segment& s) {
  std::vector<Vec2> pts;
  const int n = s.isArc() ? 32 : 1;
  for (int i = 0; i <= n; ++i) pts.push_back(s.pointAt(static_cast<double>(i) / n));
  return pts;
}

// Where the depth line b = level, travelled along the pass direction, first
// meets the contour (a of the crossing); nullopt when the contour never reaches it.
std::optional<double> crossing(const std::vector<Step>& contour, double level, double sb) {
  for (const Step& s : contour) {
    const double b0 = s.path.start.y(), b1 = s.path.end.y();
    if ((level - b0) * sb < -kEps || (b1 - level) * sb < -kEps) continue;
    if (!s.path.isArc()) {
      if (std::abs(b1 - b0) < kEps) return s.path.start.x();
      const double t = (level - b0) / (b1 - b0);
      return s.path.start.x() + t * (s.path.end.x() - s.path.start.x());
    }
    // Arc: the point of the circle at b = level that lies on the swept part,
    // nearest to the arc's start along it.
    const Segment& a = s.path;
    const double r = a.radius();
    const double db = level - a.centre.y();
    if (std::abs(db) > r + kEps) continue;
    const double da = std::sqrt(std::max(0.0, r * r - db * db));
    const Vec2 rel0 = a.start - a.centre;
    const double phi0 = std::atan2(rel0.y(), rel0.x());
    double best = -1.0, bestA = 0.0;
    for (const double cand : {a.centre.x() - da, a.centre.x() + da}) {
      const double phi = std::atan2(db, cand - a.centre.x());
      double u = (a.ccw ? 1.0 : -1.0) * (phi - phi0);
      u = std::fmod(u, 2.0 * std::numbers::pi);
      if (u < 0) u += 2.0 * std::numbers::pi;
      if (u <= a.sweep() + 1e-9 && (best < 0 || u < best)) {
        best = u;
        bestA = cand;
      }
    }
    if (best >= 0) return bestA;
  }
  return std::nullopt;
}

}  // namespace

std::optional<CycleAlarm> stockRemoval(const CycleInput& in, Profile& profile, double depth, double retract,
                                       const Vec2& allowance, bool swap, std::vector<Step>& out,
                                       const Vec2& roughAllowance, bool firstMayMoveAlong) {
  const std::string g = in.gWord ? "G" + in.gWord->number : "G71";
  movesOnly(profile);
  std::vector<Step> moves = profile.moves;
  Vec2 start = in.start;
  Vec2 shift = allowance;
  Vec2 roughShift = allowance + roughAllowance;  // where the passes stop (Haas I/K)
  if (swap) {
    swapAll(moves);
    start = swapped(start);
    shift = swapped(shift);
    roughShift = swapped(roughShift);
  }
  // Type I: the first profile block moves only across the passes (X for G71).
  // Type II: it names both axes (Fanuc 0i-TF: "W0" will do), and pockets are allowed.
  const Step& first = moves.front();
  const Block& nsBlock = in.program->blocks[static_cast<std::size_t>(profile.blockOf.front())];
  const bool typeII = (nsBlock.has('X') || nsBlock.has('U')) && (nsBlock.has('Z') || nsBlock.has('W'));
  if (!firstMayMoveAlong && !typeII && std::abs(first.path.end.x() - first.path.start.x()) > kEps)
    return alarmAt(codes::kProfileFirstBlockAxis, nsBlock.words.empty() ? nullptr : &nsBlock.words.front(), nsBlock,
                   {g, swap ? "Z" : "X"});
  const Vec2 aPrime = first.path.end;
  std::vector<Step> contour(moves.begin() + 1, moves.end());
  const double sb = sign(start.y() - aPrime.y());  // towards the stock
  // Pieces at the end of the profile that lie wholly at or beyond the start
  // point's level (`X1.6` back to the start's X, then a retract along Z) are
  // outside the stock: the passes run along the profile before them. Where the
  // machine allows such a tail (Haas) the roughing leaves it out and the last
  // pass travels it as written; elsewhere (Fanuc) it must be monotonic too.
  std::size_t cut = contour.size();
  if (sb != 0.0) {
    const auto outside = [&](const Step& s) {
      for (const Vec2& p : samples(s.path))
        if ((p.y() - start.y()) * sb < -1e-4) return false;
      return true;
    };
    while (cut > 1 && outside(contour[cut - 1])) --cut;
  }
  double sa = sign(contour[cut - 1].path.end.x() - aPrime.x());  // along the passes
  if (sa == 0.0) sa = sign(contour.back().path.end.x() - aPrime.x());
  if (!in.profile || !in.profile->cycles.profileTailBeyondStart) cut = contour.size();
  // The profile must move steadily away from A' in both axes (type II: along the passes).
  bool pockets = false;
  for (std::size_t i = 0; i < cut; ++i) {
    const auto pts = samples(contour[i].path);
    bool ok = sa != 0.0 && sb != 0.0;
    for (std::size_t j = 1; ok && j < pts.size(); ++j)
      ok = (pts[j].y() - pts[j - 1].y()) * sb >= -1e-4 && (pts[j].x() - pts[j - 1].x()) * sa >= -1e-4;
    if (!ok && typeII && sa != 0.0 && sb != 0.0 && movesOneWayAlong(contour[i].path, sa)) {
      pockets = true;
      continue;
    }
    if (!ok) {
      const Block& b = in.program->blocks[static_cast<std::size_t>(profile.blockOf[i + 1])];
      return alarmAt(codes::kProfileNotMonotonic, b.words.empty() ? nullptr : &b.words.front(), b,
                     {g, std::to_string(b.line)});
    }
  }
  std::vector<Step> shifted, roughed;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    Step t = contour[i];
    t.path = contour[i].path.translated(shift);
    shifted.push_back(t);
    if (i >= cut) continue;
    t.path = contour[i].path.translated(roughShift);
    roughed.push_back(t);
  }
  const Vec2 aShift = aPrime + shift;
  const Vec2 aRough = aPrime + roughShift;
  if (std::abs(start.y() - aShift.y()) / depth > kMaxPasses) {
    const std::string passes = fmt::format("{:.0f}", std::ceil(std::abs(start.y() - aShift.y()) / depth));
    return CycleAlarm{codes::kTooManyPasses, in.gWord ? in.gWord->range : SourceRange{}, {g, passes, num(depth)}};
  }
  const bool infeedRapid = first.kind == StepKind::Rapid;
  std::vector<Step> steps;
  Vec2 pos = start;
  if (pockets) {
    if (auto a = roughPockets(g, in.gWord ? in.gWord->range : SourceRange{}, start, roughed, depth, retract, sa, sb,
                              infeedRapid, steps, pos))
      return a;
    // The last pass starts as the profile does: from the start point.
    for (const Vec2& p : {Vec2(pos.x(), start.y()), start}) {
      if ((p - pos).norm() <= kEps) continue;
      steps.push_back(rapid(pos, p));
      pos = p;
    }
  }
  for (int k = 1; !pockets; ++k) {
    const double level = start.y() - sb * k * depth;
    if ((level - aRough.y()) * sb <= kEps) break;
    const Vec2 in0(start.x(), level);
    steps.push_back(infeedRapid ? rapid(pos, in0) : feedLine(pos, in0));
    const double aEnd = crossing(roughed, level, sb).value_or(roughed.back().path.end.x());
    pos = in0;
    if ((aEnd - start.x()) * sa > kEps) {
      const Vec2 cutEnd(aEnd, level);
      steps.push_back(feedLine(pos, cutEnd));
      pos = cutEnd;
    }
    // 45-degree retract by e, then back to the start along the passes.
    const Vec2 away(pos.x() - sa * retract, level + sb * retract);
    steps.push_back(rapid(pos, away));
    steps.push_back(rapid(away, Vec2(start.x(), away.y())));
    pos = Vec2(start.x(), away.y());
  }
  // The last pass follows the profile offset by the finishing allowance, cutting:
  // a G00 inside the shape (a step down to the bottom of a bore, `N210 G00 X22.`)
  // is cut at the feed as the rest of A'->B is (Fanuc's pre-finishing cut); only
  // the approach to A' keeps the first block's G00/G01, and a tail past the shape
  // (a Haas retract above the bar) stays as written.
  steps.push_back(infeedRapid ? rapid(pos, aShift) : feedLine(pos, aShift));
  for (std::size_t i = 0; i < shifted.size(); ++i) {
    Step s = shifted[i];
    if (i < cut && s.kind == StepKind::Rapid) s.kind = StepKind::Feed;
    steps.push_back(s);
  }
  steps.push_back(rapid(shifted.back().path.end, start));
  for (Step& s : steps) s.feed = 0.0, s.where = {};
  if (swap) swapAll(steps);
  out = std::move(steps);
  return std::nullopt;
}

// ---- G74 / G75 peck cycles (frame: pecks along the first coordinate) ------------

std::vector<Step> pecks(const Vec2& start, const Vec2& target, double peck, double shiftStep, double retract) {
  std::vector<Step> steps;
  const double sa = sign(target.x() - start.x());
  const double sb = sign(target.y() - start.y());
  const double depth = std::abs(target.x() - start.x());
  const double across = std::abs(target.y() - start.y());
  Vec2 pos = start;
  double b = start.y();
  for (;;) {
    if (std::abs(b - pos.y()) > kEps) {
      steps.push_back(rapid(pos, Vec2(pos.x(), b)));
      pos = Vec2(pos.x(), b);
    }
    if (sa != 0.0) {
      double done = 0.0;
      for (;;) {
        done = peck > kEps ? std::min(depth, done + peck) : depth;
        const Vec2 bottom(start.x() + sa * done, b);
        steps.push_back(feedLine(pos, bottom));
        pos = bottom;
        if (done >= depth - kEps) break;
        const Vec2 back(bottom.x() - sa * retract, b);
        steps.push_back(rapid(pos, back));
        pos = back;
      }
      steps.push_back(rapid(pos, Vec2(start.x(), b)));
      pos = Vec2(start.x(), b);
    }
    const double moved = std::abs(b - start.y());
    if (sb == 0.0 || moved >= across - kEps) break;
    b = shiftStep > kEps ? start.y() + sb * std::min(across, moved + shiftStep) : target.y();
  }
  if ((pos - start).norm() > kEps) steps.push_back(rapid(pos, start));
  return steps;
}

}  // namespace klueng::core::machine::cycles::detail
