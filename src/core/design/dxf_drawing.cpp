// Reading a DXF drawing's lines, arcs and polylines with dxflib.
#include "dxf_drawing.h"

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace klueng::core::design::detail {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool looksLikeCentreLine(const std::string& name) {
  const std::string u = upper(name);
  return u.find("CENTER") != std::string::npos || u.find("CENTRE") != std::string::npos ||
         u.find("AXIS") != std::string::npos;
}

class Collector : public DL_CreationAdapter {
 public:
  DxfDrawing drawing;

  void addLayer(const DL_LayerData& data) override { layerLinetype_[data.name] = attributes.getLinetype(); }
  void addBlock(const DL_BlockData&) override { inBlock_ = true; }
  void endBlock() override { inBlock_ = false; }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") drawing.insunits = value;
  }

  void addLine(const DL_LineData& d) override {
    flushPolyline();
    if (inBlock_) return;
    add(mirror(Vec2(d.x1, d.y1)), mirror(Vec2(d.x2, d.y2)));
  }
  void addArc(const DL_ArcData& d) override {
    flushPolyline();
    if (inBlock_) return;
    const double a1 = d.angle1 * M_PI / 180.0, a2 = d.angle2 * M_PI / 180.0;
    const Vec2 c(d.cx, d.cy);
    DxfSegment s = segment(mirror(c + d.radius * Vec2(std::cos(a1), std::sin(a1))),
                           mirror(c + d.radius * Vec2(std::cos(a2), std::sin(a2))));
    s.arc = true;
    s.centre = mirror(c);
    s.radius = d.radius;
    s.ccw = !mirrored();  // an arc seen from below (extrusion -Z) turns the other way
    drawing.segments.push_back(s);
  }
  void addPolyline(const DL_PolylineData& d) override {
    flushPolyline();
    polylineOpen_ = !inBlock_;
    polylineClosed_ = (d.flags & 1) != 0;
    vertices_.clear();
  }
  void addVertex(const DL_VertexData& d) override {
    if (polylineOpen_) vertices_.push_back({mirror(Vec2(d.x, d.y)), mirrored() ? -d.bulge : d.bulge});
  }
  void endSequence() override { flushPolyline(); }
  void endEntity() override {
    // LWPOLYLINE has no SEQEND: its vertices end with the entity.
  }
  void addSpline(const DL_SplineData&) override { odd("spline"); }
  void addControlPoint(const DL_ControlPointData& d) override { oddAt(Vec2(d.x, d.y)); }
  void addFitPoint(const DL_FitPointData& d) override { oddAt(Vec2(d.x, d.y)); }
  void addEllipse(const DL_EllipseData& d) override { odd("ellipse", Vec2(d.cx, d.cy)); }
  void addCircle(const DL_CircleData& d) override { odd("circle", Vec2(d.cx, d.cy)); }
  void addInsert(const DL_InsertData& d) override { odd("block insert", Vec2(d.ipx, d.ipy)); }

  void finish() { flushPolyline(); }

 private:
  struct Vertex {
    Vec2 p;
    double bulge;
  };
  std::map<std::string, std::string> layerLinetype_;
  bool inBlock_ = false;
  bool polylineOpen_ = false, polylineClosed_ = false;
  std::vector<Vertex> vertices_;
  bool oddPending_ = false;

  bool mirrored() { return getExtrusion() && getExtrusion()->getDirection()[2] < 0.0; }
  Vec2 mirror(const Vec2& p) { return mirrored() ? Vec2(-p.x(), p.y()) : p; }

  DxfSegment segment(const Vec2& a, const Vec2& b) {
    DxfSegment s;
    s.a = a;
    s.b = b;
    s.layer = attributes.getLayer();
    std::string linetype = attributes.getLinetype();
    if (upper(linetype) == "BYLAYER" || linetype.empty()) linetype = layerLinetype_[s.layer];
    s.centreLine = looksLikeCentreLine(linetype) || looksLikeCentreLine(s.layer);
    return s;
  }
  void add(const Vec2& a, const Vec2& b) {
    if ((a - b).norm() > 1e-9) drawing.segments.push_back(segment(a, b));
  }
  // A polyline's segments; a bulge b is tan(quarter of the arc's angle), positive counter-clockwise.
  void flushPolyline() {
    if (!polylineOpen_) return;
    polylineOpen_ = false;
    const std::size_t n = vertices_.size();
    for (std::size_t k = 0; n > 1 && k < (polylineClosed_ ? n : n - 1); ++k) {
      const Vertex& v = vertices_[k];
      const Vec2 a = v.p, b = vertices_[(k + 1) % n].p;
      const double chord = (b - a).norm();
      if (chord < 1e-9) continue;
      if (std::abs(v.bulge) < 1e-9) {
        add(a, b);
        continue;
      }
      DxfSegment s = segment(a, b);
      s.arc = true;
      s.ccw = v.bulge > 0.0;
      // A bulge past a million is an arc of R over 10000 on any chord above 0.04 mm
      // (refused later as too large): held there, b*b cannot overflow.
      const double bulge = std::clamp(v.bulge, -1e6, 1e6);
      s.radius = std::abs(chord * (1.0 + bulge * bulge) / (4.0 * bulge));
      const Vec2 dir = (b - a) / chord, left(-dir.y(), dir.x());
      s.centre = (a + b) / 2.0 + left * (chord / 2.0) * (1.0 - bulge * bulge) / (2.0 * bulge);
      drawing.segments.push_back(s);
    }
    vertices_.clear();
  }
  void odd(const char* kind, const Vec2& at = Vec2(0.0, 0.0)) {
    flushPolyline();
    if (inBlock_) return;
    drawing.odd.push_back({kind, attributes.getLayer(), at});
    oddPending_ = at == Vec2(0.0, 0.0);
  }
  void oddAt(const Vec2& p) {
    if (oddPending_ && !drawing.odd.empty()) drawing.odd.back().at = p;
    oddPending_ = false;
  }
};

