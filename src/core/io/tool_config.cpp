#include "klueng/core/io/tool_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <system_error>

#include "io/text_util.h"
#include "klueng/core/io/text_encoding.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/diagnostic_codes.h"

#ifndef KLUENG_SHIPPED_DATA_DIR
#define KLUENG_SHIPPED_DATA_DIR "."
#endif

namespace klueng::core::io {

namespace fs = std::filesystem;
using detail::makeDiagnostic;

namespace {

std::string twoDigits(int n) { return fmt::format("{:02}", n); }

// Decodes a config file's bytes; nullopt (with F104) for binary data.
std::optional<std::string> decodeConfig(std::string_view bytes, const std::string& fileName,
                                        std::vector<Diagnostic>& diags) {
  if (const auto nul = detail::findNulByte(bytes)) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kBinaryFile, nul->line, nul->column, 1, {fileName}));
    return std::nullopt;
  }
  return detail::decodeText(bytes);
}

// Warns once about non-blank lines past the last one the format uses.
void warnAboutExtraLines(const std::vector<std::string_view>& lines, std::size_t used, const std::string& fileName,
                         std::vector<Diagnostic>& diags) {
  for (std::size_t i = used; i < lines.size(); ++i) {
    if (detail::trim(lines[i]).empty()) continue;
    diags.push_back(makeDiagnostic(Severity::Warning, codes::kLinesIgnored, static_cast<int>(i) + 1, 1, 0,
                                   {fileName, std::to_string(used)}));
    return;
  }
}

bool hasImageExtension(std::string_view name) {
  if (name.size() < 5) return false;
  std::string ext(name.substr(name.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".bmp" || ext == ".png";
}

bool hasControlCharacters(std::string_view s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7F;
  });
}

