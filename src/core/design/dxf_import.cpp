// A part design from a DXF drawing's half section: pick the layer, scale to
// millimetres, find the axis, join the lines and arcs into one outline, walk
// its outside (and bore) from the right-hand face leftward, and read the walk
// as the design's steps.
#include "klueng/core/design/dxf_import.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <filesystem>
#include <set>

#include "dxf_drawing.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::design {

namespace {

using detail::DxfSegment;

constexpr double kJoin = 1e-3;  // mm: ends this close meet

Diagnostic fileProblem(const char* code, std::vector<std::string> args, Severity severity = Severity::Error) {
  Diagnostic d;
  d.severity = severity;
  d.code = code;
  d.args = std::move(args);
  return d;
}

// A size or place in a message: three decimals; a huge one in powers of ten (not 300 digits),
// and one no double holds as "1e308+" (issue 42 item 6: "Øinf").
std::string mm(double v) {
  if (!std::isfinite(v)) return v < 0.0 ? "-1e308+" : "1e308+";
  if (std::abs(v) >= 1e7) return fmt::format("{:.3e}", v);
  return fmt::format("{:.3f}", std::abs(v) < 5e-4 ? 0.0 : v);
}
double round3(double v) { return std::round(v * 1000.0) / 1000.0; }

struct Units {
  double factor;
  const char* name;
  const char* thai = "";
};

// $INSUNITS to millimetres; factor 0 when it is no length.
Units unitsOf(int insunits) {
  switch (insunits) {
    case 0: return {1.0, "millimetres", "มิลลิเมตร"};  // unitless: as drawn, checked by size below
    case 1: return {25.4, "inches", "นิ้ว"};
    case 2: return {304.8, "feet", "ฟุต"};
    case 4: return {1.0, "millimetres", "มิลลิเมตร"};
    case 5: return {10.0, "centimetres", "เซนติเมตร"};
    case 6: return {1000.0, "metres", "เมตร"};
    case 9: return {0.0254, "mils", "มิล"};
    case 13: return {0.001, "microns", "ไมครอน"};
    case 14: return {100.0, "decimetres", "เดซิเมตร"};
    default: return {0.0, ""};
  }
}

// One segment of the outline walked from a to b (an arc's sense follows the walk).
struct Walked {
  Vec2 a, b;  // (z, radius) of the part
  bool arc = false;
  double radius = 0.0;
  bool ccw = true;
};

// How far an arc bows out from its chord.
double sagitta(const DxfSegment& s) {
  const Vec2 u = s.a - s.centre, v = s.b - s.centre;
  double sweep = std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
  if (!s.ccw) sweep = -sweep;
  if (sweep < 0.0) sweep += 2.0 * M_PI;
  return s.radius * (1.0 - std::cos(sweep / 2.0));
}

class Importer {
 public:
  Importer(const std::string& fileName, const DxfImportOptions& options, io::ReadResult<PartDesign>& out)
      : file_(fileName), options_(options), out_(out) {}

