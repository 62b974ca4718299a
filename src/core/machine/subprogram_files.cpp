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

// The folder's regular files by lower-case name (so O1000.NC and o1000.nc both match).
std::vector<std::pair<std::string, std::string>> folderFiles(const std::string& folder) {
  std::vector<std::pair<std::string, std::string>> files;
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : fs::path(folder), ec);
  for (; !ec && it != fs::directory_iterator(); it.increment(ec)) {
    std::error_code fec;
    if (!it->is_regular_file(fec)) continue;
    files.emplace_back(lower(it->path().filename().string()), it->path().string());
    if (files.size() > 100000) break;
  }
  std::sort(files.begin(), files.end());
  return files;
}

void shiftExpressions(gcode::Block& b, int offset) {
  for (gcode::Word& w : b.words)
    if (w.expr >= 0) w.expr += offset;
  gcode::Statement& s = b.statement;
  if (s.condition >= 0) s.condition += offset;
  if (s.target >= 0) s.target += offset;
  if (s.value >= 0) s.value += offset;
}

}  // namespace

std::vector<Diagnostic> attachSubprogramFiles(gcode::Program& program, const std::string& folder,
                                              gcode::Dialect dialect) {
  std::vector<Diagnostic> diagnostics;
  std::vector<std::pair<std::string, std::string>> files;  // read once, when a call needs it
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
      for (const std::string& name : candidateNames(number)) {
        const auto it = std::lower_bound(files.begin(), files.end(), std::make_pair(name, std::string()));
        if (it != files.end() && it->first == name) {
          path = it->second;
          break;
        }
      }
      if (path.empty() || attached.count(path)) continue;
      attached.insert(path);
      const int fileIndex = static_cast<int>(program.files.size());
      program.files.push_back(path);
      io::ReadResult<io::ProgramFile> read = io::readProgramFile(path);
      for (Diagnostic d : read.diagnostics) {
        d.range.file = fileIndex;
        diagnostics.push_back(std::move(d));
      }
      if (!read.value) continue;
      gcode::Program sub = gcode::parse(read.value->gcode, read.value->gcodeFirstLine, fileIndex);
      for (Diagnostic& d : sub.lexicalDiagnostics) program.lexicalDiagnostics.push_back(std::move(d));
      // A file without its own O block is the program its name says.
      const bool named = !sub.blocks.empty() && !sub.blocks.front().words.empty() &&
                         sub.blocks.front().words.front().letter == 'O';
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