std::string oneConfigLine(std::string_view text) {
  std::string s(text);
  std::replace_if(
      s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return s;
}

std::string folderOf(const std::string& path) {
  const fs::path p(path);
  return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

}  // namespace

// ---------------------------------------------------------------- tools.cfg

std::string ToolTable::bitmapPath(int tool) const {
  if (tool < 1 || tool > kMaxStations) return {};
  const auto i = static_cast<std::size_t>(tool - 1);
  std::string name = bitmap[i];
  if (name.empty()) return {};
  if (name.rfind(kLibraryPrefix, 0) == 0) return libraryPath[i];
#ifndef _WIN32
  // tools.cfg files from the Windows program write folders with backslashes.
  std::replace(name.begin(), name.end(), '\\', '/');
#endif
  const fs::path p(name);
  if (p.is_absolute() || folder.empty()) return name;
  return (fs::path(folder) / p).string();
}

double ToolTable::pixelsPerMmOf(int tool) const {
  if (tool < 1 || tool > kMaxStations) return kSeedPixelsPerMm;
  return pixelsPerMm[static_cast<std::size_t>(tool - 1)];
}

std::string ToolTable::libraryId(int tool) const {
  if (tool < 1 || tool > kMaxStations) return {};
  const std::string& line = bitmap[static_cast<std::size_t>(tool - 1)];
  return line.rfind(kLibraryPrefix, 0) == 0 ? line.substr(kLibraryPrefix.size()) : std::string();
}

void ToolTable::setLibraryTool(int tool, const std::string& id, const std::string& path, double ppm) {
  if (tool < 1 || tool > kMaxStations) return;
  const auto i = static_cast<std::size_t>(tool - 1);
  bitmap[i] = std::string(kLibraryPrefix) + id;
  libraryPath[i] = path;
  pixelsPerMm[i] = ppm;
  bitmapUnreadable[i] = false;
}

ReadResult<ToolTable> parseToolTable(std::string_view text, const std::string& folder, const std::string& fileName,
                                     int stations, const ToolLibrary* library) {
  ReadResult<ToolTable> result;
  auto& diags = result.diagnostics;
  const std::optional<std::string> decoded = decodeConfig(text, fileName, diags);
  if (!decoded) return result;
  const std::vector<std::string_view> lines = detail::splitLines(*decoded);
  stations = std::clamp(stations, 1, kMaxStations);
  if (!library) library = &shippedToolLibrary();

  ToolTable table;
  table.folder = folder;
  table.stations = stations;
  for (int tool = 1; tool <= stations && static_cast<std::size_t>(tool) <= lines.size(); ++tool) {
    const std::string_view line = lines[static_cast<std::size_t>(tool - 1)];
    std::string_view name = detail::trim(line);
    // ` | material=...` after the bitmap or library tool (issue 39).
    if (const std::size_t bar = name.find('|'); bar != std::string_view::npos) {
      const std::string_view option = detail::trim(name.substr(bar + 1));
      name = detail::trim(name.substr(0, bar));
      const std::string_view value = option.rfind("material=", 0) == 0 ? option.substr(9) : std::string_view();
      if (value == "hss" || value == "carbide" || value == "coated-carbide") {
        table.material[static_cast<std::size_t>(tool - 1)] = std::string(value);
      } else {
        diags.push_back(makeDiagnostic(Severity::Error, codes::kToolLineBadOption, tool,
                                       detail::columnOf(line, option.empty() ? name : option), utf8Length(option),
                                       {fileName, twoDigits(tool), std::string(option)}));
      }
    }
    if (name.empty()) continue;  // a tool without a bitmap
    if (name.rfind(kLibraryPrefix, 0) == 0) {
      const std::string_view id = detail::trim(name.substr(kLibraryPrefix.size()));
      const LibraryTool* t = library->find(id);
      if (!t) {
        const std::string_view at = id.empty() ? name : id;
        diags.push_back(makeDiagnostic(Severity::Error, codes::kNotInToolLibrary, tool, detail::columnOf(line, at),
                                       utf8Length(at),
                                       {fileName, twoDigits(tool), std::string(id), library->idList()}));
        continue;
      }
      table.setLibraryTool(tool, t->id, library->bitmapPath(*t), t->pixelsPerMm);
      continue;
    }
    if (hasControlCharacters(name) || !hasImageExtension(name)) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kNotBitmapName, tool, detail::columnOf(line, name),
                                     utf8Length(name), {fileName, twoDigits(tool), std::string(name)}));
      continue;
    }
    table.bitmap[static_cast<std::size_t>(tool - 1)] = std::string(name);
  }
  const int required = std::min(kSeedToolLines, stations);
  if (lines.size() < static_cast<std::size_t>(required)) {
    const int count = static_cast<int>(lines.size());
    diags.push_back(makeDiagnostic(Severity::Error, codes::kToolTableShort, std::max(count, 1), 1, 0,
                                   {fileName, std::to_string(count), twoDigits(count + 1)}));
  }
  warnAboutExtraLines(lines, static_cast<std::size_t>(stations), fileName, diags);
  result.value = std::move(table);
  return result;
}

