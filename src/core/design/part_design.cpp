// Reading part designs (JSON, with nlohmann::json) and the cutting-speed table.
#include "klueng/core/design/part_design.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "klueng/core/design/iso_fits.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_read.h"

namespace klueng::core::design {

namespace {

Diagnostic fileDiagnostic(const char* code, int line, int column, std::vector<std::string> args) {
  Diagnostic d;
  d.severity = Severity::Error;
  d.code = code;
  d.range.line = line;
  d.range.column = column;
  d.args = std::move(args);
  return d;
}

// Line and column (1-based) of a byte offset.
std::pair<int, int> placeOf(const std::string& text, std::size_t byte) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++line, column = 1;
    else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80)
      ++column;
  }
  return {line, column};
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  const auto b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// The JSON of a part file, or why the text is not JSON in `result`'s diagnostics.
std::optional<nlohmann::json> parsePartJson(const std::string& text, const std::string& fileName,
                                            io::ReadResult<PartDesign>& result) {
  // Why the text is not JSON, in our words (both languages), never the JSON library's
  // English (issue 42 item 6); the diagnostic's line and column say where.
  // The place is said in the words too: a window that lists messages without their place still shows it.
  const auto notJson = [&](std::size_t byte, const std::string& en, const std::string& th) {
    const auto [line, column] = placeOf(text, byte);
    const std::string at = fmt::format(" (line {}, column {})", line, column);
    const std::string atTh = fmt::format(" (บรรทัด {} คอลัมน์ {})", line, column);
    result.diagnostics.push_back(fileDiagnostic(codes::kPartFileNotJson, line, column, {fileName, en + at, th + atTh}));
  };
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    const std::size_t byte = e.byte > 0 ? e.byte - 1 : 0;
    if (text.find_first_not_of(" \t\r\n") == std::string::npos)
      result.diagnostics.push_back(
          fileDiagnostic(codes::kPartFileNotJson, 0, 0, {fileName, "the file is empty", "ไฟล์ว่างเปล่า"}));
    else if (byte + 1 >= text.size())
      notJson(byte, "the text ends before the JSON is complete (a missing } or ]?)",
              "ข้อความจบก่อนที่ JSON จะครบ (ขาด } หรือ ] หรือไม่)");
    else
      notJson(byte, "the JSON is not valid here (a missing comma, quote or bracket, or a word that is not JSON?)",
              "JSON ไม่ถูกต้องที่ตำแหน่งนี้ (ขาดจุลภาค เครื่องหมายคำพูด หรือวงเล็บ หรือมีคำที่ไม่ใช่ JSON หรือไม่)");
  } catch (const nlohmann::json::exception& e) {
    // A number too big for a double ("number overflow parsing '2.5e553'"): no byte
    // offset in the exception, so the place is where that number is written.
    const std::string why = e.what();
    std::size_t byte = 0;
    if (const auto q = why.find('\''); q != std::string::npos)
      if (const auto q2 = why.find('\'', q + 1); q2 != std::string::npos)
        byte = std::min(text.find(why.substr(q + 1, q2 - q - 1)), text.size());
    notJson(byte, "a number is too large for this program (at most about 1e308)",
            "ตัวเลขใหญ่เกินกว่าที่โปรแกรมรับได้ (ไม่เกินประมาณ 1e308)");
  }
  return std::nullopt;
}

// Reads a part design's fields from its JSON, one read function a field; each
// problem is a diagnostic in `result`, and any problem leaves the design unread.
class PartDesignReader {
 public:
  PartDesignReader(nlohmann::json j, const std::string& fileName, io::ReadResult<PartDesign>& result)
      : j_(std::move(j)), fileName_(fileName), result_(result) {}

  void read() {
    if (!j_.is_object()) {
      bad("(the file)", "an object { ... }", "ออบเจกต์ { ... }");
      return;
    }
    readNameAndMaterial();
    readToolMaterial();
    readStock();
    readOutsideAndInside();
    readGeneralTolerance();
    readPartOff();
    readGrooves();
    readThreads();
    if (ok_) result_.value = std::move(part_);
  }

