#include "klueng/core/io/tool_library.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <map>
#include <utility>

#include "io/text_util.h"
#include "klueng/core/io/text_encoding.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::io {

namespace fs = std::filesystem;
using detail::makeDiagnostic;

namespace {

constexpr std::array<std::pair<ToolKind, std::string_view>, 9> kKindIds = {{
    {ToolKind::Unknown, "unknown"},
    {ToolKind::Turning, "turning"},
    {ToolKind::ThreadingOd, "threading-od"},
    {ToolKind::ThreadingId, "threading-id"},
    {ToolKind::Grooving, "grooving"},
    {ToolKind::Parting, "parting"},
    {ToolKind::CentreDrill, "centre-drill"},
    {ToolKind::Drill, "drill"},
    {ToolKind::Boring, "boring"},
}};

constexpr std::size_t kFieldCount = 9;

bool isToolId(std::string_view id) {
  if (id.empty() || id.size() > 40) return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_';
  });
}

std::string kindList() {
  std::string s;
  for (const auto& [kind, id] : kKindIds) {
    if (kind == ToolKind::Unknown) continue;
    if (!s.empty()) s += ", ";
    s += id;
  }
  return s;
}

// Fields split at '|', each trimmed; views into `line`.
std::vector<std::string_view> splitBars(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t bar = line.find('|', start);
    const std::string_view raw =
        line.substr(start, bar == std::string_view::npos ? std::string_view::npos : bar - start);
    std::string_view field = detail::trim(raw);
    if (field.empty()) field = raw.substr(0, 0);  // keep the position for the column
    out.push_back(field);
    if (bar == std::string_view::npos) break;
    start = bar + 1;
  }
  return out;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

std::string_view toolKindId(ToolKind kind) {
  for (const auto& [k, id] : kKindIds)
    if (k == kind) return id;
  return "unknown";
}

bool parseToolKindId(std::string_view id, ToolKind& out) {
  for (const auto& [k, name] : kKindIds)
    if (name == id && k != ToolKind::Unknown) {
      out = k;
      return true;
    }
  return false;
}

const LibraryTool* ToolLibrary::find(std::string_view id) const {
  for (const LibraryTool& t : tools)
    if (t.id == id) return &t;
  return nullptr;
}

std::string ToolLibrary::bitmapPath(const LibraryTool& tool) const {
  const fs::path p(tool.bitmap);
  if (p.is_absolute() || folder.empty()) return tool.bitmap;
  return (fs::path(folder) / p).string();
}

std::string ToolLibrary::idList() const {
  std::string s;
  for (const LibraryTool& t : tools) {
    if (!s.empty()) s += ", ";
    s += t.id;
  }
  return s;
}