ReadResult<ToolTable> readToolTable(const std::string& path, int stations, const ToolLibrary* library) {
  ReadResult<ToolTable> result;
  const std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  result = parseToolTable(*bytes, folderOf(path), path, stations, library);
  if (!result.value) return result;
  for (int tool = 1; tool <= kMaxStations; ++tool) {
    const std::string file = result.value->bitmapPath(tool);
    std::error_code ec;
    if (file.empty()) continue;
    const fs::file_status status = fs::status(file, ec);
    if (fs::is_regular_file(status)) continue;
    const std::string& name = result.value->bitmap[static_cast<std::size_t>(tool - 1)];
    const int length = utf8Length(name);
    // Only what is not there is "missing": anything else says what it is.
    const auto notAFile = [&](const std::string& en, const std::string& th) {
      result.diagnostics.push_back(makeDiagnostic(Severity::Error, codes::kBitmapNotAFile, tool, 1, length,
                                                  {path, twoDigits(tool), name, en, th}));
    };
    if (fs::is_directory(status))
      result.diagnostics.push_back(
          makeDiagnostic(Severity::Error, codes::kBitmapIsFolder, tool, 1, length, {path, twoDigits(tool), name}));
    else if (ec == std::errc::too_many_symbolic_link_levels)
      notAFile("a link that leads back to itself (a loop of links)", "ลิงก์ที่วนกลับมาหาตัวเอง (ลิงก์วนซ้ำ)");
    else if (fs::is_character_file(status) || fs::is_block_file(status))
      notAFile("a device", "อุปกรณ์ (device)");
    else if (fs::is_fifo(status))
      notAFile("a pipe (FIFO)", "ไปป์ (FIFO)");
    else if (fs::is_socket(status))
      notAFile("a socket", "ซ็อกเก็ต (socket)");
    else if (std::error_code lec; fs::is_symlink(fs::symlink_status(file, lec))) {
      const std::string target = fs::read_symlink(file, lec).string();
      notAFile(fmt::format("a link to '{}', which does not exist", target),
               fmt::format("ลิงก์ไปยัง '{}' ซึ่งไม่มีอยู่", target));
    } else
      result.diagnostics.push_back(
          makeDiagnostic(Severity::Error, codes::kBitmapMissing, tool, 1, length, {path, twoDigits(tool), name}));
  }
  std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.range.line < b.range.line; });
  return result;
}

std::string formatToolTable(const ToolTable& t) {
  int last = kSeedToolLines;
  for (int i = 0; i < kMaxStations; ++i)
    if (!t.bitmap[static_cast<std::size_t>(i)].empty()) last = std::max(last, i + 1);
  std::string out;
  for (int i = 0; i < last; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out += oneConfigLine(t.bitmap[k]);
    if (!t.material[k].empty() && !t.bitmap[k].empty()) out += " | material=" + oneConfigLine(t.material[k]);
    out += '\n';
  }
  return out;
}

// ---------------------------------------------------------------- offset.cfg

ReadResult<OffsetTable> parseOffsetTable(std::string_view text, const std::string& fileName) {
  ReadResult<OffsetTable> result;
  auto& diags = result.diagnostics;
  const std::optional<std::string> decoded = decodeConfig(text, fileName, diags);
  if (!decoded) return result;
  const std::vector<std::string_view> lines = detail::splitLines(*decoded);

  OffsetTable table;
  for (int number = 1; number <= kOffsetCount && static_cast<std::size_t>(number) <= lines.size(); ++number) {
    const std::string_view line = lines[static_cast<std::size_t>(number - 1)];
    const std::vector<std::string_view> fields = detail::splitFields(line);
    const std::string label = twoDigits(number);
    if (fields.empty()) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kOffsetEmpty, number, 1, 0, {fileName, label}));
      continue;
    }
    if (fields.size() != 4) {
      // Point at the first field too many, or at the end of a short line.
      const int column = fields.size() > 4 ? detail::columnOf(line, fields[4])
                                           : utf8Length(detail::trim(line)) + detail::columnOf(line, fields[0]);
      diags.push_back(makeDiagnostic(Severity::Error, codes::kOffsetFieldCount, number, column, 0,
                                     {fileName, label, std::to_string(fields.size())}));
      continue;
    }
    Offset offset;
    bool rowOk = true;
    double* numbers[3] = {&offset.x, &offset.z, &offset.r};
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> v = detail::parseNumber(fields[static_cast<std::size_t>(i)]);
      if (!v) {
        const std::string_view f = fields[static_cast<std::size_t>(i)];
        diags.push_back(makeDiagnostic(Severity::Error, codes::kOffsetNotNumber, number, detail::columnOf(line, f),
                                       utf8Length(f), {fileName, label, std::string(f)}));
        rowOk = false;
      } else {
        *numbers[i] = *v;
      }
    }
    if (rowOk && offset.r < 0.0) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kNegativeNoseRadius, number,
                                     detail::columnOf(line, fields[2]), utf8Length(fields[2]),
                                     {fileName, label, std::string(fields[2])}));
      rowOk = false;
    }
    // A wear or geometry offset beyond any lathe's (1e308 once passed here) is a typing slip.
    constexpr double kMaxOffsetMm = 1000.0, kMaxNoseRadiusMm = 50.0;
    for (int i = 0; rowOk && i < 3; ++i) {
      const double limit = i == 2 ? kMaxNoseRadiusMm : kMaxOffsetMm;
      if (std::abs(*numbers[i]) > limit) {
        const std::string_view f = fields[static_cast<std::size_t>(i)];
        diags.push_back(makeDiagnostic(Severity::Error, codes::kOffsetBeyondLathe, number, detail::columnOf(line, f),
                                       utf8Length(f), {fileName, label, std::string(f), detail::formatNumber(limit)}));
        rowOk = false;
      }
    }
    const std::string_view tip = fields[3];
    if (tip.size() != 1 || tip[0] < '0' || tip[0] > '9') {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kBadTipNumber, number, detail::columnOf(line, tip),
                                     utf8Length(tip), {fileName, label, std::string(tip)}));
      rowOk = false;
    } else {
      offset.tip = tip[0] - '0';
    }
    // A row with any error stays 0 0 0 0 rather than half read.
    if (rowOk) table.offsets[static_cast<std::size_t>(number - 1)] = offset;
  }
  if (lines.size() < static_cast<std::size_t>(kSeedOffsetLines)) {
    const int count = static_cast<int>(lines.size());
    diags.push_back(makeDiagnostic(Severity::Error, codes::kOffsetTableShort, std::max(count, 1), 1, 0,
                                   {fileName, std::to_string(count), twoDigits(count + 1)}));
  }
  warnAboutExtraLines(lines, kOffsetCount, fileName, diags);
  std::stable_sort(diags.begin(), diags.end(),
                   [](const Diagnostic& a, const Diagnostic& b) { return a.range.line < b.range.line; });
  result.value = table;
  return result;
}

