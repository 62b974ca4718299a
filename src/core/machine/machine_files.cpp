// Machine files on disk (machine_files.h).
#include "klueng/core/machine/machine_files.h"

#include <algorithm>
#include <filesystem>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/text_encoding.h"

namespace klueng::core::machine {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kMaxMachineFileBytes = 256 * 1024;

// The machine.cfg lines of a machine file, each on its own line number, the
// others blank: machine.cfg's reader then names the right line and column.
std::string machineCfgLines(std::string_view text, const std::vector<gcode::MachineDefinition::OtherKey>& keys) {
  std::string out;
  int line = 1;
  std::size_t k = 0;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (k < keys.size() && keys[k].line == line) {
      out.append(text.substr(start, end - start));
      ++k;
    }
    out += '\n';
    ++line;
    if (end == text.size()) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

MachineFileResult readMachineFile(const std::string& path) {
  MachineFileResult result;
  auto bytes = io::readFileLimited(path, kMaxMachineFileBytes);
  result.diagnostics = bytes.diagnostics;
  if (!bytes.value) return result;
  gcode::MachineFileRead read = gcode::parseMachineFile(*bytes.value, path);
  for (Diagnostic& d : read.diagnostics) result.diagnostics.push_back(std::move(d));
  if (!read.machine) return result;
  // Its machine.cfg keys, checked as machine.cfg's are (F141 for a key neither knows).
  if (!read.machine->otherKeys.empty()) {
    const auto cfg = io::parseMachineConfig(machineCfgLines(read.machine->text, read.machine->otherKeys), path);
    bool bad = false;
    for (const Diagnostic& d : cfg.diagnostics) {
      if (d.code == codes::kNoMachineParameters) continue;
      bad = bad || isError(d.severity);
      result.diagnostics.push_back(d);
    }
    if (bad) return result;
  }
  std::sort(result.diagnostics.begin(), result.diagnostics.end(),
            [](const Diagnostic& a, const Diagnostic& b) { return a.range.line < b.range.line; });
  result.machine = std::move(read.machine);
  return result;
}

std::vector<std::string> machineFolders(const std::string& configDir) {
  std::vector<std::string> folders;
  std::error_code ec;
  const auto add = [&](const std::string& base) {
    if (base.empty()) return;
    const fs::path dir = fs::path(base) / "machines";
    if (!fs::is_directory(dir, ec)) return;
    const std::string canonical = fs::weakly_canonical(dir, ec).string();
    for (const std::string& f : folders)
      if (fs::weakly_canonical(f, ec).string() == canonical) return;
    folders.push_back(dir.string());
  };
  add(io::userConfigDir());
  add(configDir);
  return folders;
}

std::vector<SetupDiagnostic> loadMachineFolders(const std::vector<std::string>& folders) {
  std::vector<SetupDiagnostic> out;
  for (const std::string& folder : folders) {
    std::vector<std::string> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder, ec))
      if (e.path().extension() == ".machine" && e.is_regular_file(ec)) files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    for (const std::string& file : files) {
      MachineFileResult r = readMachineFile(file);
      for (Diagnostic& d : r.diagnostics) out.push_back({file, std::move(d)});
      if (r.machine) gcode::registerMachine(std::move(*r.machine));
    }
  }
  return out;
}

std::optional<gcode::Dialect> resolveMachine(const std::string& nameOrFile, std::vector<SetupDiagnostic>& diagnostics) {
  gcode::Dialect d{};
  const bool looksLikeFile =
      nameOrFile.find('/') != std::string::npos || fs::path(nameOrFile).extension() == ".machine";
  if (!looksLikeFile && gcode::parseDialectId(nameOrFile, d)) return d;
  std::error_code ec;
  if (!looksLikeFile && !fs::exists(nameOrFile, ec)) {
    std::string ids;
    for (const gcode::MachineProfile* p : gcode::machineProfiles())
      ids += (ids.empty() ? "" : ", ") + std::string(p->id);
    diagnostics.push_back({nameOrFile, Diagnostic{Severity::Error, codes::kUnknownMachine, {}, {nameOrFile, ids}}});
    return std::nullopt;
  }
  if (fs::path(nameOrFile).extension() != ".machine" && !fs::is_directory(nameOrFile, ec)) {
    diagnostics.push_back({nameOrFile, Diagnostic{Severity::Error, codes::kNotAMachineFile, {}, {nameOrFile}}});
    return std::nullopt;
  }
  MachineFileResult r = readMachineFile(nameOrFile);
  for (Diagnostic& diag : r.diagnostics) diagnostics.push_back({nameOrFile, std::move(diag)});
  if (!r.machine) return std::nullopt;
  return gcode::registerMachine(std::move(*r.machine));
}

std::optional<gcode::Dialect> machineOfProgram(const io::ProgramFile& file, std::vector<Diagnostic>& warnings) {
  const std::optional<io::NamedMachine> named = io::machineNamedIn(file.gcode);
  if (!named) return std::nullopt;
  gcode::Dialect d{};
  if (gcode::parseDialectId(named->id, d)) return d;
  std::string ids;
  for (const gcode::MachineProfile* p : gcode::machineProfiles()) ids += (ids.empty() ? "" : ", ") + std::string(p->id);
  Diagnostic w{Severity::Warning, codes::kProgramMachineUnknown, {}, {named->id, ids}};
  w.range.line = file.gcodeFirstLine + named->line - 1;
  w.range.column = named->column;
  w.range.length = io::utf8Length(named->id);
  warnings.push_back(std::move(w));
  return std::nullopt;
}

io::MachineConfig withMachineKeys(const io::MachineConfig& setup, const gcode::MachineProfile& machine) {
  if (machine.text.empty()) return setup;
  const gcode::MachineFileRead read = gcode::parseMachineFile(machine.text, std::string(machine.file));
  if (!read.machine || read.machine->otherKeys.empty()) return setup;
  // The setup's values first, the machine's lines after them: a later key wins.
  const std::string text = io::formatMachineConfig(setup) + machineCfgLines(machine.text, read.machine->otherKeys);
  const auto merged = io::parseMachineConfig(text, std::string(machine.file));
  return merged.value ? *merged.value : setup;
}

}  // namespace klueng::core::machine