ReadResult<ToolLibrary> parseToolLibrary(std::string_view text, const std::string& folder,
                                         const std::string& fileName) {
  ReadResult<ToolLibrary> result;
  auto& diags = result.diagnostics;
  if (const auto nul = detail::findNulByte(text)) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kBinaryFile, nul->line, nul->column, 1, {fileName}));
    return result;
  }
  const std::string decoded = detail::decodeText(text);
  const std::vector<std::string_view> lines = detail::splitLines(decoded);
  ToolLibrary library;
  library.folder = folder;
  std::map<std::string, int> lineOfId;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int lineNo = static_cast<int>(i) + 1;
    if (detail::configProblemsFull(diags, fileName, lineNo)) break;
    const std::string_view line = lines[i];
    const std::string_view content = detail::trim(line);
    if (content.empty() || content.front() == '#') continue;
    const std::vector<std::string_view> f = splitBars(line);
    const auto error = [&](const char* code, std::string_view at, std::vector<std::string> args) {
      args.insert(args.begin(), fileName);
      diags.push_back(
          makeDiagnostic(Severity::Error, code, lineNo, detail::columnOf(line, at), utf8Length(at), std::move(args)));
    };
    if (f.size() != kFieldCount && f.size() != kFieldCount + 1) {
      error(codes::kLibraryLineFields, content, {std::to_string(f.size())});
      continue;
    }
    LibraryTool tool;
    bool ok = true;
    if (!isToolId(f[0])) {
      error(codes::kBadToolId, f[0], {std::string(f[0])});
      ok = false;
    } else if (const auto it = lineOfId.find(std::string(f[0])); it != lineOfId.end()) {
      error(codes::kDuplicateToolId, f[0], {std::string(f[0]), std::to_string(it->second)});
      ok = false;
    }
    tool.id = std::string(f[0]);
    if (!parseToolKindId(f[1], tool.kind)) {
      error(codes::kBadToolKind, f[1], {std::string(f[1]), kindList()});
      ok = false;
    }
    const std::optional<double> ppm = detail::parseNumber(f[2]);
    if (!ppm || *ppm < 1.0 || *ppm > 100.0) {
      error(codes::kBadPixelsPerMm, f[2], {std::string(f[2])});
      ok = false;
    } else {
      tool.pixelsPerMm = *ppm;
    }
    const auto nonNegative = [&](std::string_view field, const char* what, double& out) {
      const std::optional<double> v = detail::parseNumber(field);
      if (!v || *v < 0.0) {
        error(codes::kLibraryNumberNegative, field, {what, std::string(field)});
        ok = false;
      } else {
        out = *v;
      }
    };
    nonNegative(f[3], "R", tool.noseRadius);
    if (f[4].size() != 1 || f[4][0] < '0' || f[4][0] > '9') {
      error(codes::kLibraryBadTip, f[4], {std::string(f[4])});
      ok = false;
    } else {
      tool.tip = f[4][0] - '0';
    }
    nonNegative(f[5], "size", tool.size);
    const std::string ext = f[6].size() > 4 ? lower(f[6].substr(f[6].size() - 4)) : std::string();
    if (ext != ".bmp" && ext != ".png") {
      error(codes::kLibraryNotBitmapName, f[6], {std::string(f[6])});
      ok = false;
    }
    tool.bitmap = std::string(f[6]);
    if (f[7].empty() || f[8].empty()) {
      error(codes::kToolNeedsNames, f[7].empty() ? f[7] : f[8], {});
      ok = false;
    }
    tool.nameEn = std::string(f[7]);
    tool.nameTh = std::string(f[8]);
    if (f.size() > kFieldCount) {
      std::string_view rest = detail::trim(f[kFieldCount]);
      while (!rest.empty()) {
        const std::size_t space = rest.find_first_of(" \t");
        const std::string_view word = rest.substr(0, space);
        rest = space == std::string_view::npos ? std::string_view() : detail::trim(rest.substr(space));
        const std::size_t eq = word.find('=');
        const std::string_view key = word.substr(0, eq);
        const std::string_view value = eq == std::string_view::npos ? std::string_view() : word.substr(eq + 1);
        const std::optional<double> number = detail::parseNumber(value);
        if (key == "material" && (value == "hss" || value == "carbide" || value == "coated-carbide")) {
          tool.material = std::string(value);
        } else if (key == "edge" && number && *number >= 0.0) {
          tool.edge = *number;
        } else {
          error(codes::kLibraryBadOption, word, {std::string(word)});
          ok = false;
        }
      }
    }
    if (!ok) continue;
    lineOfId.emplace(tool.id, lineNo);
    tool.line = lineNo;
    library.tools.push_back(std::move(tool));
  }
  result.value = std::move(library);
  return result;
}

ReadResult<ToolLibrary> readToolLibrary(const std::string& path) {
  ReadResult<ToolLibrary> result;
  const std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics);
  if (!bytes) return result;
  const fs::path p(path);
  result = parseToolLibrary(*bytes, p.has_parent_path() ? p.parent_path().string() : std::string("."), path);
  if (!result.value) return result;
  for (const LibraryTool& t : result.value->tools) {
    std::error_code ec;
    if (!fs::is_regular_file(result.value->bitmapPath(t), ec))
      result.diagnostics.push_back(makeDiagnostic(Severity::Error, codes::kLibraryBitmapMissing, t.line, 1,
                                                  utf8Length(t.id), {path, t.id, t.bitmap}));
  }
  return result;
}

std::string shippedToolLibraryPath() {
  return (fs::path(shippedConfigDir()) / "resources" / "tools" / "library" / "library.cfg").string();
}

const ToolLibrary& shippedToolLibrary() {
  static const ToolLibrary library = [] {
    ReadResult<ToolLibrary> r = readToolLibrary(shippedToolLibraryPath());
    return r.value ? std::move(*r.value) : ToolLibrary{};
  }();
  return library;
}

ToolKind guessToolKind(std::string_view fileName) {
  const std::string name = lower(fs::path(std::string(fileName)).filename().string());
  const auto has = [&](std::string_view w) { return name.find(w) != std::string::npos; };
  const bool inside = has("inside") || has("internal") || has("-id") || has("_id") || has("boring");
  if (has("thread")) return inside ? ToolKind::ThreadingId : ToolKind::ThreadingOd;
  if (has("parting") || has("cut-off") || has("cutoff")) return ToolKind::Parting;
  if (has("groov")) return ToolKind::Grooving;
  if (has("centre-drill") || has("center-drill") || has("centre_drill") || has("center_drill"))
    return ToolKind::CentreDrill;
  if (has("drill")) return ToolKind::Drill;
  if (has("boring") || has("bore")) return ToolKind::Boring;
  if (has("turning") || has("cnmg") || has("dnmg") || has("vnmg") || has("facing")) return ToolKind::Turning;
  return ToolKind::Unknown;
}

bool toolKindFits(ToolKind have, ToolKind want) {
  if (have == ToolKind::Unknown || want == ToolKind::Unknown || have == want) return true;
  const auto blade = [](ToolKind k) { return k == ToolKind::Grooving || k == ToolKind::Parting; };
  const auto drill = [](ToolKind k) { return k == ToolKind::Drill || k == ToolKind::CentreDrill; };
  return (blade(have) && blade(want)) || (drill(have) && drill(want));
}

}  // namespace klueng::core::io