ReadResult<OffsetTable> readOffsetTable(const std::string& path) {
  ReadResult<OffsetTable> result;
  const std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  return parseOffsetTable(*bytes, path);
}

std::string formatOffsetTable(const OffsetTable& t) {
  int last = kSeedOffsetLines;
  for (int i = 0; i < kOffsetCount; ++i) {
    const Offset& o = t.offsets[static_cast<std::size_t>(i)];
    if (o.x != 0.0 || o.z != 0.0 || o.r != 0.0 || o.tip != 0) last = std::max(last, i + 1);
  }
  std::string out;
  for (int i = 0; i < last; ++i) {
    const Offset& o = t.offsets[static_cast<std::size_t>(i)];
    out += fmt::format("{} {} {} {}\n", detail::formatNumber(o.x), detail::formatNumber(o.z), detail::formatNumber(o.r),
                       std::clamp(o.tip, 0, 9));
  }
  return out;
}

// ---------------------------------------------------------------- machine.cfg

namespace {

enum class Rule { Any, Positive, NonNegative, Stations, Count, Flag };

struct MachineKey {
  const char* name;
  double MachineConfig::*field;  // nullptr: a whole-number field (count)
  Rule rule;
  const char* comment;
  int MachineConfig::*count = nullptr;
  bool MachineConfig::*flag = nullptr;  // Rule::Flag: 0 or 1
};

// Values no lathe has (rapid_x = 1e-300, max_spindle_rpm = 1e308 once passed): F148.
// `zeroIsOff`: 0 is allowed too (accel_x = 0 turns acceleration off), but nothing between 0 and min
// (accel_x = 1e-320 made every move last for ever: a cycle time of inf; issue 42 item 6).
struct Plausible {
  const char* name;
  double min, max;
  bool zeroIsOff = false;
};
constexpr Plausible kPlausible[] = {
    {"rapid_x", 1.0, 200000.0},
    {"rapid_z", 1.0, 200000.0},
    {"accel_x", 1.0, 100000.0, true},
    {"accel_z", 1.0, 100000.0, true},
    {"max_spindle_rpm", 1.0, 100000.0},
    {"spindle_power_kw", 0.0, 10000.0},
    {"spindle_torque_nm", 0.0, 1000000.0},
    {"chuck_max_rpm", 0.0, 100000.0},
    {"reference_x", -100000.0, 100000.0},
    {"reference_z", -100000.0, 100000.0},
    {"start_x", -100000.0, 100000.0},
    {"start_z", -100000.0, 100000.0},
    {"travel_x_min", -100000.0, 100000.0},
    {"travel_x_max", -100000.0, 100000.0},
    {"travel_z_min", -100000.0, 100000.0},
    {"travel_z_max", -100000.0, 100000.0},
    {"chuck_grip", 0.0, 10000.0},
    {"chuck_jaw_height", 0.0, 10000.0},
    {"spindle_bore", 0.0, 10000.0},
    {"max_run_time", 1.0, 1.0e7},
};

constexpr int kMinTurretStations = 1;
constexpr int kMaxTurretStations = 24;
constexpr int kMaxBlockLimit = 100000000;

constexpr MachineKey kMachineKeys[] = {
    {"rapid_x", &MachineConfig::rapidX, Rule::Positive, "X rapid rate, mm/min (radial)"},
    {"rapid_z", &MachineConfig::rapidZ, Rule::Positive, "Z rapid rate, mm/min"},
    {"accel_x", &MachineConfig::accelX, Rule::NonNegative,
     "X acceleration, mm/s^2 (radial); 0 = moves start and stop at once"},
    {"accel_z", &MachineConfig::accelZ, Rule::NonNegative, "Z acceleration, mm/s^2; 0 = off"},
    {"max_spindle_rpm", &MachineConfig::maxSpindleRpm, Rule::Positive, "maximum spindle speed, rpm"},
    {"spindle_power_kw", &MachineConfig::spindlePowerKw, Rule::NonNegative,
     "spindle motor power, kW (cutting-data warnings, docs/cutting-data.md); 0 = not known"},
    {"spindle_torque_nm", &MachineConfig::spindleTorqueNm, Rule::NonNegative,
     "largest spindle torque, N*m; 0 = not known"},
    {"chuck_max_rpm", &MachineConfig::chuckMaxRpm, Rule::NonNegative,
     "highest speed the chuck is rated for, rpm (on its body or in its manual); 0 = not known"},
    {"reference_x", &MachineConfig::referenceX, Rule::Any, "reference point X (diameter), G27/G28/G29"},
    {"reference_z", &MachineConfig::referenceZ, Rule::Any, "reference point Z"},
    {"start_x", &MachineConfig::startX, Rule::Any, "tool start position X (diameter)"},
    {"start_z", &MachineConfig::startZ, Rule::Any, "tool start position Z"},
    {"travel_x_min", &MachineConfig::travelXMin, Rule::Any, "travel limits, X as diameter"},
    {"travel_x_max", &MachineConfig::travelXMax, Rule::Any, nullptr},
    {"travel_z_min", &MachineConfig::travelZMin, Rule::Any, "travel limits, Z"},
    {"travel_z_max", &MachineConfig::travelZMax, Rule::Any, nullptr},
    {"chuck_grip", &MachineConfig::chuckGrip, Rule::NonNegative, "length of stock held by the chuck jaws, mm"},
    {"chuck_jaw_height", &MachineConfig::chuckJawHeight, Rule::NonNegative,
     "radial height of the jaws above the stock, mm"},
    {"spindle_bore", &MachineConfig::spindleBore, Rule::NonNegative,
     "through-hole of the spindle and chuck (diameter, mm): drills may pass the part's end into it"},
    {"turret_stations", nullptr, Rule::Stations, "tool stations on the turret (1 to 24)",
     &MachineConfig::turretStations},
    {"max_blocks", nullptr, Rule::Count,
     "a run stops after this many blocks run again by a loop, jump or call (a loop proven endless stops before)",
     &MachineConfig::maxBlocks},
    {"max_run_time", &MachineConfig::maxRunTime, Rule::Positive,
     "... or, once blocks run again, after this much simulated machining time, seconds\n"
     "# (a program that runs no block twice ends by itself and is never stopped by the clock)"},
    {"tools_beyond_centre", nullptr, Rule::Flag,
     "1 = the tools work beyond the centre line (a rear tool post, programmed in X < 0): drawn and cut\n"
     "# mirrored onto the front; a program without Klueng's header is read as its own moves show",
     nullptr, &MachineConfig::toolsBeyondCentre},
    {"calculator_input", nullptr, Rule::Flag,
     "a length without a decimal point: 1 = whole mm or inches (X30 = 30 mm, calculator-type input);\n"
     "# 0 = least input increments (X30 = 0.030 mm, 0.0030 in), as a standard Fanuc (parameter 3401#0)\n"
     "# or Haas (setting 162 off); a program without Klueng's header is read as its own numbers show",
     nullptr, &MachineConfig::calculatorInput},
};

}  // namespace

