// Words for the part's features, in English and Thai (GLOSSARY terms).
#include <fmt/format.h>

#include <cmath>

#include "klueng/core/cut/part_features.h"

namespace klueng::core::cut {

namespace {

struct KindName {
  FeatureKind kind;
  const char* en;
  const char* th;
};

constexpr KindName kKindNames[] = {
    {FeatureKind::Face, "Face", "หน้าตัด"},     {FeatureKind::Cylinder, "Cylinder", "ทรงกระบอก"},
    {FeatureKind::Taper, "Taper", "เรียว"},    {FeatureKind::Chamfer, "Chamfer", "ลบมุม"},
    {FeatureKind::Arc, "Arc", "ส่วนโค้ง"},      {FeatureKind::Groove, "Groove", "ร่อง"},
    {FeatureKind::Thread, "Thread", "เกลียว"},
};

// A drawing's number: at most `decimals` digits, trailing zeros dropped ("30", "28.16", "1.5").
std::string num(double v, int decimals = 2) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  if (s == "-0") s = "0";
  return s;
}

bool th(Lang lang) { return lang == Lang::Th; }

template <class... Args>
std::string say(Lang lang, const char* en, const char* thai, const Args&... args) {
  return fmt::format(fmt::runtime(th(lang) ? thai : en), args...);
}

}  // namespace

std::string featureKindName(FeatureKind kind, Lang lang) {
  for (const KindName& k : kKindNames)
    if (k.kind == kind) return th(lang) ? k.th : k.en;
  return {};
}

namespace {

// Sizes and places in the display unit: a mm text is as before (no unit written,
// trailing zeros dropped); an inch text writes sizes with ″ and keeps the
// decimals an inch drawing (3) or a control (4) shows.
struct Words {
  const UnitFormat& u;
  // A label's size: "30" / "1.750″".
  std::string size(double mm, int mmDecimals = 2) const { return u.size(mm, mmDecimals) + u.sizeMark(); }
  // A description's size and place: "30" / "1.7500″", "Z-15" / "Z-0.5906".
  std::string exact(double mm) const { return u.inch() ? u.position(mm) + u.sizeMark() : num(mm, 3); }
  std::string place(double mm) const { return u.inch() ? u.position(mm) : num(mm, 3); }
  std::string face(double mm) const { return u.inch() ? u.size(mm) : num(mm); }
};

// Threads per inch when the pitch is a whole or half number of them (16 TPI = 1.5875 mm), else 0.
double threadsPerInch(double pitchMm) {
  if (pitchMm <= 0.0) return 0.0;
  const double tpi = kMmPerInch / pitchMm;
  const double half = std::round(tpi * 2.0) / 2.0;
  return std::abs(tpi - half) < 0.02 ? half : 0.0;
}

}  // namespace

std::string featureLabel(const PartFeature& f, Lang lang) { return featureLabel(f, lang, UnitFormat{}); }

std::string featureLabel(const PartFeature& f, Lang lang, const UnitFormat& units) {
  const Words w{units};
  switch (f.kind) {
    case FeatureKind::Cylinder: return "Ø" + w.size(f.diameter);
    case FeatureKind::Face: return "Z" + w.face(f.zLeft);
    case FeatureKind::Chamfer:
      // An inch drawing writes a 45° chamfer as "0.050″ × 45°", a metric one "C1.25".
      if (f.isFortyFiveChamfer()) return units.inch() ? w.size(f.radialHeight) + " × 45°" : "C" + num(f.radialHeight);
      return w.size(f.axialLength) + " × " + num(f.angle, 1) + "°";
    case FeatureKind::Taper: return num(f.angle, 2) + "°";
    case FeatureKind::Arc: return "R" + w.size(f.radius);
    case FeatureKind::Groove:
      return fmt::format("{} {} × Ø{}", th(lang) ? "ร่อง" : "groove", w.size(f.width), w.size(f.diameter));
    case FeatureKind::Thread:
      if (units.inch()) {
        // A unified thread is named by its major Ø and threads per inch: "0.750″-16 TPI".
        if (const double tpi = threadsPerInch(f.pitch); tpi > 0.0)
          return fmt::format("{}-{} TPI", w.size(f.diameter), num(tpi, 1));
        return "Ø" + w.size(f.diameter) + " × P" + w.size(f.pitch);
      }
      return "M" + num(f.diameter, 1) + "×" + num(f.pitch);
  }
  return {};
}

std::string describeFeature(const PartFeature& f, Lang lang) { return describeFeature(f, lang, UnitFormat{}); }

std::string describeFeature(const PartFeature& f, Lang lang, const UnitFormat& units) {
  const Words w{units};
  const std::string kind = featureKindName(f.kind, lang);
  const std::string where = f.kind == FeatureKind::Face
                                ? fmt::format("Z{}", w.place(f.zLeft))
                                : say(lang, "Z{} to Z{}", "Z{} ถึง Z{}", w.place(f.zRight), w.place(f.zLeft));
  const std::string inside = f.side == FeatureSide::Inside ? (th(lang) ? " (ด้านใน)" : " (inside)") : "";
  switch (f.kind) {
    case FeatureKind::Face:
      return say(lang, "{}{} at {} from Ø{} to Ø{}", "{}{} ที่ {} จาก Ø{} ถึง Ø{}", kind, inside, where,
                 w.exact(f.diameterLeft), w.exact(f.diameterRight));
    case FeatureKind::Cylinder:
      return say(lang, "{}{} Ø{}, {}, length {}", "{}{} Ø{} {} ยาว {}", kind, inside, w.exact(f.diameter), where,
                 w.exact(f.length()));
    case FeatureKind::Taper:
    case FeatureKind::Chamfer:
      return say(lang, "{}{} {} ({} × {}°), Ø{} to Ø{}, {}", "{}{} {} ({} × {}°) Ø{} ถึง Ø{} {}", kind, inside,
                 featureLabel(f, lang, units), w.exact(f.axialLength), num(f.angle, 2), w.exact(f.diameterRight),
                 w.exact(f.diameterLeft), where);
    case FeatureKind::Arc:
      return say(lang, "{}{} R{} {}, centre Z{} X{}, {}", "{}{} R{} {} จุดศูนย์กลาง Z{} X{} {}", kind, inside,
                 w.exact(f.radius), f.convex ? (th(lang) ? "มุมนูน" : "round") : (th(lang) ? "มุมเว้า" : "fillet"),
                 w.place(f.centre.x()), w.place(2.0 * f.centre.y()), where);
    case FeatureKind::Groove:
      return say(lang, "{}{} width {}, depth {}, Ø{}, {}", "{}{} กว้าง {} ลึก {} Ø{} {}", kind, inside, w.exact(f.width),
                 w.exact(f.depth), w.exact(f.diameter), where);
    case FeatureKind::Thread:
      return say(lang, "{}{} {}, pitch {}, major Ø{}, minor Ø{}, {}", "{}{} {} ระยะพิตช์ {} Ø นอก {} Ø ใน {} {}", kind,
                 inside, featureLabel(f, lang, units), w.exact(f.pitch), w.exact(f.diameter), w.exact(f.minorDiameter),
                 where);
  }
  return kind;
}

}  // namespace klueng::core::cut
