// Every file a run reads (run_inputs.h).
#include "klueng/core/job/run_inputs.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "klueng/core/cut/cutting_data.h"
#include "klueng/core/io/macro_variables.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/machine/machine_files.h"

namespace klueng::core::job {

namespace {
namespace fs = std::filesystem;
}  // namespace

std::vector<std::string> setupInputFiles(const machine::LoadedSetup& loaded) {
  std::vector<std::string> files;
  if (!loaded.dir.empty()) {
    for (const char* name : {"tools.cfg", "offset.cfg", "machine.cfg"})
      files.push_back((fs::path(loaded.dir) / name).string());
    files.push_back(io::macroVariablesPath(loaded.dir));
  }
  for (int tool = 1; tool <= io::kMaxStations; ++tool)
    if (std::string bitmap = loaded.setup.tools.bitmapPath(tool); !bitmap.empty()) files.push_back(std::move(bitmap));
  const io::ToolLibrary& library = io::shippedToolLibrary();
  files.push_back(io::shippedToolLibraryPath());
  for (const io::LibraryTool& tool : library.tools) files.push_back(library.bitmapPath(tool));
  files.push_back(io::shippedCuttingSpeedsPath());
  files.push_back(cut::shippedMaterialsPath());  // the cutting data's materials (issue 39)
  for (const std::string& folder : machine::machineFolders(loaded.dir)) {
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
      if (it->path().extension() == ".machine") files.push_back(it->path().string());
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

std::vector<std::string> runInputFiles(const std::string& path, const Job* job, const machine::LoadedSetup& loaded) {
  std::vector<std::string> files{path};
  if (job && job->program())
    for (const std::string& sub : job->program()->files)
      if (!sub.empty()) files.push_back(sub);  // files[0] is "": the program itself
  for (std::string& f : setupInputFiles(loaded)) files.push_back(std::move(f));
  return files;
}

}  // namespace klueng::core::job