ReadResult<MachineConfig> parseMachineConfig(std::string_view text, const std::string& fileName) {
  ReadResult<MachineConfig> result;
  auto& diags = result.diagnostics;
  const std::optional<std::string> decoded = decodeConfig(text, fileName, diags);
  if (!decoded) return result;
  const std::vector<std::string_view> lines = detail::splitLines(*decoded);

  MachineConfig config;
  std::map<std::string, int> lineOfKey;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int lineNumber = static_cast<int>(i) + 1;
    if (detail::configProblemsFull(diags, fileName, lineNumber)) break;
    const std::string_view line = lines[i];
    std::string_view content = line.substr(0, std::min(line.find('#'), line.size()));
    content = detail::trim(content);
    if (content.empty()) continue;
    const std::size_t eq = content.find('=');
    if (eq == std::string_view::npos) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kNotKeyValue, lineNumber, detail::columnOf(line, content),
                                     utf8Length(content), {fileName}));
      continue;
    }
    const std::string_view key = detail::trim(content.substr(0, eq));
    const std::string_view value = detail::trim(content.substr(eq + 1));
    if (key.empty()) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kNotKeyValue, lineNumber, detail::columnOf(line, content),
                                     utf8Length(content), {fileName}));
      continue;
    }
    const MachineKey* entry = nullptr;
    for (const MachineKey& k : kMachineKeys)
      if (key == k.name) entry = &k;
    if (!entry) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kUnknownParameter, lineNumber, detail::columnOf(line, key),
                                     utf8Length(key), {fileName, std::string(key)}));
      continue;
    }
    const int valueColumn =
        value.empty() ? detail::columnOf(line, content) + utf8Length(content) : detail::columnOf(line, value);
    const std::optional<double> number = detail::parseNumber(value);
    if (!number) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kParameterNotNumber, lineNumber, valueColumn,
                                     utf8Length(value), {fileName, std::string(key), std::string(value)}));
      continue;
    }
    if (entry->rule == Rule::Positive && *number <= 0.0) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kParameterNotPositive, lineNumber, valueColumn,
                                     utf8Length(value), {fileName, std::string(key), std::string(value)}));
      continue;
    }
    if (entry->rule == Rule::NonNegative && *number < 0.0) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kParameterNegative, lineNumber, valueColumn,
                                     utf8Length(value), {fileName, std::string(key), std::string(value)}));
      continue;
    }
    if (entry->rule == Rule::Flag && *number != 0.0 && *number != 1.0) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kParameterNotWhole, lineNumber, valueColumn,
                                     utf8Length(value), {fileName, std::string(key), std::string(value), "0", "1"}));
      continue;
    }
    const bool stations = entry->rule == Rule::Stations;
    if ((stations || entry->rule == Rule::Count) &&
        (*number != std::floor(*number) || *number < (stations ? kMinTurretStations : 1) ||
         *number > (stations ? kMaxTurretStations : kMaxBlockLimit))) {
      diags.push_back(makeDiagnostic(
          Severity::Error, codes::kParameterNotWhole, lineNumber, valueColumn, utf8Length(value),
          {fileName, std::string(key), std::string(value), std::to_string(stations ? kMinTurretStations : 1),
           std::to_string(stations ? kMaxTurretStations : kMaxBlockLimit)}));
      continue;
    }
    bool plausible = true;
    for (const Plausible& p : kPlausible)
      if (key == p.name && (*number < p.min || *number > p.max) && !(p.zeroIsOff && *number == 0.0)) {
        const std::string min = detail::formatNumber(p.min);
        diags.push_back(
            makeDiagnostic(Severity::Error, codes::kParameterOutOfRange, lineNumber, valueColumn, utf8Length(value),
                           {fileName, std::string(key), std::string(value), p.zeroIsOff ? "0 (off) or " + min : min,
                            detail::formatNumber(p.max), p.zeroIsOff ? "0 (ปิด) หรือ " + min : min}));
        plausible = false;
      }
    if (!plausible) continue;
    if (lineOfKey.count(entry->name))
      diags.push_back(makeDiagnostic(Severity::Warning, codes::kParameterTwice, lineNumber, detail::columnOf(line, key),
                                     utf8Length(key), {fileName, std::string(key)}));
    lineOfKey[entry->name] = lineNumber;
    if (entry->field)
      config.*(entry->field) = *number;
    else if (entry->flag)
      config.*(entry->flag) = *number != 0.0;
    else
      config.*(entry->count) = static_cast<int>(*number);
  }

  // An empty machine.cfg (or only comments) is not what anyone meant to write: say the defaults apply.
  if (lineOfKey.empty() && !hasErrors(diags))
    diags.push_back(makeDiagnostic(Severity::Warning, codes::kNoMachineParameters, 0, 0, 0, {fileName}));

  const auto checkRange = [&](const char* minKey, double MachineConfig::*min, const char* maxKey,
                              double MachineConfig::*max) {
    if (config.*min < config.*max) return;
    const int line =
        std::max(lineOfKey.count(minKey) ? lineOfKey[minKey] : 0, lineOfKey.count(maxKey) ? lineOfKey[maxKey] : 0);
    diags.push_back(makeDiagnostic(Severity::Error, codes::kTravelLimitsReversed, line, line ? 1 : 0, 0,
                                   {fileName, minKey, maxKey}));
    MachineConfig defaults;
    config.*min = defaults.*min;
    config.*max = defaults.*max;
  };
  checkRange("travel_x_min", &MachineConfig::travelXMin, "travel_x_max", &MachineConfig::travelXMax);
  checkRange("travel_z_min", &MachineConfig::travelZMin, "travel_z_max", &MachineConfig::travelZMax);

  // The tool starts inside the travel limits, or every program would be blamed for the machine's slip.
  const auto inside = [&](const char* key, double MachineConfig::*v, double lo, double hi) {
    if (config.*v >= lo && config.*v <= hi) return;
    const int line = lineOfKey.count(key) ? lineOfKey[key] : 0;
    diags.push_back(makeDiagnostic(
        Severity::Error, codes::kStartOutsideTravel, line, line ? 1 : 0, 0,
        {fileName, key, detail::formatNumber(config.*v), detail::formatNumber(lo), detail::formatNumber(hi)}));
  };
  inside("start_x", &MachineConfig::startX, config.travelXMin, config.travelXMax);
  inside("start_z", &MachineConfig::startZ, config.travelZMin, config.travelZMax);

  result.value = config;
  return result;
}