 private:
  void missing(const std::string& field) {
    result_.diagnostics.push_back(fileDiagnostic(codes::kPartFieldMissing, 0, 0, {fileName_, field}));
    ok_ = false;
  }

  // What the field must be, in both languages: the Thai sentence is Thai all through (issue 42 item 6).
  void bad(const std::string& field, const std::string& en, const std::string& th) {
    result_.diagnostics.push_back(fileDiagnostic(codes::kPartFieldBad, 0, 0, {fileName_, field, en, th}));
    ok_ = false;
  }

  // A positive finite number up to `max`, or the reason it is not.
  void positive(const nlohmann::json& o, const std::string& key, const std::string& field, double& out,
                double max = kMaxPartSize) {
    if (!o.contains(key)) return missing(field);
    if (!o[key].is_number() || !std::isfinite(o[key].get<double>()) || o[key].get<double>() <= 0.0 ||
        o[key].get<double>() > max) {
      const std::string most = fmt::format("{}", max);
      return bad(field, "a number of millimetres above 0 (at most " + most + ")",
                 "ตัวเลขเป็นมิลลิเมตรที่มากกว่า 0 (ไม่เกิน " + most + ")");
    }
    out = o[key].get<double>();
  }

  // The name and material go into the program's header and comments: a text the program's
  // own check reads back (a 10 MB name made a program its check refused; issue 42 item 6).
  void words(const char* key, std::string& out) {
    if (!j_.contains(key) || !j_[key].is_string()) return;
    const std::string text = j_[key].get<std::string>();
    std::size_t points = 0;
    for (const char c : text) points += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    if (points > kMaxPartTextChars)
      return bad(key, "a text of at most " + std::to_string(kMaxPartTextChars) + " characters",
                 "ข้อความยาวไม่เกิน " + std::to_string(kMaxPartTextChars) + " ตัวอักษร");
    out = text;
  }

  void readNameAndMaterial() {
    words("name", part_.name);
    words("material", part_.material);
  }

  void readToolMaterial() {
    if (!j_.contains("tool_material")) return;
    if (!j_["tool_material"].is_string() ||
        (j_["tool_material"].get<std::string>() != "hss" && j_["tool_material"].get<std::string>() != "carbide"))
      bad("tool_material", "\"hss\" or \"carbide\"", "\"hss\" หรือ \"carbide\"");
    else
      part_.toolMaterial = j_["tool_material"].get<std::string>();
  }

  void readStock() {
    if (!j_.contains("stock") || !j_["stock"].is_object()) return missing("stock");
    // A bar a lathe holds (the DXF import's limits): the program's rapids clear it by a few mm
    // and must stay within the control's numbers (issue 42 item 6: a 10000 mm stock).
    positive(j_["stock"], "diameter", "stock.diameter", part_.stockDiameter, kMaxStockDiameter);
    positive(j_["stock"], "length", "stock.length", part_.stockLength, kMaxStockLength);
    if (j_["stock"].contains("bore")) {
      positive(j_["stock"], "bore", "stock.bore", part_.stockBore);
      if (part_.stockBore >= part_.stockDiameter && part_.stockDiameter > 0.0)
        bad("stock.bore", "smaller than the stock's diameter", "เล็กกว่าเส้นผ่านศูนย์กลางของชิ้นงาน");
    }
  }

