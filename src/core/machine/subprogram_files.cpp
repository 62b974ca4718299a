// Subprogram files from the program's folder (subprogram_files.h).
#include "klueng/core/machine/subprogram_files.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <system_error>

#include <fmt/format.h>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/gcode/program_index.h"
#include "klueng/core/io/folder_files.h"
#include "klueng/core/io/program_file.h"

namespace klueng::core::machine {

namespace {

namespace fs = std::filesystem;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The names a control's program O<number> may have on disk, in order of preference.
std::vector<std::string> candidateNames(int number) {
  std::vector<std::string> stems{fmt::format("o{}", number), fmt::format("{}", number)};
  for (int width : {4, 5}) {
    const std::string padded = fmt::format("{:0{}d}", number, width);
    if (padded != fmt::format("{}", number)) {
      stems.push_back("o" + padded);
      stems.push_back(padded);
    }
  }
  std::vector<std::string> names;
  for (const char* ext : {".nc", "", ".txt", ".tap", ".cnc"})
    for (const std::string& stem : stems) names.push_back(stem + ext);
  return names;
}

struct FolderEntry {
  std::string lowerName;
  std::string path;
  bool regular = false;  // a file that can be read as a program (else a folder, a pipe, a device...)
  bool folder = false;
};

// The folder's entries by lower-case name (so O1000.NC and o1000.nc both match).
std::vector<FolderEntry> folderFiles(const std::string& folder) {
  std::vector<FolderEntry> files;
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::error_code fec;
    const bool regular = it->is_regular_file(fec);
    files.push_back(
        {lower(it->path().filename().string()), it->path().string(), regular, !regular && it->is_directory(fec)});
    if (files.size() > 100000) break;
  }
  std::sort(files.begin(), files.end(),
            [](const FolderEntry& a, const FolderEntry& b) { return a.lowerName < b.lowerName; });
  return files;
}

void shiftExpressions(gcode::Block& b, int offset) {
  for (gcode::Word& w : b.words)
    if (w.expr >= 0) w.expr += offset;
  const gcode::Statement& read = b.statement();
  if (read.condition < 0 && read.target < 0 && read.value < 0) return;  // (most blocks: no notes to make)
  gcode::Statement& s = b.editStatement();
  if (s.condition >= 0) s.condition += offset;
  if (s.target >= 0) s.target += offset;
  if (s.value >= 0) s.value += offset;
}

}  // namespace

std::vector<Diagnostic> attachSubprogramFiles(gcode::Program& program, const std::string& folder,
                                              gcode::Dialect dialect) {
  std::vector<Diagnostic> diagnostics;
  std::vector<FolderEntry> files;  // read once, when a call needs it
  bool listed = false;
  std::set<std::string> attached;
  for (int round = 0; round < kMaxSubprogramFiles; ++round) {
    const auto called = gcode::calledPrograms(program, dialect);
    if (called.empty()) break;  // most programs call nothing: no index to build
    const gcode::ProgramIndex index(program);
    std::vector<int> missing;
    for (int n : called)
      if (!index.program(n)) missing.push_back(n);
    if (missing.empty()) break;
    if (!listed) {
      files = folderFiles(folder);
      listed = true;
    }
    bool added = false;
    for (int number : missing) {
      if (static_cast<int>(program.files.size()) > kMaxSubprogramFiles) break;
      std::string path;
      const FolderEntry* notAFile = nullptr;
      for (const std::string& name : candidateNames(number)) {
        const auto it = std::lower_bound(files.begin(), files.end(), name,
                                         [](const FolderEntry& e, const std::string& n) { return e.lowerName < n; });
        if (it == files.end() || it->lowerName != name) continue;
        if (it->regular) {
          path = it->path;
          break;
        }
        if (!notAFile) notAFile = &*it;  // said only if no name of it is a file
      }
      if (path.empty() && notAFile &&
          std::none_of(program.notProgramFiles.begin(), program.notProgramFiles.end(),
                       [number](const gcode::Program::NotAFile& n) { return n.number == number; }))
        program.notProgramFiles.push_back({number, fs::path(notAFile->path).filename().string(), notAFile->folder});
      if (path.empty() || attached.count(path)) continue;
      attached.insert(path);
      const int fileIndex = static_cast<int>(program.files.size());
      program.files.push_back(path);
      // A link that leaves the folder (O1000.nc -> /etc/shadow) is never opened: the
      // job drops the file with F158 and the call is E404 (issue 42 item 1).
      if (!io::insideFolder(path, folder)) continue;
      io::ReadResult<io::ProgramFile> read = io::readProgramFile(path);
      for (Diagnostic d : read.diagnostics) {
        d.range.file = fileIndex;
        diagnostics.push_back(std::move(d));
      }
      if (!read.value) continue;
      gcode::Program sub = gcode::parse(read.value->gcode, read.value->gcodeFirstLine, fileIndex);
      for (Diagnostic& d : sub.lexicalDiagnostics) program.lexicalDiagnostics.push_back(std::move(d));
      // A file without its own O block is the program its name says.
      const bool named =
          !sub.blocks.empty() && !sub.blocks.front().words.empty() && sub.blocks.front().words.front().letter == 'O';
      if (!named) {
        gcode::Block o;
        o.line = read.value->gcodeFirstLine;
        o.file = fileIndex;
        gcode::Word w;
        w.letter = 'O';
        w.number = std::to_string(number);
        w.value = number;
        w.range = SourceRange{o.line, 1, 0, fileIndex};
        o.words.push_back(std::move(w));
        program.blocks.push_back(std::move(o));
      }
      const int offset = static_cast<int>(program.expressions.size());
      for (gcode::Expression& e : sub.expressions) program.expressions.push_back(std::move(e));
      for (gcode::Block& b : sub.blocks) {
        shiftExpressions(b, offset);
        program.blocks.push_back(std::move(b));
      }
      // The moved blocks borrow their words from the file's word store: the program keeps it.
      for (std::shared_ptr<void>& store : sub.wordStores) program.wordStores.push_back(std::move(store));
      added = true;
    }
    if (!added) break;
  }
  return diagnostics;
}

std::string diagnosticFile(const gcode::Program& program, const Diagnostic& d, const std::string& mainPath) {
  if (d.range.file <= 0 || d.range.file >= static_cast<int>(program.files.size())) return mainPath;
  return program.files[static_cast<std::size_t>(d.range.file)];
}

}  // namespace klueng::core::machine
