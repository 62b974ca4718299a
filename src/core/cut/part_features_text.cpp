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
    {FeatureKind::Face, "Face", "หน้าตัด"},         {FeatureKind::Cylinder, "Cylinder", "ทรงกระบอก"},
    {FeatureKind::Taper, "Taper", "เรียว"},          {FeatureKind::Chamfer, "Chamfer", "ลบมุม"},
    {FeatureKind::Arc, "Arc", "ส่วนโค้ง"},            {FeatureKind::Groove, "Groove", "ร่อง"},
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

std::string featureLabel(const PartFeature& f, Lang lang) {
  switch (f.kind) {
    case FeatureKind::Cylinder:
      return "Ø" + num(f.diameter);
    case FeatureKind::Face:
      return "Z" + num(f.zLeft);
    case FeatureKind::Chamfer:
      if (f.isFortyFiveChamfer()) return "C" + num(f.radialHeight);
      return num(f.axialLength) + " × " + num(f.angle, 1) + "°";
    case FeatureKind::Taper:
      return num(f.angle, 2) + "°";
    case FeatureKind::Arc:
      return "R" + num(f.radius);
    case FeatureKind::Groove:
      return fmt::format("{} {} × Ø{}", th(lang) ? "ร่อง" : "groove", num(f.width), num(f.diameter));
    case FeatureKind::Thread:
      return "M" + num(f.diameter, 1) + "×" + num(f.pitch);
  }
  return {};
}

std::string describeFeature(const PartFeature& f, Lang lang) {
  const std::string kind = featureKindName(f.kind, lang);
  const std::string where =
      f.kind == FeatureKind::Face
          ? fmt::format("Z{}", num(f.zLeft, 3))
          : say(lang, "Z{} to Z{}", "Z{} ถึง Z{}", num(f.zRight, 3), num(f.zLeft, 3));
  const std::string inside = f.side == FeatureSide::Inside ? (th(lang) ? " (ด้านใน)" : " (inside)") : "";
  switch (f.kind) {
    case FeatureKind::Face:
      return say(lang, "{}{} at {} from Ø{} to Ø{}", "{}{} ที่ {} จาก Ø{} ถึง Ø{}", kind, inside, where,
                         num(f.diameterLeft, 3), num(f.diameterRight, 3));
    case FeatureKind::Cylinder:
      return say(lang, "{}{} Ø{}, {}, length {}", "{}{} Ø{} {} ยาว {}", kind, inside,
                         num(f.diameter, 3), where, num(f.length(), 3));
    case FeatureKind::Taper:
    case FeatureKind::Chamfer:
      return say(lang, "{}{} {} ({} × {}°), Ø{} to Ø{}, {}", "{}{} {} ({} × {}°) Ø{} ถึง Ø{} {}", kind,
                         inside, featureLabel(f, lang), num(f.axialLength, 3), num(f.angle, 2),
                         num(f.diameterRight, 3), num(f.diameterLeft, 3), where);
    case FeatureKind::Arc:
      return say(lang, "{}{} R{} {}, centre Z{} X{}, {}", "{}{} R{} {} จุดศูนย์กลาง Z{} X{} {}", kind,
                         inside, num(f.radius, 3),
                         f.convex ? (th(lang) ? "มุมนูน" : "round") : (th(lang) ? "มุมเว้า" : "fillet"),
                         num(f.centre.x(), 3), num(2.0 * f.centre.y(), 3), where);
    case FeatureKind::Groove:
      return say(lang, "{}{} width {}, depth {}, Ø{}, {}", "{}{} กว้าง {} ลึก {} Ø{} {}", kind, inside,
                         num(f.width, 3), num(f.depth, 3), num(f.diameter, 3), where);
    case FeatureKind::Thread:
      return say(lang, "{}{} {}, pitch {}, major Ø{}, minor Ø{}, {}", "{}{} {} ระยะพิตช์ {} Ø นอก {} Ø ใน {} {}",
                         kind, inside, featureLabel(f, lang), num(f.pitch, 3),
                         num(f.diameter, 3), num(f.minorDiameter, 3), where);
  }
  return kind;
}

}  // namespace klueng::core::cut
