#include "png_writer.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>

#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

namespace fs = std::filesystem;

// The module, opened once per process; nullptr (and why) when it cannot be found.
void* openModule(std::string* why) {
  static std::string failure;
  static void* const handle = []() -> void* {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
      failure = "cannot find the program's own folder: " + ec.message();
      return nullptr;
    }
    for (const fs::path& candidate :
         {self.parent_path() / "klueng-png.so", self.parent_path() / KLUENG_LIBDIR_FROM_BIN / "klueng-png.so"}) {
      if (!fs::exists(candidate, ec)) continue;
      void* h = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!h) failure = std::string("cannot open the picture module: ") + ::dlerror();
      return h;
    }
    failure = "the picture module klueng-png.so is not installed beside " + self.string();
    return nullptr;
  }();
  if (!handle && why) *why = failure;
  return handle;
}

// One entry point of the module; nullptr (and why) when it is not there.
void* moduleSymbol(const char* name, std::string* why) {
  void* handle = openModule(why);
  if (!handle) return nullptr;
  void* symbol = ::dlsym(handle, name);
  if (!symbol && why) *why = std::string("klueng-png.so has no ") + name + ": not Klueng's picture module";
  return symbol;
}

KluengSectionPngFn loadModule(std::string* why) {
  return reinterpret_cast<KluengSectionPngFn>(moduleSymbol("klueng_section_png", why));
}

}  // namespace

std::optional<core::Diagnostic> writeSectionPng(const render::SectionPicture& picture, const std::string& path) {
  const auto failed = [&](const std::string& why, const std::string& thai) {
    return core::Diagnostic{core::Severity::Error, core::codes::kCannotWriteFile, {}, {path, why, thai}};
  };
  std::string why;
  const KluengSectionPngFn draw = loadModule(&why);
  if (!draw) return failed(why, "ใช้โมดูลวาดภาพ klueng-png.so ไม่ได้: " + why);
  char* bytes = nullptr;
  std::size_t size = 0;
  if (!draw(&picture, &bytes, &size)) return failed("the picture could not be drawn", "วาดภาพไม่ได้");
  const std::unique_ptr<char, decltype(&std::free)> owned(bytes, &std::free);
  return core::io::writeFileAtomic(path, std::string_view(bytes, size));
}

}  // namespace klueng::cli

namespace klueng::cli {

namespace {

// Runs a module entry that draws a PDF into memory, then writes it with the
// checked writer: a failed write keeps the old file and is reported (issue 29).
template <class Input, class Fn>
std::optional<core::Diagnostic> writePdf(const char* symbol, const Input& input, const std::string& path) {
  const auto failed = [&](const std::string& why, const std::string& thai) {
    return core::Diagnostic{core::Severity::Error, core::codes::kCannotWriteFile, {}, {path, why, thai}};
  };
  std::string why;
  const auto draw = reinterpret_cast<Fn>(moduleSymbol(symbol, &why));
  if (!draw) return failed(why, "ใช้โมดูลวาดภาพ klueng-png.so ไม่ได้: " + why);
  char* bytes = nullptr;
  std::size_t size = 0;
  char reason[512] = {0};
  if (!draw(&input, &bytes, &size, reason, sizeof reason))
    return failed(reason, std::string("สร้าง PDF ไม่ได้: ") + reason);
  const std::unique_ptr<char, decltype(&std::free)> owned(bytes, &std::free);
  return core::io::writeFileAtomic(path, std::string_view(bytes, size));
}

}  // namespace

std::optional<core::Diagnostic> writeClassPdf(const KluengClassPdf& input, const std::string& path) {
  return writePdf<KluengClassPdf, KluengClassPdfFn>("klueng_class_pdf", input, path);
}

std::optional<core::Diagnostic> writePrintPdf(const KluengPrintPdf& input, const std::string& path) {
  return writePdf<KluengPrintPdf, KluengPrintPdfFn>("klueng_print_pdf", input, path);
}

}  // namespace klueng::cli