ReadResult<MachineConfig> readMachineConfig(const std::string& path) {
  ReadResult<MachineConfig> result;
  const std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  return parseMachineConfig(*bytes, path);
}

std::string formatMachineConfig(const MachineConfig& m) {
  std::string out =
      "# Klueng machine parameters: key = value, '#' starts a comment.\n"
      "# X values are diameters; lengths in mm, rates in mm/min.\n";
  for (const MachineKey& k : kMachineKeys) {
    if (k.comment) out += fmt::format("\n# {}\n", k.comment);
    out += fmt::format("{} = {}\n", k.name,
                       k.field  ? detail::formatNumber(m.*(k.field))
                       : k.flag ? std::string(m.*(k.flag) ? "1" : "0")
                                : std::to_string(m.*(k.count)));
  }
  return out;
}

// ---------------------------------------------------------------- folders

std::string installedDataDir(const std::string& executable) {
  if (executable.empty()) return {};
  // <prefix>/bin/klueng -> <prefix>/share/klueng
  const fs::path share = fs::path(executable).parent_path().parent_path() / "share" / "klueng";
  std::error_code ec;
  return fs::is_regular_file(share / "tools.cfg", ec) ? share.string() : std::string();
}

std::string shippedConfigDir() {
  // An installed Klueng finds its data beside its own bin/ (a package unpacked
  // anywhere works); only a program run from the build tree uses the sources.
  static const std::string dir = [] {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    const std::string installed = ec ? std::string() : installedDataDir(self.string());
    return installed.empty() ? std::string(KLUENG_SHIPPED_DATA_DIR) : installed;
  }();
  return dir;
}

