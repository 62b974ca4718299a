// A part design's outside and bore as contour moves. Both are built by one
// routine in a mirrored frame where diameters grow toward the chuck (the bore's
// are negated), so every rule — no undercut, edge breaks that fit, arcs that
// meet their neighbours — is written once.
#include "contour.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::core::design::detail {

namespace {

constexpr double kEps = 1e-9;
constexpr double kFaceLead = 1.0;  // mm a side the finishing pass starts below the first corner, on the face

struct SideCodes {
  const char* undercut;
  const char* edgeTooLarge;
};

// The arc of `s` from (z0, r0) to (z1, r1), radius coordinates in the mirrored
// frame (outward = +r); false with the reason when it cannot be turned.
bool arcMove(const OutsideStep& s, const std::string& n, double side, double z0, double r0, double z1, double r1,
             ContourMove& out, std::vector<Diagnostic>& why) {
  const double R = s.radius;
  const double dz = z1 - z0, dr = r1 - r0, chord = std::hypot(dz, dr);
  if (R <= 0.0 || chord > 2.0 * R + 1e-6) {
    why.push_back(problem(codes::kArcCannotJoin, {n, num(R), num(side * 2.0 * r0), num(side * 2.0 * r1),
                                                  num(std::round(chord * 1000.0) / 1000.0)}));
    return false;
  }
  const double tz = dz / chord, tr = dr / chord;
  const double outZ = tr, outR = -tz;  // the chord's normal away from the axis (going left, -tz > 0)
  const double h = std::sqrt(std::max(0.0, R * R - chord * chord / 4.0));
  const double mz = (z0 + z1) / 2.0, mr = (r0 + r1) / 2.0;
  const double sign = s.concave ? 1.0 : -1.0;  // a bulging arc has its centre inside the part
  out = {2.0 * r1, z1, true, s.concave, R, mz + sign * h * outZ, mr + sign * h * outR};
  // Rising all the way toward the chuck: the circle's top (bulging) or bottom
  // (hollow) may only be at the arc's end.
  const double cz = out.centreZ;
  const bool turns = s.concave ? (cz >= z1 - 1e-6 && cz < z0 - 1e-6) : (cz > z1 + 1e-6 && cz <= z0 + 1e-6);
  if (turns) {
    const double turnR = s.concave ? out.centreR - R : out.centreR + R;
    why.push_back(problem(codes::kArcNeedsUndercut, {n, num(R), num(std::round(side * 2000.0 * turnR) / 1000.0)}));
    return false;
  }
  return true;
}

Contour build(const std::vector<OutsideStep>& steps, double side, double before, bool slopedFromAxis,
              const SideCodes& codes, std::vector<Diagnostic>& why) {
  Contour c;
  c.side = side;
  const double faceFrom = before;  // the face's far edge (the axis, or the bar's outside for a bore)
  double z = 0.0;  // `before`: the mirrored Ø at the current step's right (outside: 0, the axis at the face)
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const OutsideStep& s = steps[k];
    const std::string n = std::to_string(k + 1);
    const double d = side * s.diameter;
    const bool sloped = s.kind != StepKind::Cylinder && (k > 0 || slopedFromAxis);
    if (d < before - kEps) why.push_back(problem(codes.undercut, {n, num(s.diameter), num(side * before)}));
    const double rise = (d - before) / 2.0;  // the face's height
    const double room = std::min(s.length, sloped ? 0.0 : rise);
    if (s.edge != EdgeBreak::None && s.edgeSize > room + kEps)
      why.push_back(problem(codes.edgeTooLarge, {n, num(s.edgeSize), num(room)}));
    if (sloped) {
      if (k == 0) c.x0 = before;
      ContourMove m{d, z - s.length};
      if (s.kind == StepKind::Arc && !arcMove(s, n, side, z, before / 2.0, z - s.length, d / 2.0, m, why))
        m = {d, z - s.length};
      m.note = s.kind == StepKind::Arc ? MoveNote::Arc : MoveNote::Taper;
      m.noteSize = s.radius;
      c.moves.push_back(m);
      z -= s.length;
      before = d;
      continue;
    }
    const double e = s.edge == EdgeBreak::None ? 0.0 : s.edgeSize;
    const double foot = d - 2.0 * e;  // where the face meets the edge break
    if (k == 0)
      c.x0 = foot;
    else if (foot > before + kEps)
      c.moves.push_back({foot, z, false, false, 0.0, 0.0, 0.0, MoveNote::Face});
    if (s.edge == EdgeBreak::Chamfer) c.moves.push_back({d, z - e, false, false, 0.0, 0.0, 0.0, MoveNote::Chamfer, e});
    if (s.edge == EdgeBreak::Round)
      c.moves.push_back({d, z - e, true, false, e, z - e, foot / 2.0, MoveNote::Round, e});
    z -= s.length;
    c.moves.push_back({d, z, false, false, 0.0, 0.0, 0.0, MoveNote::Cylinder, s.length});
    before = d;
  }
  // The finishing pass comes up the face to the first corner rather than along
  // Z onto it: turning away from the nose there, it goes round the corner and
  // leaves it sharp (turning toward the nose it would leave a sliver under it).
  if (!steps.empty() && (steps[0].kind == StepKind::Cylinder || !slopedFromAxis) &&
      c.x0 - faceFrom >= 2.0 * kFaceLead) {
    c.moves.insert(c.moves.begin(), ContourMove{c.x0, 0.0, false, false, 0.0, 0.0, 0.0, MoveNote::Face});
    c.x0 -= 2.0 * kFaceLead;
  }
  // Back from the mirrored frame.
  c.x0 *= side;
  for (ContourMove& m : c.moves) {
    m.x *= side;
    m.centreR *= side;
    if (side < 0.0) m.clockwise = !m.clockwise;
  }
  return c;
}

}  // namespace