// Why dxflib cannot be given the text, in English and Thai; empty when it can.
// dxflib reads anything without complaint, except what is checked here first: a
// binary file; no SECTION (every DXF has one); a line of 1,024 bytes or more
// (its line buffer's stream fails without reaching its end, and it reads on
// forever); a real that is no finite double; and a count beyond the file. It allocates a polyline's vertices, a
// spline's knots and points and a leader's vertices at the count the file states
// (groups 90, 72-74, 76) before reading them: a corrupt count of 462 million
// asked for 14 GB. Each vertex takes at least two groups (four lines), so no
// true count exceeds the lines.
std::pair<std::string, std::string> unreadableByDxflib(const std::string& text) {
  if (text.find('\0') != std::string::npos || text.rfind("AutoCAD Binary DXF", 0) == 0)
    return {"it is a binary file (save the drawing as ASCII DXF)", "เป็นไฟล์ไบนารี (บันทึกแบบเป็น DXF แบบ ASCII)"};
  std::vector<std::string_view> lines;
  for (std::size_t at = 0; at <= text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + at, end - at);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front()))) line.remove_prefix(1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.remove_suffix(1);
    if (end - at >= 1023) {
      const std::string n = std::to_string(lines.size() + 1), length = std::to_string(end - at);
      return {
          "line " + n + " is " + length + " characters long (a DXF line holds one code or one value): it is corrupt",
          "บรรทัด " + n + " ยาว " + length + " ตัวอักษร (บรรทัดของ DXF มีรหัสหรือค่าเพียงหนึ่งอย่าง): ไฟล์เสียหาย"};
    }
    lines.push_back(line);
    at = end + 1;
  }
  if (std::find(lines.begin(), lines.end(), "SECTION") == lines.end())
    return {"it has no SECTION (a DXF file has HEADER and ENTITIES sections)",
            "ไม่มี SECTION (ไฟล์ DXF มีส่วน HEADER และ ENTITIES)"};
  const long limit = std::max<long>(1000, static_cast<long>(lines.size()));
  // Codes and counts read as dxflib reads them: the leading number ("90?" is group 90).
  // (The whole line, as dxflib reads it: "0000…0244839779" is 244839779 whatever its length.)
  const auto number = [](std::string_view line) { return std::strtol(std::string(line).c_str(), nullptr, 10); };
  std::string_view entity;
  for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
    // dxflib keeps the code as an int (4294967296 is group 0), and starts a new
    // entity at group 9 as at group 0 (a header variable's 9 names it).
    const int code = static_cast<int>(number(lines[i]));
    if (code == 0 || code == 9) entity = lines[i + 1];
    // Only where dxflib allocates by them (an MLEADER's group 90 holds flags, not a count).
    const bool counts = (entity == "LWPOLYLINE" && code == 90) || (entity == "LEADER" && code == 76) ||
                        (entity == "SPLINE" && code >= 72 && code <= 74);
    // (dxflib keeps strtol's long as an int: -3000000000 becomes 1294967296.)
    const long count = counts ? number(lines[i + 1]) : 0;
    // Reals (points 10-39, values 40-59): dxflib reads them with istream >>, which
    // turns a number past a double into +-1.8e308 and "nan" into 0 without a word;
    // neither is a drawing's number, so both are refused here with their line.
    if (code >= 10 && code <= 59) {
      std::string value(lines[i + 1]);
      std::replace(value.begin(), value.end(), ',', '.');  // as dxflib reads a decimal comma
      if (!std::isfinite(std::strtod(value.c_str(), nullptr))) {
        const std::string n = std::to_string(i + 2);
        value.resize(std::min<std::size_t>(value.size(), 32));
        return {"line " + n + " holds " + value + ", which is not a finite number: it is corrupt",
                "บรรทัด " + n + " มีค่า " + value + " ซึ่งไม่ใช่ตัวเลขที่มีค่าจำกัด (เป็นอนันต์หรือไม่ใช่ตัวเลข): ไฟล์เสียหาย"};
      }
    }
    if (count > limit || static_cast<int>(count) > limit) {
      const std::string n = std::to_string(i + 2), value = std::to_string(count), group = std::to_string(code);
      return {"line " + n + " says " + value + " points (group " + group + "), more than the file holds: it is corrupt",
              "บรรทัด " + n + " ระบุจำนวนจุด " + value + " (กลุ่ม " + group + ") มากกว่าที่ไฟล์มีอยู่: ไฟล์เสียหาย"};
    }
  }
  return {};
}

}  // namespace

DxfDrawing readDxfDrawing(const std::string& text) {
  Collector c;
  if (auto [why, whyThai] = unreadableByDxflib(text); !why.empty()) {
    c.drawing.why = std::move(why);
    c.drawing.whyThai = std::move(whyThai);
    return c.drawing;
  }
  std::istringstream in(text);
  DL_Dxf dxf;
  bool read = false;
  try {
    read = dxf.in(in, &c);
  } catch (const std::exception&) {
    // dxflib throws on some malformed values (a "999" comment of just "dxflib"
    // asks for its version at position 7).
    read = false;
  }
  if (!read) {
    c.drawing.why = "dxflib could not read it";
    c.drawing.whyThai = "dxflib อ่านไฟล์นี้ไม่ได้";
    return c.drawing;
  }
  c.finish();
  c.drawing.parsed = true;
  return c.drawing;
}

}  // namespace klueng::core::design::detail
