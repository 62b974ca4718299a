#include "png_writer.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>

#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

namespace fs = std::filesystem;

// The module's entry point, opened once per process; nullptr (and why) when it cannot be found.
KluengSectionPngFn loadModule(std::string* why) {
  static std::string failure;
  static const KluengSectionPngFn fn = []() -> KluengSectionPngFn {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
      failure = "cannot find the program's own folder: " + ec.message();
      return nullptr;
    }
    for (const fs::path& candidate : {self.parent_path() / "klueng-png.so",
                                      self.parent_path() / KLUENG_LIBDIR_FROM_BIN / "klueng-png.so"}) {
      if (!fs::exists(candidate, ec)) continue;
      void* handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!handle) {
        failure = std::string("cannot open the picture module: ") + ::dlerror();
        return nullptr;
      }
      if (auto* entry = reinterpret_cast<KluengSectionPngFn>(::dlsym(handle, "klueng_section_png"))) return entry;
      failure = candidate.string() + " is not Klueng's picture module";
      return nullptr;
    }
    failure = "the picture module klueng-png.so is not installed beside " + self.string();
    return nullptr;
  }();
  if (!fn && why) *why = failure;
  return fn;
}

}  // namespace

bool writeSectionPng(const render::SectionPicture& picture, const std::string& path, std::string* error) {
  const KluengSectionPngFn draw = loadModule(error);
  if (!draw) return false;
  char* bytes = nullptr;
  std::size_t size = 0;
  if (!draw(&picture, &bytes, &size)) {
    if (error) *error = "the picture could not be drawn";
    return false;
  }
  const std::unique_ptr<char, decltype(&std::free)> owned(bytes, &std::free);
  return core::io::writeTextFileAtomic(path, std::string_view(bytes, size), error);
}

}  // namespace klueng::cli
