// What a folder run may read (folder_files.h).
#include "klueng/core/io/folder_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "io/text_util.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/program_file.h"

namespace klueng::core::io {

namespace {

namespace fs = std::filesystem;
using detail::makeDiagnostic;

Diagnostic fileError(const char* code, std::vector<std::string> args) {
  return makeDiagnostic(Severity::Error, code, 0, 0, 0, std::move(args));
}

// `inner` lies in `outer` (both canonical): every element of outer starts inner.
bool within(const fs::path& inner, const fs::path& outer) {
  auto o = outer.begin();
  auto i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// A line that a control reads as a block: a word (letter and a number, a sign,
// a point, `#` or `[`), a macro assignment `#1=`, or IF/WHILE/GOTO/END/DO.
bool looksLikeBlock(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && (isSpace(line[i]) || line[i] == '/')) ++i;
  if (i >= line.size()) return false;
  const auto upper = [](char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); };
  const char c = upper(line[i]);
  if (c == '#') return i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1]));
  if (c < 'A' || c > 'Z') return false;
  for (const std::string_view keyword : {"IF", "WHILE", "GOTO", "END", "DO"}) {
    const std::string_view rest = line.substr(i);
    if (rest.size() >= keyword.size() &&
        std::equal(keyword.begin(), keyword.end(), rest.begin(), [&](char k, char r) { return k == upper(r); }))
      return true;
  }
  std::size_t j = i + 1;
  while (j < line.size() && isSpace(line[j])) ++j;
  if (j >= line.size()) return false;
  const char n = line[j];
  return std::isdigit(static_cast<unsigned char>(n)) || n == '-' || n == '+' || n == '.' || n == '#' || n == '[';
}

// A line that holds nothing a control reads: blank, `%`, a comment.
bool isCommentOnly(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && isSpace(line[i])) ++i;
  return i >= line.size() || line[i] == '%' || line[i] == '(' || line[i] == ';';
}

}  // namespace

bool insideFolder(const std::string& path, const std::string& folder) {
  std::error_code ec;
  const fs::path target = fs::canonical(path, ec);
  if (ec) return false;
  const fs::path root = fs::canonical(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  return !ec && within(target, root);
}

std::vector<FolderEntry> programFolderEntries(const std::string& folder) {
  std::vector<FolderEntry> entries;
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    const fs::path& p = it->path();
    if (!isProgramFileName(p.string())) continue;
    FolderEntry e{p.string(), p.filename().string(), FolderEntryKind::Program};
    std::error_code sec;
    const bool link = it->is_symlink(sec);
    const fs::file_status target = fs::status(p, sec);  // follows a link
    if (!fs::exists(target))
      e.kind = FolderEntryKind::Dangling;
    else if (link && !insideFolder(e.path, folder))
      e.kind = FolderEntryKind::OutsideFolder;  // decided before its kind: nothing about it is said
    else if (fs::is_directory(target))
      e.kind = FolderEntryKind::Folder;
    else if (!fs::is_regular_file(target))
      e.kind = FolderEntryKind::NotAFile;
    entries.push_back(std::move(e));
  }
  std::sort(entries.begin(), entries.end(), [](const FolderEntry& a, const FolderEntry& b) { return a.path < b.path; });
  return entries;
}

std::optional<Diagnostic> folderEntryRefusal(const FolderEntry& entry) {
  switch (entry.kind) {
    case FolderEntryKind::Program: return std::nullopt;
    case FolderEntryKind::OutsideFolder: return fileError(codes::kOutsideFolder, {entry.path});
    case FolderEntryKind::Folder: return fileError(codes::kCannotReadFile, {entry.path});
    case FolderEntryKind::Dangling: return fileError(codes::kNoSuchFile, {entry.path});
    case FolderEntryKind::NotAFile: {
      if (std::optional<Diagnostic> d = notAnOrdinaryFile(entry.path)) return d;
      return fileError(codes::kCannotReadFile, {entry.path});
    }
  }
  return std::nullopt;
}

std::optional<Diagnostic> notAGcodeProgram(std::string_view gcode, const std::string& fileName) {
  // Binary data: control characters a text editor never writes (tab, line ends, form feed and
  // DOS's end-of-file mark aside), looked for in the first 64 KiB.
  const std::string_view probe = gcode.substr(0, 64 * 1024);
  const auto control = std::count_if(probe.begin(), probe.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\f' && c != '\v' && c != 0x1a) || c == 0x7f;
  });
  if (control > 4) return fileError(codes::kNotAProgram, {fileName, "binary data", "ข้อมูลไบนารี"});
  int lines = 0;
  bool anyText = false;
  for (std::size_t start = 0; start < gcode.size() && lines < kGcodeProbeLines;) {
    std::size_t end = gcode.find('\n', start);
    if (end == std::string_view::npos) end = gcode.size();
    const std::string_view line = gcode.substr(start, end - start);
    start = end + 1;
    if (isCommentOnly(line)) continue;
    anyText = true;
    if (looksLikeBlock(line)) return std::nullopt;
    ++lines;
  }
  if (!anyText) return std::nullopt;  // blank or comments only: the checker has its own words for it
  return fileError(codes::kNotAProgram,
                   {fileName, "no G-code in its first " + std::to_string(kGcodeProbeLines) + " lines",
                    "ไม่มี G-code ใน " + std::to_string(kGcodeProbeLines) + " บรรทัดแรก"});
}

}  // namespace klueng::core::io