double Contour::smallestX() const {
  double v = x0;
  for (const ContourMove& m : moves) v = std::min(v, m.x);
  return v;
}

double Contour::largestX() const {
  double v = x0;
  for (const ContourMove& m : moves) v = std::max(v, m.x);
  return v;
}

Contour outsideContour(const PartDesign& part, std::vector<Diagnostic>& why) {
  return build(part.outside, 1.0, 0.0, true, {codes::kPartUndercut, codes::kPartEdgeTooLarge}, why);
}

Contour boreContour(const PartDesign& part, std::vector<Diagnostic>& why) {
  return build(part.inside, -1.0, -part.stockDiameter, false, {codes::kBoreUndercut, codes::kBoreEdgeTooLarge}, why);
}

double zAtDiameter(const Contour& contour, double d) {
  const double side = contour.side, target = side * d;
  double px = side * contour.x0, pz = 0.0;
  for (const ContourMove& m : contour.moves) {
    const double mx = side * m.x;
    if (mx >= target - kEps && px < target + kEps) {
      if (m.arc) {
        const double cr = side * m.centreR, dr = target / 2.0 - cr;
        const double h = std::sqrt(std::max(0.0, m.radius * m.radius - dr * dr));
        // The root on this arc's span, the one nearer its start.
        for (const double zc : {m.centreZ + h, m.centreZ - h})
          if (zc <= pz + 1e-6 && zc >= m.z - 1e-6) return zc;
        return m.z;
      }
      if (std::abs(mx - px) < 1e-12) return pz;
      return pz + (m.z - pz) * (target - px) / (mx - px);
    }
    px = mx;
    pz = m.z;
  }
  return pz;
}

std::string num(double v) {
  if (std::abs(v - std::round(v)) < 1e-9) return fmt::format("{}.", static_cast<long long>(std::llround(v)));
  std::string s = fmt::format("{:.3f}", v);
  while (s.back() == '0') s.pop_back();
  return s;
}

std::string plain(double v) {
  std::string s = num(std::abs(v) < 5e-4 ? 0.0 : v);
  if (s.back() == '.') s.pop_back();
  return s;
}

Diagnostic problem(const char* code, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.code = code;
  d.args = std::move(args);
  return d;
}

std::string commentText(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    if (c == '(')
      c = '[';
    else if (c == ')')
      c = ']';
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      c = ' ';
  }
  return out;
}

void Writer::block(const std::string& words, const std::string& comment) {
  // Each blank-separated G word, renumbered for the machine's G-code system.
  std::string renumbered;
  for (std::size_t at = 0; at < words.size();) {
    std::size_t end = words.find(' ', at);
    if (end == std::string::npos) end = words.size();
    const std::string_view word(words.data() + at, end - at);
    const bool gCode =
        word.size() > 1 && word.front() == 'G' && word.find_first_not_of("0123456789", 1) == std::string_view::npos;
    const int inA = gCode ? std::stoi(std::string(word.substr(1))) : -1;
    const int inSystem = gCode ? gcode::numberInSystem('G', inA, machine_) : -1;
    if (gCode && inSystem >= 0 && inSystem != inA)
      renumbered += fmt::format("G{:02}", inSystem);
    else
      renumbered += word;
    if (end < words.size()) renumbered += ' ';
    at = end + 1;
  }
  std::string line = numbered_ ? fmt::format("N{} {}", n_, renumbered) : renumbered;
  n_ += step_;
  if (!comment.empty()) line += " (" + commentText(comment) + ")";
  text_ += line + "\n";
}