std::string shippedCuttingSpeedsPath() {
  return (fs::path(shippedConfigDir()) / "resources" / "parts" / "cutting_speeds.cfg").string();
}

std::string samplesDir(const std::string& shippedDir) {
  if (shippedDir.empty()) return {};
  std::error_code ec;
  for (const fs::path& dir : {fs::path(shippedDir) / "samples", fs::path(shippedDir) / "resources" / "samples"})
    if (fs::is_directory(dir, ec)) return dir.string();
  return {};
}

std::string userConfigDir() {
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg && *xdg && fs::path(xdg).is_absolute())
    return (fs::path(xdg) / "klueng").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".local" / "share" / "klueng").string();
  return {};
}

std::string findConfigDir(const std::string& explicitDir) {
  if (!explicitDir.empty()) return explicitDir;
  if (const char* env = std::getenv("KLUENG_DATA_DIR"); env && *env) return env;
  const std::string user = userConfigDir();
  std::error_code ec;
  if (!user.empty() && fs::is_regular_file(fs::path(user) / "tools.cfg", ec)) return user;
  return shippedConfigDir();
}

std::string ensureUserConfigDir(std::string* error) {
  const auto fail = [&](const std::string& what) {
    if (error) *error = what;
    return std::string();
  };
  const std::string user = userConfigDir();
  if (user.empty()) return fail("neither XDG_DATA_HOME nor HOME is set");
  const fs::path userDir(user);
  const fs::path shipped(shippedConfigDir());
  std::error_code ec;
  fs::create_directories(userDir, ec);
  if (ec) return fail(user + ": " + ec.message());

  // Copy only what is missing: the user's own edits are never overwritten.
  const auto copyIfMissing = [&](const fs::path& relative) -> bool {
    const fs::path to = userDir / relative;
    const fs::path from = shipped / relative;
    std::error_code e;
    if (fs::exists(to, e) || !fs::is_regular_file(from, e)) return true;
    if (to.has_parent_path()) fs::create_directories(to.parent_path(), e);
    fs::copy_file(from, to, e);
    if (e) {
      if (error) *error = to.string() + ": " + e.message();
      return false;
    }
    // The shipped files may be read-only; the per-user copy must be writable.
    fs::permissions(to, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::add, e);
    return true;
  };
  for (const char* name : {"tools.cfg", "offset.cfg", "machine.cfg"})
    if (!copyIfMissing(name)) return {};

  // The bitmaps named by the shipped tools.cfg, kept at the same relative paths.
  const ReadResult<ToolTable> shippedTools = readToolTable((shipped / "tools.cfg").string());
  if (shippedTools.value)
    for (const std::string& name : shippedTools.value->bitmap)
      if (!name.empty() && name.rfind(kLibraryPrefix, 0) != 0 && fs::path(name).is_relative() && !copyIfMissing(name))
        return {};
  return user;
}

}  // namespace klueng::core::io
