// Reading a machine setup's folder (setup_files.h).
#include "klueng/core/machine/setup_files.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "klueng/core/io/text_encoding.h"
#include "klueng/core/machine/machine_files.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::machine {

bool isUnreadable(const Diagnostic& d) {
  return d.code == codes::kNoSuchFile || d.code == codes::kCannotReadFile || d.code == codes::kFileTooLarge ||
         d.code == codes::kNotAnOrdinaryFile || d.code == codes::kPathTooLong;
}

bool LoadedSetup::hasErrors() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const SetupDiagnostic& f) { return isError(f.diagnostic.severity); });
}

std::optional<std::vector<int>> LoadedSetup::toolsWithBitmap() const {
  if (!toolTableRead) return std::nullopt;
  return machine::toolsWithBitmap(setup);
}

LoadedSetup loadMachineSetup(const std::string& explicitDir, bool readBitmaps) {
  LoadedSetup loaded;
  loaded.dir = io::findConfigDir(explicitDir);
  const std::filesystem::path dir(loaded.dir);
  const auto collect = [&loaded](const std::string& file, const std::vector<Diagnostic>& diags) {
    for (const Diagnostic& d : diags) {
      if (isUnreadable(d)) loaded.unreadable = true;
      loaded.diagnostics.push_back({file, d});
    }
  };
  std::error_code ec;
  const std::string machinePath = (dir / "machine.cfg").string();
  if (std::filesystem::exists(machinePath, ec)) {
    auto machine = io::readMachineConfig(machinePath);
    collect(machinePath, machine.diagnostics);
    if (machine.value) loaded.setup.machine = *machine.value;
  }
  const std::string toolsPath = (dir / "tools.cfg").string();
  auto tools = io::readToolTable(toolsPath, loaded.setup.machine.turretStations);
  collect(toolsPath, tools.diagnostics);
  if (tools.value) {
    loaded.setup.tools = *tools.value;
    loaded.toolTableRead = true;
  }
  const std::string offsetsPath = (dir / "offset.cfg").string();
  auto offsets = io::readOffsetTable(offsetsPath);
  collect(offsetsPath, offsets.diagnostics);
  if (offsets.value) loaded.setup.offsets = *offsets.value;

  // The machines folders (issue 27): the user's and this setup's, adding or overriding machines.
  for (SetupDiagnostic& d : loadMachineFolders(machineFolders(loaded.dir))) loaded.diagnostics.push_back(std::move(d));

  // Every bitmap is decoded once here: one that does not decode is no tool,
  // for the editor, a run and the CLI alike.
  for (int t = 1; t <= io::kToolCount; ++t) {
    const std::string path = loaded.setup.tools.bitmapPath(t);
    if (path.empty() || !std::filesystem::is_regular_file(path, ec)) continue;  // F121 already says so
    auto image = io::readImage(path);
    for (const Diagnostic& d : image.diagnostics) loaded.diagnostics.push_back({path, d});
    const auto i = static_cast<std::size_t>(t - 1);
    // Larger than a tool can be: a setup error now, at its tools.cfg line, not an alarm when the tool cuts.
    const double ppm = loaded.setup.tools.pixelsPerMmOf(t);
    const int most = io::maxToolBitmapPixels(ppm);
    if (image.ok() && (image.value->width > most || image.value->height > most)) {
      const std::string& name = loaded.setup.tools.bitmap[i];
      loaded.diagnostics.push_back(
          {toolsPath,
           Diagnostic{Severity::Error,
                      codes::kToolBitmapTooLarge,
                      {t, 1, io::utf8Length(name)},
                      {toolsPath, fmt::format("{:02}", t), name, std::to_string(image.value->width),
                       std::to_string(image.value->height), std::to_string(most), fmt::format("{:g}", ppm)}}});
      image.value.reset();
    }
    loaded.setup.tools.bitmapUnreadable[i] = !image.ok();
    if (image.ok() && readBitmaps) loaded.bitmaps[i] = std::move(*image.value);
  }
  return loaded;
}

std::vector<int> toolsWithBitmap(const MachineSetup& setup) {
  std::vector<int> out;
  std::error_code ec;
  const int stations = static_cast<int>(setup.tools.bitmap.size());
  for (int t = 1; t <= stations; ++t) {
    const std::string path = setup.tools.bitmapPath(t);
    if (setup.tools.bitmapUnreadable[static_cast<std::size_t>(t - 1)]) continue;
    if (!path.empty() && std::filesystem::is_regular_file(path, ec)) out.push_back(t);
  }
  return out;
}

}  // namespace klueng::core::machine
