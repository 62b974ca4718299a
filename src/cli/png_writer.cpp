#include "png_writer.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>
#include <vector>

#include "cli_common.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/io/program_file.h"

namespace klueng::cli {

namespace {

namespace fs = std::filesystem;

// Why the module could not be used: a catalog code (messages_cli.cpp) and its argument.
struct ModuleFailure {
  const char* code = nullptr;
  std::string arg;
};

// The module, opened once per process; nullptr (and why) when it cannot be found.
void* openModule(ModuleFailure* why) {
  static ModuleFailure failure;
  static void* const handle = []() -> void* {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
      failure = {core::codes::kCliNoOwnFolder, ec.message()};
      return nullptr;
    }
    for (const fs::path& candidate :
         {self.parent_path() / "klueng-png.so", self.parent_path() / KLUENG_LIBDIR_FROM_BIN / "klueng-png.so"}) {
      if (!fs::exists(candidate, ec)) continue;
      void* h = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!h) failure = {core::codes::kCliModuleNotOpened, ::dlerror()};
      return h;
    }
    failure = {core::codes::kCliModuleMissing, self.string()};
    return nullptr;
  }();
  if (!handle && why) *why = failure;
  return handle;
}

// One entry point of the module; nullptr (and why) when it is not there.
void* moduleSymbol(const char* name, ModuleFailure* why) {
  void* handle = openModule(why);
  if (!handle) return nullptr;
  void* symbol = ::dlsym(handle, name);
  if (!symbol && why) *why = {core::codes::kCliModuleNoEntry, name};
  return symbol;
}

// F108 with the reason in both languages, from the catalog.
core::Diagnostic notWritten(const std::string& path, const char* code, const std::string& arg = {}) {
  if (!code) code = core::codes::kCliPictureNotDrawn;
  std::vector<std::string> args;
  if (!arg.empty()) args.push_back(arg);
  return core::Diagnostic{core::Severity::Error,
                          core::codes::kCannotWriteFile,
                          {},
                          {path, cliText(code, core::Lang::En, args), cliText(code, core::Lang::Th, args)}};
}

KluengSectionPngFn loadModule(ModuleFailure* why) {
  return reinterpret_cast<KluengSectionPngFn>(moduleSymbol("klueng_section_png", why));
}

}  // namespace

std::optional<core::Diagnostic> writeSectionPng(const render::SectionPicture& picture, const std::string& path) {
  ModuleFailure why;
  const KluengSectionPngFn draw = loadModule(&why);
  if (!draw) return notWritten(path, why.code, why.arg);
  char* bytes = nullptr;
  std::size_t size = 0;
  if (!draw(&picture, &bytes, &size)) return notWritten(path, core::codes::kCliPictureNotDrawn);
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
  ModuleFailure why;
  const auto draw = reinterpret_cast<Fn>(moduleSymbol(symbol, &why));
  if (!draw) return notWritten(path, why.code, why.arg);
  char* bytes = nullptr;
  std::size_t size = 0;
  char reason[512] = {0};
  // The module says why in the sheets' language (messages_render.cpp), the run's own.
  if (!draw(&input, &bytes, &size, reason, sizeof reason))
    return core::Diagnostic{core::Severity::Error, core::codes::kCannotWriteFile, {}, {path, reason, reason}};
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