  // A tolerance: a number (±), [upper, lower] in mm, or (on a Ø) an ISO 286 class such as "h7".
  void readTolerance(const nlohmann::json& v, const std::string& field, double size, bool fits, cut::Tolerance& out) {
    const auto finite = [](const nlohmann::json& n) {
      return n.is_number() && std::isfinite(n.get<double>()) && std::abs(n.get<double>()) <= 100.0;
    };
    if (finite(v) && v.get<double>() > 0.0) {
      out = {v.get<double>(), -v.get<double>(), ""};
    } else if (v.is_array() && v.size() == 2 && finite(v[0]) && finite(v[1]) &&
               v[0].get<double>() >= v[1].get<double>()) {
      out = {v[0].get<double>(), v[1].get<double>(), ""};
    } else if (fits && v.is_string()) {
      const auto fit = isoFit(v.get<std::string>(), size);
      if (!fit)
        return bad(field, std::string("an ISO 286 class of ") + kIsoFitsKnown,
                   std::string("ชั้นพิกัดงานสวม ISO 286 หนึ่งใน ") + kIsoFitsKnown);
      out = *fit;
      return;
    } else {
      return fits ? bad(field, "± mm (0.05), [upper, lower] mm ([0.02, -0.01]) or an ISO 286 class (\"h7\")",
                        "± มม. (0.05), [บน, ล่าง] มม. ([0.02, -0.01]) หรือชั้นพิกัดงานสวม ISO 286 (\"h7\")")
                  : bad(field, "± mm (0.1) or [upper, lower] mm ([0.1, -0.2])",
                        "± มม. (0.1) หรือ [บน, ล่าง] มม. ([0.1, -0.2])");
    }
    out.text = cut::toleranceLabel(out);
  }

  // One step of a list: its kind and Ø, length, edge break, tolerances and roughness;
  // nothing when its kind is missing or it is not an object.
  std::optional<OutsideStep> readStep(const std::string& key, bool arcs, std::size_t k) {
    const std::string word = key == "inside" ? "bore" : "cylinder";
    const nlohmann::json& o = j_[key][k];
    const std::string at = key + "[" + std::to_string(k) + "]";
    if (!o.is_object()) {
      bad(at, key == "inside" ? "an object { \"bore\": ... }" : "an object { \"cylinder\": ... }",
          key == "inside" ? "ออบเจกต์ { \"bore\": ... }" : "ออบเจกต์ { \"cylinder\": ... }");
      return std::nullopt;
    }
    OutsideStep step;
    if (o.contains(word)) {
      positive(o, word, at + "." + word, step.diameter);
    } else if (o.contains("taper")) {
      step.kind = StepKind::Taper;
      positive(o, "taper", at + ".taper", step.diameter);
    } else if (arcs && o.contains("arc")) {
      step.kind = StepKind::Arc;
      positive(o, "arc", at + ".arc", step.diameter);
      positive(o, "radius", at + ".radius", step.radius);
      if (o.contains("concave")) {
        if (!o["concave"].is_boolean())
          bad(at + ".concave", "true or false", "true หรือ false");
        else
          step.concave = o["concave"].get<bool>();
      }
    } else {
      missing(at + "." + word);
      return std::nullopt;
    }
    positive(o, "length", at + ".length", step.length);
    if (o.contains("chamfer")) {
      step.edge = EdgeBreak::Chamfer;
      positive(o, "chamfer", at + ".chamfer", step.edgeSize);
    } else if (o.contains("round")) {
      step.edge = EdgeBreak::Round;
      positive(o, "round", at + ".round", step.edgeSize);
    }
    if (o.contains("tolerance")) {
      if (step.kind != StepKind::Cylinder)
        bad(at + ".tolerance", "on a cylinder's or bore's Ø only", "ใส่ได้เฉพาะที่ Ø ของทรงกระบอกหรือรูคว้านเท่านั้น");
      else
        readTolerance(o["tolerance"], at + ".tolerance", step.diameter, true, step.tolerance);
    }
    if (o.contains("length_tolerance"))
      readTolerance(o["length_tolerance"], at + ".length_tolerance", step.length, false, step.lengthTolerance);
    if (o.contains("roughness")) positive(o, "roughness", at + ".roughness", step.roughness);
    return step;
  }

  // A list of steps: outside cylinders, tapers and arcs; in the bore cylinders and tapers.
  void readSteps(const std::string& key, bool arcs, std::vector<OutsideStep>& into) {
    for (std::size_t k = 0; k < j_[key].size(); ++k)
      if (const std::optional<OutsideStep> step = readStep(key, arcs, k)) into.push_back(*step);
  }

