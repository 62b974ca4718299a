#include "klueng/core/machine/trace.h"

#include <fmt/format.h>

#include <cmath>
#include <iterator>

namespace klueng::core::machine {

namespace {
// Four decimals, never "-0.0000".
void put(std::string& out, double v) {
  if (std::abs(v) < 0.00005) v = 0.0;
  fmt::format_to(std::back_inserter(out), ",{:.4f}", v);
}
}  // namespace

std::string_view moveKindName(MoveKind kind) {
  switch (kind) {
    case MoveKind::Rapid: return "RAPID";
    case MoveKind::Line: return "LINE";
    case MoveKind::Arc: return "ARC";
    case MoveKind::Thread: return "THREAD";
    case MoveKind::Dwell: return "DWELL";
  }
  return "LINE";
}

std::string formatTraceCsv(const Timeline& timeline) {
  std::string out;
  out.reserve(96 * (timeline.moves.size() + 1));
  out += kTraceHeader;
  out += '\n';
  for (const Move& m : timeline.moves) {
    out += moveKindName(m.kind);
    fmt::format_to(std::back_inserter(out), ",{}", m.line);
    put(out, m.tStart);
    put(out, m.tEnd);
    put(out, diameterOf(m.path.start));
    put(out, zOf(m.path.start));
    put(out, diameterOf(m.path.end));
    put(out, zOf(m.path.end));
    const bool arc = m.path.isArc();
    const Vec2 rel = arc ? Vec2(m.path.centre - m.path.start) : Vec2(Vec2::Zero());
    put(out, xOf(rel));
    put(out, zOf(rel));
    out += ',';
    if (arc) out += m.path.ccw ? "CCW" : "CW";
    put(out, m.feed);
    put(out, m.rpm);
    fmt::format_to(std::back_inserter(out), ",{},", m.callLevel);
    if (m.program > 0) fmt::format_to(std::back_inserter(out), "O{:04d}", m.program);
    out += '\n';
  }
  return out;
}

}  // namespace klueng::core::machine
