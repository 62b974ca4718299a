#include "infer/tool_words.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <initializer_list>
#include <vector>

#include "klueng/core/gcode/address_table.h"

namespace klueng::core::machine::detail {

namespace {

using io::ToolKind;

// Upper-case ASCII; Thai and other UTF-8 bytes kept as they are.
std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

// ASCII words of the comment ("I.D." -> "ID", "CUT-OFF" -> "CUT", "OFF").
std::vector<std::string> words(const std::string& up) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : up) {
    if ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')) {
      cur += c;
    } else if (c == '.' && !cur.empty() && cur.size() <= 2 && std::isalpha(static_cast<unsigned char>(cur.back()))) {
      continue;  // I.D. / O.D.
    } else if (!cur.empty()) {
      out.push_back(cur);
      cur.clear();
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

bool hasWord(const std::vector<std::string>& ws, std::initializer_list<std::string_view> any) {
  for (const std::string& w : ws)
    for (std::string_view a : any)
      if (w == a) return true;
  return false;
}

bool hasPrefix(const std::vector<std::string>& ws, std::initializer_list<std::string_view> any) {
  for (const std::string& w : ws)
    for (std::string_view a : any)
      if (w.rfind(a, 0) == 0) return true;
  return false;
}

bool hasText(const std::string& up, std::initializer_list<std::string_view> any) {
  for (std::string_view a : any)
    if (up.find(a) != std::string::npos) return true;
  return false;
}

bool followedBy(const std::vector<std::string>& ws, std::string_view first, std::string_view second) {
  for (std::size_t i = 0; i + 1 < ws.size(); ++i)
    if (ws[i] == first && ws[i + 1] == second) return true;
  return false;
}

// A drill's size written with the tool, in mm: "16MM", "16 MM", "Ø16", "DIA 16",
// "PHI22", "16 มม"; inches as shops write them: `1"`, `1/2 DRILL`, `1/2"`; a bare
// "DIA .5" or ".5 DIA" is in the program's units (`unitMm` mm each).
double sizeMm(const std::string& up, double unitMm) {
  const auto isNum = [&](std::size_t i) {
    return i < up.size() && (std::isdigit(static_cast<unsigned char>(up[i])) || up[i] == '.');
  };
  const auto skipSpaces = [&](std::size_t j) {
    while (j < up.size() && up[j] == ' ') ++j;
    return j;
  };
  for (std::size_t i = 0; i < up.size(); ++i) {
    if (!isNum(i) || (i > 0 && (isNum(i - 1) || up[i - 1] == '/'))) continue;
    std::size_t end = i;
    while (isNum(end)) ++end;
    double v = std::strtod(up.substr(i, end - i).c_str(), nullptr);
    if (!(v > 0.0)) continue;
    // A fraction: 1/2, 3/8.
    bool fraction = false;
    if (end + 1 < up.size() && up[end] == '/' && std::isdigit(static_cast<unsigned char>(up[end + 1]))) {
      std::size_t d = end + 1;
      while (d < up.size() && std::isdigit(static_cast<unsigned char>(up[d]))) ++d;
      const double below = std::strtod(up.substr(end + 1, d - end - 1).c_str(), nullptr);
      if (below > 0.0) v /= below;
      end = d;
      fraction = true;
    }
    const std::size_t j = skipSpaces(end);
    if (!fraction && (up.compare(j, 2, "MM") == 0 || up.compare(j, 6, "มม") == 0)) return v;
    if (j < up.size() && (up[j] == '"' || up.compare(j, 4, "INCH") == 0 || up.compare(j, 2, "IN") == 0))
      return v * 25.4;
    if (fraction && (up.compare(j, 5, "DRILL") == 0 || up.compare(j, 3, "DIA") == 0)) return v * 25.4;
    if (up.compare(j, 3, "DIA") == 0) return v * unitMm;  // ".5 DIA"
    // Ø (C3 98), ⌀ (E2 8C 80), Φ (CE A6), "PHI" or "DIA" just before the number.
    std::size_t k = i;
    while (k > 0 && up[k - 1] == ' ') --k;
    const auto before = [&](std::string_view w) { return k >= w.size() && up.compare(k - w.size(), w.size(), w) == 0; };
    if (before("\xC3\x98") || before("\xE2\x8C\x80") || before("\xCE\xA6") || before("PHI"))
      return fraction ? v * 25.4 : v;
    // "FI16", "FI 8": Ø as Polish and Russian shops spell it (a word of its own).
    if (before("FI") && (k < 3 || !std::isalpha(static_cast<unsigned char>(up[k - 3])))) return fraction ? v * 25.4 : v;
    const bool dWord =
        k == i && k >= 1 && up[k - 1] == 'D' && (k < 2 || !std::isalpha(static_cast<unsigned char>(up[k - 2])));
    if (before("DIA") || dWord) return fraction ? v * 25.4 : v * unitMm;
  }
  return 0.0;
}

// A bare number right after the drill's own word, in the program's units: "DRILL 10", "FORET 22",
// "SVERLO 1.3", "T2 DRILL 1.0" in an inch program ("DRILL 10X30": the diameter, then the depth).
double sizeAfterDrillWord(const std::string& up, std::initializer_list<std::string_view> drillWords, double unitMm) {
  for (std::string_view w : drillWords)
    for (std::size_t at = up.find(w); at != std::string::npos; at = up.find(w, at + 1)) {
      if (at > 0 && std::isalpha(static_cast<unsigned char>(up[at - 1]))) continue;
      std::size_t j = at + w.size();
      while (j < up.size() && std::isalpha(static_cast<unsigned char>(up[j]))) ++j;  // the word's ending
      while (j < up.size() && (up[j] == ' ' || up[j] == ':' || up[j] == '-')) ++j;
      if (j >= up.size() || !(std::isdigit(static_cast<unsigned char>(up[j])) || up[j] == '.')) continue;
      char* end = nullptr;
      const double v = std::strtod(up.c_str() + j, &end);
      const std::size_t after = static_cast<std::size_t>(end - up.c_str());
      if (after < up.size() && up[after] == '/') continue;  // a fraction: sizeMm's
      if (after < up.size() && std::isalpha(static_cast<unsigned char>(up[after])) && up[after] != 'X') continue;
      if (v > 0.0) return v * unitMm;
    }
  return 0.0;
}

}  // namespace

namespace {

bool isUpperAt(const std::string& s, std::size_t i) { return i < s.size() && s[i] >= 'A' && s[i] <= 'Z'; }
bool isDigitAt(const std::string& s, std::size_t i) { return i < s.size() && s[i] >= '0' && s[i] <= '9'; }

// The nose radius a tool comment states, in mm; 0 when none: "R0.4", "R.8", "R0,2" (a radius word
// of its own), an ISO insert code's last two digits ("CNMG 120408": 0.8 mm), an ANSI code's last
// digit in 64ths of an inch ("CNMG 431": 1/64 in).
double statedNoseRadiusMm(const std::string& up, double unitMm) {
  for (std::size_t i = 0; i < up.size(); ++i) {
    // An insert code: four letters, an optional blank, then 6 (ISO) or 3 (ANSI) digits.
    if (i + 4 < up.size() && (i == 0 || !isUpperAt(up, i - 1)) && isUpperAt(up, i) && isUpperAt(up, i + 1) &&
        isUpperAt(up, i + 2) && isUpperAt(up, i + 3) &&
        std::string_view("CDKRSTVW").find(up[i]) != std::string_view::npos) {
      std::size_t d = i + 4;
      if (d < up.size() && up[d] == ' ') ++d;
      std::size_t e = d;
      while (isDigitAt(up, e)) ++e;
      if (e - d == 6) return (up[e - 2] - '0') + (up[e - 1] - '0') / 10.0;
      if (e - d == 3 && up[e - 1] >= '1' && up[e - 1] <= '8') return (up[e - 1] - '0') * 25.4 / 64.0;
    }
    // "R0.4": R alone before a number with a decimal point (a comma for it too).
    if (up[i] != 'R' || (i > 0 && (isUpperAt(up, i - 1) || isDigitAt(up, i - 1)))) continue;
    std::size_t k = i + 1;
    while (k < up.size() && (up[k] == ' ' || up[k] == '=')) ++k;
    std::size_t e = k;
    bool point = false;
    while (e < up.size() && (isDigitAt(up, e) || ((up[e] == '.' || up[e] == ',') && !point))) {
      point = point || up[e] == '.' || up[e] == ',';
      ++e;
    }
    if (!point || e == k || isUpperAt(up, e)) continue;
    std::string number = up.substr(k, e - k);
    std::replace(number.begin(), number.end(), ',', '.');
    const double mm = std::atof(number.c_str()) * unitMm;
    if (mm >= 0.05 && mm <= 3.0) return mm;
  }
  return 0.0;
}

}  // namespace

CommentTool classifyComment(std::string_view comment, double unitMm) {
  CommentTool out;
  const std::string up = upper(comment);
  out.noseRadiusMm = statedNoseRadiusMm(up, unitMm);
  const std::vector<std::string> ws = words(up);
  // The words shops write in English, Thai and the other languages lathe programs
  // come in (French, Spanish/Portuguese, German, Italian, Polish): a tool's kind is
  // said the same way in a shop's own language.
  const bool inside = hasWord(ws, {"ID", "INTERNAL", "INSIDE", "INNER", "INT"}) ||
                      hasPrefix(ws, {"INTERIEUR", "INTERIOR", "INTERNO", "INNEN", "WEWN"}) ||
                      hasText(up, {"เกลียวใน", "ภายใน"});

  // The insert by its name or its angle as shops write it ("35* FINISH", "55 DEG", "80°").
  const auto angle = [&](std::string_view deg) {
    for (const char* mark : {"*", "°", " DEG", "DEG", "-DEG"}) {
      const std::string text = std::string(deg) + mark;
      for (std::size_t at = up.find(text); at != std::string::npos; at = up.find(text, at + 1))
        if (at == 0 || !std::isdigit(static_cast<unsigned char>(up[at - 1]))) return true;  // not "135*"
    }
    return false;
  };
  if (hasWord(ws, {"VNMG", "VBMT", "VCMT"}) || angle("35"))
    out.insert = "vnmg";
  else if (hasWord(ws, {"DNMG", "DCMT", "DCGT"}) || angle("55"))
    out.insert = "dnmg";
  else if (hasWord(ws, {"CNMG", "CCMT"}) || angle("80"))
    out.insert = "cnmg";
  out.roughing = hasPrefix(ws, {"ROUGH", "ROUSH", "EBAUCH", "DESBAST", "SCHRUPP", "ZGRUB", "CERNOV", "CHERNOV"}) ||
                 hasText(up, {"กลึงหยาบ", "ЧЕРНОВ", "чернов"});
  out.finishing = hasPrefix(ws, {"FINISH", "FIN", "ACAB", "SCHLICHT", "WYKANCZ", "CISTOV", "CHISTOV"}) ||
                  hasText(up, {"กลึงละเอียด", "ละเอียด", "ЧИСТОВ", "чистов"});

  // A bar puller or bar stop, as shops spell it ("BARPULER", "BAR PULLER", "BAR STOP", "PUXADOR"):
  // it grips or stops the bar with the spindle stopped and cuts nothing.
  if (followedBy(ws, "BAR", "PULLER") || followedBy(ws, "BAR", "PULER") || followedBy(ws, "BAR", "PULL") ||
      followedBy(ws, "BAR", "STOP") || followedBy(ws, "BAR", "FEEDER") || followedBy(ws, "BAR", "GRIPPER") ||
      hasPrefix(ws, {"BARPUL", "BARSTOP", "BARGRIP", "PUXADOR", "STANGENZIEH", "STANGENGREIF", "TIREBARRE", "EMBARREUR",
                     "JALADOR"}) ||
      hasText(up, {"ตัวดึงชิ้นงาน", "ตัวดึงบาร์", "ตัวกั้นบาร์", "ЗАХВАТ ПРУТКА"})) {
    out.holdsBar = true;
    out.pullsBar = !followedBy(ws, "BAR", "STOP") && !hasPrefix(ws, {"BARSTOP"}) && !hasText(up, {"ตัวกั้นบาร์"});
    return out;
  }
  if (followedBy(ws, "CENTER", "DRILL") || followedBy(ws, "CENTRE", "DRILL") ||
      hasWord(ws, {"SPOT", "CENTERDRILL", "CENTRER", "CENTRAGE", "ZENTRIER"}) || hasText(up, {"นำศูนย์", "รูศูนย์"})) {
    out.kind = ToolKind::CentreDrill;
  } else if (hasPrefix(ws, {"THREAD", "THD", "THRD", "FILET", "ROSCA", "ROSCADO", "GEWINDE", "GWINT"}) ||
             hasText(up, {"เกลียว"})) {
    out.kind = inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd;
  } else if (followedBy(ws, "CUT", "OFF") || followedBy(ws, "PART", "OFF") ||
             hasPrefix(ws, {"CUTOFF", "PARTING", "PARTOFF", "TRONC", "TRONZ", "SANGR", "BEDAME", "ABSTECH", "ODCIN",
                            "ODCIEC", "OTREZ"}) ||
             hasText(up, {"ตัดขาด", "ตัดชิ้นงาน", "ОТРЕЗ", "отрез"})) {
    out.kind = ToolKind::Parting;
  } else if (hasPrefix(ws, {"GROOV", "GORGE", "RANUR", "EINSTECH", "ROWK", "ROWEK"}) || hasText(up, {"ร่อง"})) {
    out.kind = ToolKind::Grooving;
  } else if (hasPrefix(ws, {"DRILL", "PERCAGE", "PERCER", "FORET", "BOHR", "TALADR", "BROCA", "WIERT", "SVERL"}) ||
             hasText(up, {"ดอกสว่าน", "เจาะ", "СВЕРЛ"})) {
    out.kind = ToolKind::Drill;
    out.drillMm = sizeMm(up, unitMm);
    if (out.drillMm == 0.0)
      out.drillMm = sizeAfterDrillWord(up, {"DRILL", "FORET", "BOHRER", "BROCA", "SVERLO", "WIERTLO"}, unitMm);
  } else if (hasPrefix(ws, {"BORE", "BORING", "ALESAGE", "MANDRIN", "WYTACZ"}) || hasText(up, {"คว้าน"}) || inside) {
    out.kind = ToolKind::Boring;
  } else if (!out.insert.empty() || out.finishing ||
             hasWord(ws, {"OD", "ROUGH", "ROUGHING", "TURN", "TURNING", "FACE", "FACING", "PROFILE", "CONTOUR"}) ||
             hasPrefix(ws, {"EBAUCH", "DRESSAGE", "CHARIOT", "DESBAST", "REFRENT", "CILINDR", "FACEAR", "SCHRUPP",
                            "TOCZ", "PLANOW", "ZEWN", "PROXODN", "PROHODN", "TOCEN", "TOCHEN"}) ||
             hasText(up, {"กลึงปอก", "กลึงหยาบ", "ปาดหน้า", "กลึงผิว", "กลึงขึ้นรูป", "ПРОХОДН", "проходн", "ТОЧЕН", "точен"})) {
    out.kind = ToolKind::Turning;
  }
  return out;
}

std::vector<CommentToolWord> toolWordsIn(std::string_view comment) {
  const auto isDigit = [&](std::size_t i) { return i < comment.size() && comment[i] >= '0' && comment[i] <= '9'; };
  std::vector<CommentToolWord> out;
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < comment.size(); ++i) {
    if (comment[i] != 'T' && comment[i] != 't') continue;
    if (i > 0 && std::isalnum(static_cast<unsigned char>(comment[i - 1]))) continue;  // "OUT1", "PT2"
    std::size_t d = i + 1;
    while (isDigit(d) && d - i <= 4) ++d;
    const std::size_t digits = d - i - 1;
    if (digits == 0 || isDigit(d)) continue;
    int value = 0;
    for (std::size_t k = i + 1; k < d; ++k) value = value * 10 + (comment[k] - '0');
    out.push_back({digits <= 2 ? value : gcode::splitToolNumber(value).station, comment.substr(i)});
    starts.push_back(i);
  }
  for (std::size_t n = 0; n + 1 < out.size(); ++n) {
    std::string_view& t = out[n].text;
    t = t.substr(0, starts[n + 1] - starts[n]);
    while (!t.empty() && (t.back() == ' ' || t.back() == ',' || t.back() == ';' || t.back() == '/' || t.back() == '-'))
      t.remove_suffix(1);
  }
  return out;
}

std::string_view commentForStation(std::string_view comment, int station) {
  const std::vector<CommentToolWord> named = toolWordsIn(comment);
  if (std::all_of(named.begin(), named.end(), [&](const CommentToolWord& w) { return w.station == station; }))
    return comment;  // "(OD TURN T0101)": all of it is about this station
  for (const CommentToolWord& w : named)
    if (w.station == station) return w.text;
  return {};
}

}  // namespace klueng::core::machine::detail