  void run(const std::string& text) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) return fail(codes::kDxfEmpty, {file_});
    const detail::DxfDrawing drawing = detail::readDxfDrawing(text);
    if (!drawing.parsed) return fail(codes::kDxfNotDxf, {file_, drawing.why, drawing.whyThai});
    if (!pickLayer(drawing)) return;
    for (const detail::DxfOddEntity& e : drawing.odd)
      if (e.layer == layer_)
        return fail(codes::kDxfUnsupportedEntity, {file_, e.kind, e.layer, mm(e.at.x()), mm(e.at.y())});
    const Units units = unitsOf(drawing.insunits);
    if (units.factor == 0.0) return fail(codes::kDxfUnits, {file_, std::to_string(drawing.insunits)});
    scale_ = units.factor;
    units_ = units;
    if (scale_ != 1.0)
      out_.diagnostics.push_back(
          fileProblem(codes::kDxfInches, {file_, fmt::format("{}", scale_), units.name, units.thai}, Severity::Note));
    if (!collect(drawing)) return;
    std::vector<Walked> chain;
    if (!join(chain)) return;
    PartDesign part;
    part.name = std::filesystem::path(file_).stem().string();
    part.material = options_.material;
    double xLeft = 0.0;
    if (!walk(chain, true, part.outside, &part.grooves, xLeft)) return;
    double boreLeft = 0.0;
    if (hasBore_ && !walk(chain, false, part.inside, nullptr, boreLeft)) return;
    double widest = 0.0, narrowest = 1e300;
    for (const OutsideStep& s : part.outside) widest = std::max(widest, s.diameter);
    for (const BoreStep& s : part.inside) narrowest = std::min(narrowest, s.diameter);
    const double length = -xLeft;
    if (!std::isfinite(widest) || !std::isfinite(length) || widest < 1.0 || widest > 2000.0 || length > 5000.0)
      return fail(codes::kDxfSize, {file_, mm(widest), mm(length), units.name, units.thai});
    part.stockDiameter = std::ceil((widest + 2.0) / 5.0 - 1e-9) * 5.0;
    if (!part.inside.empty()) part.stockBore = std::max(0.0, std::floor((narrowest - 2.0) / 2.0 + 1e-9) * 2.0);
    part.stockLength = std::ceil((length + options_.chuckGrip + 5.0) / 5.0 - 1e-9) * 5.0;
    out_.value = std::move(part);
  }

 private:
  std::string file_;
  DxfImportOptions options_;
  io::ReadResult<PartDesign>& out_;
  std::string layer_;
  double scale_ = 1.0;
  Units units_{1.0, "millimetres", "มิลลิเมตร"};
  double axis_ = 0.0, right_ = 0.0;  // the drawing's Y of the axis, X of the face (mm)
  std::vector<DxfSegment> segs_;     // the outline's, in mm
  bool hasBore_ = false;

  void fail(const char* code, std::vector<std::string> args) {
    out_.diagnostics.push_back(fileProblem(code, std::move(args)));
  }
  // The drawing's own X Y of a part point (z, radius).
  std::string X(const Vec2& p) const { return mm((p.x() + right_) / scale_); }
  std::string Y(const Vec2& p) const { return mm((p.y() + axis_) / scale_); }

  bool pickLayer(const detail::DxfDrawing& d) {
    std::set<std::string> layers;
    for (const DxfSegment& s : d.segments)
      if (!s.centreLine) layers.insert(s.layer);
    std::string list;
    for (const std::string& l : layers) list += (list.empty() ? "" : ", ") + l;
    if (!options_.layer.empty()) {
      layer_ = options_.layer;
      if (!layers.count(layer_))
        return fail(codes::kDxfNothingOnLayer, {file_, layer_, list.empty() ? "-" : list}), false;
      return true;
    }
    if (layers.empty()) return fail(codes::kDxfNothingOnLayer, {file_, "0", "-"}), false;
    if (layers.size() > 1) return fail(codes::kDxfPickLayer, {file_, list}), false;
    layer_ = *layers.begin();
    return true;
  }

  bool collect(const detail::DxfDrawing& d) {
    bool axisFound = false;
    double lowest = 1e300;
    for (DxfSegment s : d.segments) {
      s.a *= scale_, s.b *= scale_, s.centre *= scale_, s.radius *= scale_;
      // Past what a double holds once in millimetres: refused as a drawing of the wrong units,
      // never joined or measured as inf (issue 42 item 6: "Øinf").
      if (!s.a.allFinite() || !s.b.allFinite() || !s.centre.allFinite() || !std::isfinite(s.radius)) {
        const double inf = std::numeric_limits<double>::infinity();
        return fail(codes::kDxfSize, {file_, mm(inf), mm(inf), units_.name, units_.thai}), false;
      }
      if (s.centreLine) {
        if (!s.arc && std::abs(s.a.y() - s.b.y()) < kJoin) axis_ = s.a.y(), axisFound = true;
        continue;
      }
      if (s.layer != layer_) continue;
      // An arc that bends less than the part's 0.001 mm rounding is the CAD's straight line.
      if (s.arc && sagitta(s) < 0.0005) s.arc = false;
      lowest = std::min({lowest, s.a.y(), s.b.y()});
      segs_.push_back(s);
    }
    if (!axisFound) axis_ = lowest;
    // The upper half only; a line drawn along the axis closes the section and is no edge.
    std::erase_if(segs_, [&](const DxfSegment& s) {
      const bool below = s.a.y() < axis_ - kJoin || s.b.y() < axis_ - kJoin;
      const bool onAxis = !s.arc && std::abs(s.a.y() - axis_) < kJoin && std::abs(s.b.y() - axis_) < kJoin;
      return below || onAxis;
    });
    if (segs_.empty()) return fail(codes::kDxfNothingOnLayer, {file_, layer_, layer_}), false;
    right_ = -1e300;
    for (const DxfSegment& s : segs_) right_ = std::max({right_, s.a.x(), s.b.x()});
    return true;
  }

  Vec2 part(const Vec2& drawn) const { return Vec2(drawn.x() - right_, drawn.y() - axis_); }

  // Join the segments end to end into one chain (axis to axis, or a closed loop).
  bool join(std::vector<Walked>& chain) {
    const std::size_t n = segs_.size();
    std::vector<Vec2> ends;
    for (const DxfSegment& s : segs_) ends.push_back(part(s.a)), ends.push_back(part(s.b));
    // Partners of each end: the other ends within kJoin (all of them first, so loose ends are known).
    // Sorted by X, each end only looks at the ends within kJoin of its X: big drawings stay fast.
    std::vector<std::vector<std::size_t>> meets(2 * n);
    std::vector<std::size_t> byX(2 * n);
    for (std::size_t i = 0; i < 2 * n; ++i) byX[i] = i;
    std::sort(byX.begin(), byX.end(), [&](std::size_t p, std::size_t q) { return ends[p].x() < ends[q].x(); });
    for (std::size_t k = 0; k < byX.size(); ++k)
      for (std::size_t m = k + 1; m < byX.size() && ends[byX[m]].x() - ends[byX[k]].x() <= kJoin; ++m) {
        const std::size_t i = byX[k], j = byX[m];
        if (j / 2 != i / 2 && (ends[i] - ends[j]).norm() <= kJoin) meets[i].push_back(j), meets[j].push_back(i);
      }
    for (std::size_t i = 0; i < 2 * n; ++i) {
      if (meets[i].size() > 1)
        return fail(codes::kDxfBranch, {file_, X(ends[i]), Y(ends[i]), std::to_string(meets[i].size() + 1)}), false;
      if (meets[i].empty() && ends[i].y() > kJoin) {
        // The gap to close: to the nearest other loose end (off the axis).
        double gap = 1e300;
        for (std::size_t j = 0; j < 2 * n; ++j)
          if (j / 2 != i / 2 && meets[j].empty() && ends[j].y() > kJoin)
            gap = std::min(gap, (ends[i] - ends[j]).norm());
        // How far the nearest other loose end is, in words: "- mm away" said nothing (issue 42 item 6).
        const bool alone = gap == 1e300;
        const std::string en = alone ? "no other loose line end is left to join it to"
                                     : "the nearest other end is " + mm(gap) + " mm away";
        const std::string th =
            alone ? "ไม่มีปลายเส้นอื่นที่ยังไม่ต่อเหลืออยู่ให้ต่อเข้าด้วยกัน" : "ปลายเส้นอื่นที่ใกล้ที่สุดห่างออกไป " + mm(gap) + " มม.";
        if (segs_[i / 2].arc)
          return fail(codes::kDxfArcApart, {file_, mm(segs_[i / 2].radius / scale_), X(ends[i]), Y(ends[i]),
                                            alone ? en : "the nearest line ends " + mm(gap) + " mm away",
                                            alone ? th : "ปลายเส้นที่ใกล้ที่สุดห่างออกไป " + mm(gap) + " มม."}),
                 false;
        return fail(codes::kDxfOpenContour, {file_, X(ends[i]), Y(ends[i]), en, th}), false;
      }
    }
    // Walk from an end on the axis if there is one, else round the loop.
    std::size_t start = 0;
    for (std::size_t i = 0; i < 2 * n; ++i)
      if (meets[i].empty()) {
        start = i;
        break;
      }
    std::vector<bool> used(n, false);
    std::size_t at = start;
    while (true) {
      const std::size_t seg = at / 2;
      if (used[seg]) break;
      used[seg] = true;
      const bool forward = at % 2 == 0;  // entered at a: walk a -> b
      const DxfSegment& s = segs_[seg];
      Walked w{part(forward ? s.a : s.b), part(forward ? s.b : s.a), s.arc, s.radius, forward ? s.ccw : !s.ccw};
      chain.push_back(w);
      const std::size_t exit = forward ? at + 1 : at - 1;
      if (meets[exit].empty()) break;
      at = meets[exit][0];
    }
    const std::size_t outlines = static_cast<std::size_t>(std::count(used.begin(), used.end(), false));
    if (outlines > 0) return fail(codes::kDxfSeveralOutlines, {file_, "2", layer_}), false;
    hasBore_ = true;
    for (const Walked& w : chain)
      for (const Vec2& p : {w.a, w.b})
        if (std::abs(p.x()) < kJoin && p.y() < kJoin) hasBore_ = false;  // the face reaches the axis
    return true;
  }

  // The outside (from the face's top) or the bore (from its bottom), walked leftward to the left end.
  bool walk(const std::vector<Walked>& chain, bool outside, std::vector<OutsideStep>& steps,
            std::vector<Groove>* grooves, double& leftEnd) {
    const std::size_t n = chain.size();
    const bool loop = (chain.front().a - chain.back().b).norm() <= kJoin;
    double left = 0.0;
    for (const Walked& w : chain) left = std::min({left, w.a.x(), w.b.x()});
    // The start: the face's top (outside) or bottom (bore), i.e. the point at Z0 with the largest / smallest radius.
    std::size_t first = 0;
    bool found = false;
    double best = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 p = chain[k].a;
      if (std::abs(p.x()) > kJoin) continue;
      if (!found || (outside ? p.y() > best : p.y() < best)) first = k, best = p.y(), found = true;
    }
    // Which way leaves the face: forward (chain[first] onward) unless that runs along Z0.
    const auto offFace = [&](const Walked& w) {
      return w.b.x() < -kJoin || (outside ? w.b.y() > w.a.y() : w.b.y() < w.a.y());
    };
    std::vector<Walked> path;
    if (found && offFace(chain[first])) {
      for (std::size_t k = first; k < n + (loop ? first : 0); ++k) path.push_back(chain[k % n]);
    } else {
      // Backward from the point chain[first].a: reverse the segments before it.
      const std::size_t end = found ? first : n;
      for (std::size_t m = 0; m < (loop ? n : end); ++m) {
        const Walked& w = chain[(end + n - 1 - m) % n];
        path.push_back({w.b, w.a, w.arc, w.radius, !w.ccw});
      }
    }
    // Cut where it reaches the left end (or the axis, in a bore).
    std::vector<Walked> run;
    for (const Walked& w : path) {
      if (std::abs(w.a.x() - left) <= kJoin && std::abs(w.b.x() - left) <= kJoin) break;  // the left face
      run.push_back(w);
      if (std::abs(w.b.x() - left) <= kJoin || (!outside && w.b.y() < kJoin)) break;
    }
    leftEnd = left;
    return toSteps(run, outside ? 1.0 : -1.0, steps, grooves);
  }

  bool toSteps(const std::vector<Walked>& run, double side, std::vector<OutsideStep>& steps,
               std::vector<Groove>* grooves) {
    const auto isFace = [](const Walked& w) { return !w.arc && std::abs(w.b.x() - w.a.x()) <= kJoin; };
    const auto isFlat = [](const Walked& w) { return !w.arc && std::abs(w.b.y() - w.a.y()) <= kJoin; };
    bool afterFace = true;
    EdgeBreak pending = EdgeBreak::None;
    double pendingSize = 0.0;
    for (std::size_t i = 0; i < run.size(); ++i) {
      const Walked& w = run[i];
      const double dz = w.b.x() - w.a.x(), rise = side * (w.b.y() - w.a.y());
      if (dz > kJoin) return fail(codes::kDxfTurnsBack, {file_, X(w.a), Y(w.a)}), false;
      const bool nextFlat = i + 1 < run.size() && isFlat(run[i + 1]);
      if (isFace(w)) {
        // Down, across and up again to the same diameter: a groove in the cylinder.
        if (grooves && rise < -kJoin && i + 2 < run.size() && nextFlat && isFace(run[i + 2]) &&
            std::abs(run[i + 2].b.y() - w.a.y()) <= kJoin && !steps.empty() &&
            steps.back().kind == StepKind::Cylinder) {
          const double width = w.a.x() - run[i + 1].b.x();
          if (round3(2.0 * run[i + 1].a.y()) <= 0.0 || round3(width) <= 0.0)
            return fail(codes::kDxfReachesAxis, {file_, X(run[i + 1].a), Y(run[i + 1].a)}), false;
          grooves->push_back({round3(w.a.x()), round3(width), round3(2.0 * run[i + 1].a.y())});
          steps.back().length = round3(steps.back().length + width);
          i += 2;
          afterFace = false;
          continue;
        }
        afterFace = true;
        continue;
      }
      const bool convex = w.ccw == (side > 0);
      const double len = -dz, d = round3(2.0 * std::abs(w.b.y()));
      if (round3(len) <= 0.0 && !isFace(w)) continue;  // a sliver drawn by the CAD's rounding
      if (d <= 0.0 || (grooves && std::abs(w.b.y()) <= kJoin))
        return fail(codes::kDxfReachesAxis, {file_, X(w.b), Y(w.b)}), false;
      if (w.arc && !(w.radius <= 10000.0))
        return fail(codes::kDxfArcTooFlat, {file_, mm(w.radius / scale_), X(w.b), Y(w.b)}), false;
      if (isFlat(w)) {
        // The cylinder beyond a groove goes on as the same step.
        if (!afterFace && !steps.empty() && steps.back().kind == StepKind::Cylinder &&
            std::abs(steps.back().diameter - d) <= 2.0 * kJoin && pending == EdgeBreak::None) {
          steps.back().length = round3(steps.back().length + len);
          continue;
        }
        OutsideStep s{StepKind::Cylinder, d, round3(len + pendingSize), pending, round3(pendingSize)};
        if (pending == EdgeBreak::None) s.edgeSize = 0.0;
        steps.push_back(s);
        pending = EdgeBreak::None;
        pendingSize = 0.0;
      } else if (!w.arc && afterFace && nextFlat && rise > 0.0 && std::abs(len - rise) <= kJoin && len <= 5.0 + kJoin) {
        pending = EdgeBreak::Chamfer;  // 45° between a face and a cylinder
        pendingSize = len;
      } else if (w.arc && afterFace && nextFlat && convex && std::abs(len - w.radius) <= kJoin &&
                 std::abs(rise - w.radius) <= kJoin) {
        pending = EdgeBreak::Round;  // a quarter round between a face and a cylinder
        pendingSize = w.radius;
      } else {
        if (w.arc && side < 0.0)
          return fail(codes::kDxfArcInBore, {file_, mm(w.radius / scale_), X(w.b), Y(w.b)}), false;
        OutsideStep s{w.arc ? StepKind::Arc : StepKind::Taper, d, round3(len)};
        if (w.arc) s.radius = round3(w.radius), s.concave = !convex;
        steps.push_back(s);
      }
      afterFace = false;
    }
    return true;
  }
};

}  // namespace

io::ReadResult<PartDesign> importDxf(const std::string& text, const std::string& fileName,
                                     const DxfImportOptions& options) {
  io::ReadResult<PartDesign> out;
  Importer(fileName, options, out).run(text);
  return out;
}

std::vector<std::string> dxfOutlineLayers(const std::string& text) {
  std::set<std::string> layers;
  for (const DxfSegment& s : detail::readDxfDrawing(text).segments)
    if (!s.centreLine) layers.insert(s.layer);
  return {layers.begin(), layers.end()};
}

}  // namespace klueng::core::design