namespace {

// The drawing's words for a contour move: "chamfer C3", "D30, 20 long".
std::string noteOf(const ContourMove& m, const Words& t) {
  const auto say = [&](const char* en, const char* th, auto... args) {
    return fmt::format(fmt::runtime(t.pick(en, th)), args...);
  };
  const std::string d = plain(std::abs(m.x));
  switch (m.note) {
    case MoveNote::Face: return say("face to D{}", "หน้าตัดถึง D{}", d);
    case MoveNote::Chamfer: return say("chamfer C{}", "ลบมุม C{}", plain(m.noteSize));
    case MoveNote::Round: return say("round R{}", "มุมโค้ง R{}", plain(m.noteSize));
    case MoveNote::Cylinder: return say("D{}, {} long", "D{} ยาว {}", d, plain(m.noteSize));
    case MoveNote::Taper: return say("taper to D{}", "เรียวถึง D{}", d);
    case MoveNote::Arc: return say("arc R{} to D{}", "ส่วนโค้ง R{} ถึง D{}", plain(m.noteSize), d);
    case MoveNote::None: break;
  }
  return {};
}

}  // namespace

void contourBlocks(Writer& w, const Contour& contour, double exitX, const Words& t) {
  w.block(fmt::format("G01 Z0. F{}", num(kFinishFeed)), t.pick("finishing feed", "อัตราป้อนกลึงละเอียด"));
  for (const ContourMove& m : contour.moves) {
    if (m.arc)
      w.block(fmt::format("{} X{} Z{} R{}", m.clockwise ? "G02" : "G03", num(m.x), num(m.z), num(m.radius)),
              noteOf(m, t));
    else
      w.block(fmt::format("G01 X{} Z{}", num(m.x), num(m.z)), noteOf(m, t));
  }
  w.block(fmt::format("G01 X{}", num(exitX)),
          contour.side > 0 ? t.pick("out over the bar", "ถอยพ้นผิวชิ้นงานดิบ") : t.pick("down into the hole", "ลงมาในรู"));
}

}  // namespace klueng::core::design::detail

namespace klueng::core::design {

namespace {

// A contour's polyline, arcs in chords of at most 5°.
std::vector<Vec2> polylineOf(const detail::Contour& c) {
  std::vector<Vec2> out{Vec2(0.0, c.x0 / 2.0)};
  for (const detail::ContourMove& m : c.moves) {
    const Vec2 to(m.z, m.x / 2.0);
    if (m.arc) {
      const Vec2 centre(m.centreZ, m.centreR), from = out.back();
      double a0 = std::atan2(from.y() - centre.y(), from.x() - centre.x());
      double a1 = std::atan2(to.y() - centre.y(), to.x() - centre.x());
      if (m.clockwise && a1 > a0) a1 -= 2.0 * M_PI;
      if (!m.clockwise && a1 < a0) a1 += 2.0 * M_PI;
      const int n = std::max(2, static_cast<int>(std::ceil(std::abs(a1 - a0) / (5.0 * M_PI / 180.0))));
      for (int k = 1; k < n; ++k) {
        const double a = a0 + (a1 - a0) * k / n;
        out.push_back(centre + m.radius * Vec2(std::cos(a), std::sin(a)));
      }
    }
    out.push_back(to);
  }
  return out;
}

}  // namespace

PartOutline partOutline(const PartDesign& part) {
  std::vector<Diagnostic> ignored;
  PartOutline o;
  o.outside = polylineOf(detail::outsideContour(part, ignored));
  if (!part.inside.empty()) o.bore = polylineOf(detail::boreContour(part, ignored));
  // Grooves: notches cut into the outside where they lie on a level stretch.
  for (const Groove& g : part.grooves) {
    const double zr = g.z, zl = g.z - g.width, r = g.diameter / 2.0;
    for (std::size_t k = 1; k < o.outside.size(); ++k) {
      const Vec2 a = o.outside[k - 1], b = o.outside[k];
      if (std::abs(a.y() - b.y()) > 1e-9 || a.x() < zr - 1e-9 || b.x() > zl + 1e-9) continue;
      o.outside.insert(o.outside.begin() + static_cast<long>(k),
                       {Vec2(zr, a.y()), Vec2(zr, r), Vec2(zl, r), Vec2(zl, a.y())});
      break;
    }
  }
  for (const Thread& t : part.threads)
    if (const OutsideStep* s = cylinderUnder(part, t.z, t.z - t.length)) {
      const double major = s->diameter / 2.0;
      o.threads.push_back({t.z, t.z - t.length, major, major - kIsoThreadHeight * t.pitch, t.pitch});
    }
  return o;
}

}  // namespace klueng::core::design