  void readOutsideAndInside() {
    if (!j_.contains("outside") || !j_["outside"].is_array())
      missing("outside");
    else
      readSteps("outside", true, part_.outside);
    if (j_.contains("inside")) {
      if (!j_["inside"].is_array())
        bad("inside", "a list [ { \"bore\": ..., \"length\": ... } ]", "รายการ [ { \"bore\": ..., \"length\": ... } ]");
      else
        readSteps("inside", false, part_.inside);
    }
  }

  void readGeneralTolerance() {
    if (!j_.contains("general_tolerance")) return;
    const auto& g = j_["general_tolerance"];
    if (!g.is_string() || !generalTolerance(g.get<std::string>(), 10.0))
      bad("general_tolerance", "\"f\", \"m\", \"c\" or \"v\" (ISO 2768-1)",
          "\"f\", \"m\", \"c\" หรือ \"v\" (ISO 2768-1)");
    else
      part_.generalTolerance = g.get<std::string>();
  }

  void readPartOff() {
    if (!j_.contains("part_off")) return;
    if (!j_["part_off"].is_boolean())
      bad("part_off", "true or false", "true หรือ false");
    else
      part_.partOff = j_["part_off"].get<bool>();
  }

  // The Z of a groove's right wall or a thread's right end: 0 or below.
  bool zAtOrBelowFace(const nlohmann::json& o) const {
    return o.is_object() && o.contains("z") && o["z"].is_number() && std::isfinite(o["z"].get<double>()) &&
           o["z"].get<double>() <= 0.0;
  }

  void readGrooves() {
    if (!j_.contains("grooves")) return;
    if (!j_["grooves"].is_array())
      bad("grooves", "a list [ { \"z\": ..., \"width\": ..., \"diameter\": ... } ]",
          "รายการ [ { \"z\": ..., \"width\": ..., \"diameter\": ... } ]");
    for (std::size_t k = 0; j_["grooves"].is_array() && k < j_["grooves"].size(); ++k) {
      const nlohmann::json& o = j_["grooves"][k];
      const std::string at = "grooves[" + std::to_string(k) + "]";
      Groove g;
      if (!zAtOrBelowFace(o)) {
        bad(at + ".z", "the Z of its right wall, 0 or below", "ค่า Z ของผนังด้านขวาของร่อง เป็น 0 หรือต่ำกว่า");
        continue;
      }
      g.z = o["z"].get<double>();
      positive(o, "width", at + ".width", g.width);
      positive(o, "diameter", at + ".diameter", g.diameter);
      part_.grooves.push_back(g);
    }
  }

  void readThreads() {
    if (!j_.contains("threads")) return;
    if (!j_["threads"].is_array())
      bad("threads", "a list [ { \"z\": ..., \"length\": ..., \"pitch\": ... } ]",
          "รายการ [ { \"z\": ..., \"length\": ..., \"pitch\": ... } ]");
    for (std::size_t k = 0; j_["threads"].is_array() && k < j_["threads"].size(); ++k) {
      const nlohmann::json& o = j_["threads"][k];
      const std::string at = "threads[" + std::to_string(k) + "]";
      Thread t;
      if (!zAtOrBelowFace(o)) {
        bad(at + ".z", "the Z of its right end, 0 or below", "ค่า Z ของปลายด้านขวาของเกลียว เป็น 0 หรือต่ำกว่า");
        continue;
      }
      t.z = o["z"].get<double>();
      positive(o, "length", at + ".length", t.length);
      positive(o, "pitch", at + ".pitch", t.pitch);
      part_.threads.push_back(t);
    }
  }

  nlohmann::json j_;
  const std::string& fileName_;
  io::ReadResult<PartDesign>& result_;
  PartDesign part_;
  bool ok_ = true;
};

}  // namespace

const OutsideStep* cylinderUnder(const PartDesign& part, double zRight, double zLeft, bool clearOfEdge) {
  double z = 0.0;
  for (const OutsideStep& s : part.outside) {
    const double right = z, left = z - s.length;
    z = left;
    if (s.kind != StepKind::Cylinder || zRight > right + 1e-9 || zLeft < left - 1e-9) continue;
    if (clearOfEdge && s.edge != EdgeBreak::None && zRight > right - s.edgeSize + 1e-9) continue;
    return &s;
  }
  return nullptr;
}

