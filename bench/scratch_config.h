#pragma once
// The shipped setup in a scratch folder with max_run_time at its limit, so that a run of a long
// program reaches its end (the whole-process and memory benches).
#include <filesystem>
#include <fstream>
#include <string>

namespace klueng::bench {

inline std::filesystem::path makeLongRunConfig(const std::filesystem::path& scratch) {
  namespace fs = std::filesystem;
  const fs::path dir = scratch / "config";
  fs::create_directories(dir);
  const fs::path source = KLUENG_SOURCE_DIR;
  fs::copy_file(source / "tools.cfg", dir / "tools.cfg");
  fs::copy_file(source / "offset.cfg", dir / "offset.cfg");
  fs::create_directory_symlink(source / "resources", dir / "resources");
  std::ifstream in(source / "machine.cfg");
  std::ofstream out(dir / "machine.cfg");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("max_run_time", 0) != 0) out << line << '\n';
  out << "max_run_time = 10000000\n";
  return dir;
}

}  // namespace klueng::bench