double PartDesign::length() const {
  double total = 0.0;
  for (const OutsideStep& s : outside) total += s.length;
  return total;
}

io::ReadResult<std::string> readPartFile(const std::string& path) {
  return io::readFileLimited(path, kMaxPartFileBytes);
}

io::ReadResult<PartDesign> readPartDesign(const std::string& text, const std::string& fileName) {
  io::ReadResult<PartDesign> result;
  std::optional<nlohmann::json> j = parsePartJson(text, fileName, result);
  if (!j) return result;
  PartDesignReader(std::move(*j), fileName, result).read();
  return result;
}

io::ReadResult<std::vector<CuttingSpeed>> readCuttingSpeeds(const std::string& path) {
  io::ReadResult<std::vector<CuttingSpeed>> result;
  const std::string file = path.empty() ? io::shippedCuttingSpeedsPath() : path;
  // Read as every setup file is (a named pipe is refused, never waited on; issue 42 item 4).
  const io::ReadResult<std::string> bytes = io::readFileLimited(file, kMaxPartFileBytes);
  if (!bytes.value) {
    result.diagnostics = bytes.diagnostics;
    return result;
  }
  std::istringstream in(*bytes.value);
  std::vector<CuttingSpeed> rows;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    std::stringstream fields(t);
    std::string name, hss, carbide;
    std::getline(fields, name, '|');
    std::getline(fields, hss, '|');
    std::getline(fields, carbide, '|');
    CuttingSpeed row{trim(name), 0.0, 0.0};
    char* end = nullptr;
    const std::string h = trim(hss), c = trim(carbide);
    row.hss = std::strtod(h.c_str(), &end);
    const bool hssOk = !h.empty() && *end == '\0' && row.hss > 0.0 && row.hss < 5000.0;
    row.carbide = std::strtod(c.c_str(), &end);
    const bool carbideOk = !c.empty() && *end == '\0' && row.carbide > 0.0 && row.carbide < 5000.0;
    if (row.material.empty() || !hssOk || !carbideOk) {
      result.diagnostics.push_back(fileDiagnostic(codes::kSpeedsLineBad, n, 1, {file, t}));
      continue;
    }
    rows.push_back(row);
  }
  result.value = std::move(rows);
  return result;
}

std::string writePartDesign(const PartDesign& part) {
  nlohmann::ordered_json j;
  j["name"] = part.name;
  j["material"] = part.material;
  j["tool_material"] = part.toolMaterial;
  j["stock"]["diameter"] = part.stockDiameter;
  j["stock"]["length"] = part.stockLength;
  if (part.stockBore > 0.0) j["stock"]["bore"] = part.stockBore;
  const auto steps = [](const std::vector<OutsideStep>& from, const char* word) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const OutsideStep& s : from) {
      nlohmann::ordered_json o;
      if (s.kind == StepKind::Cylinder) o[word] = s.diameter;
      if (s.kind == StepKind::Taper) o["taper"] = s.diameter;
      if (s.kind == StepKind::Arc) o["arc"] = s.diameter;
      o["length"] = s.length;
      if (s.kind == StepKind::Arc) o["radius"] = s.radius;
      if (s.kind == StepKind::Arc && s.concave) o["concave"] = true;
      if (s.edge == EdgeBreak::Chamfer) o["chamfer"] = s.edgeSize;
      if (s.edge == EdgeBreak::Round) o["round"] = s.edgeSize;
      // A tolerance as it was written: an ISO class by name, ± as one number, else [upper, lower].
      const auto tolerance = [](const cut::Tolerance& t) -> nlohmann::ordered_json {
        if (!t.text.empty() && std::isalpha(static_cast<unsigned char>(t.text[0]))) return t.text;
        if (t.upper == -t.lower) return t.upper;
        return nlohmann::ordered_json::array({t.upper, t.lower});
      };
      if (s.tolerance.given()) o["tolerance"] = tolerance(s.tolerance);
      if (s.lengthTolerance.given()) o["length_tolerance"] = tolerance(s.lengthTolerance);
      if (s.roughness > 0.0) o["roughness"] = s.roughness;
      list.push_back(o);
    }
    return list;
  };
  j["outside"] = steps(part.outside, "cylinder");
  if (!part.inside.empty()) j["inside"] = steps(part.inside, "bore");
  for (const Groove& g : part.grooves)
    j["grooves"].push_back({{"z", g.z}, {"width", g.width}, {"diameter", g.diameter}});
  for (const Thread& t : part.threads) j["threads"].push_back({{"z", t.z}, {"length", t.length}, {"pitch", t.pitch}});
  if (part.partOff) j["part_off"] = true;
  if (!part.generalTolerance.empty()) j["general_tolerance"] = part.generalTolerance;
  return j.dump(2) + "\n";
}

std::string cuttingSpeedRow(const std::string& material, const std::vector<CuttingSpeed>& table) {
  std::string lower = material;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const CuttingSpeed& row : table)
    if (!row.material.empty() && lower.find(row.material) != std::string::npos) return row.material;
  // The words lathe teachers write in Thai (GLOSSARY), and common English ones.
  static const std::pair<const char*, const char*> kAliases[] = {
      {"เหล็กหล่อ", "cast-iron"}, {"cast iron", "cast-iron"}, {"อะลูมิเนียม", "aluminium"},
      {"อลูมิเนียม", "aluminium"}, {"aluminum", "aluminium"},  {"ทองเหลือง", "brass"},
      {"เหล็ก", "steel"},        {"s45c", "steel"},          {"mild steel", "steel"}};
  for (const auto& [word, row] : kAliases)
    if (lower.find(word) != std::string::npos)
      for (const CuttingSpeed& r : table)
        if (r.material == row) return row;
  return {};
}

std::vector<cut::DrawnDimension> drawnDimensions(const PartDesign& part, const std::string& general) {
  const std::string generalClass = general.empty() ? part.generalTolerance : general;
  std::vector<cut::DrawnDimension> out;
  const auto add = [&](cut::DimensionKind kind, cut::FeatureSide side, double nominal, cut::Tolerance t, double zRight,
                       double zLeft) {
    if (!t.given() && !generalClass.empty())
      if (const auto g = generalTolerance(generalClass, nominal)) t = *g;
    if (t.given()) out.push_back({kind, side, nominal, t, zRight, zLeft});
  };
  const auto steps = [&](const std::vector<OutsideStep>& list, cut::FeatureSide side) {
    double z = 0.0;
    for (const OutsideStep& s : list) {
      const double zr = z, zl = z - s.length;
      z = zl;
      // The Ø where the cylinder is, clear of its edge break.
      if (s.kind == StepKind::Cylinder)
        add(cut::DimensionKind::Diameter, side, s.diameter, s.tolerance,
            zr - (s.edge == EdgeBreak::None ? 0.0 : s.edgeSize), zl);
      add(cut::DimensionKind::Length, side, s.length, s.lengthTolerance, zr, zl);
    }
  };
  steps(part.outside, cut::FeatureSide::Outside);
  steps(part.inside, cut::FeatureSide::Inside);
  return out;
}

std::vector<cut::FinishMark> finishMarks(const PartDesign& part) {
  std::vector<cut::FinishMark> out;
  for (const bool inside : {false, true}) {
    double z = 0.0, from = 0.0;  // a first taper or arc starts on the axis
    for (const OutsideStep& s : inside ? part.inside : part.outside) {
      const double zr = z, zl = z - s.length;
      const double d0 = s.kind == StepKind::Cylinder ? s.diameter : std::min(from, s.diameter);
      const double d1 = s.kind == StepKind::Cylinder ? s.diameter : std::max(from, s.diameter);
      if (s.roughness > 0.0) out.push_back(cut::FinishMark{inside, zl, zr, d0, d1, s.roughness});
      z = zl;
      from = s.diameter;
    }
  }
  return out;
}

double spindleRpm(double cuttingSpeed, double diameter) {
  return diameter > 0.0 ? 1000.0 * cuttingSpeed / (M_PI * diameter) : 0.0;
}

}  // namespace klueng::core::design
