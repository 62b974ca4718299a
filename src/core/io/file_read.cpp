#include "klueng/core/io/file_read.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string_view>
#include <system_error>

#include "io/text_util.h"
#include "klueng/core/diagnostic_codes.h"

namespace klueng::core::io {

std::optional<Diagnostic> notAnOrdinaryFile(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  const auto what = [&](const char* en, const char* th) {
    return detail::makeDiagnostic(Severity::Error, codes::kNotAnOrdinaryFile, 0, 0, 0, {path, en, th});
  };
  if (S_ISFIFO(st.st_mode)) return what("a pipe (FIFO)", "ไปป์ (FIFO)");
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return what("a device", "อุปกรณ์ (device)");
  if (S_ISSOCK(st.st_mode)) return what("a socket", "ซ็อกเก็ต (socket)");
  return std::nullopt;
}

bool isOpenDescriptor(const std::string& path) {
  namespace fs = std::filesystem;
  const auto descriptorPath = [](const fs::path& p) {
    const std::string text = p.lexically_normal().string();
    for (const std::string_view prefix : {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/"})
      if (text.starts_with(prefix)) return true;
    // /proc/<our pid>/fd/N
    const std::string own = "/proc/" + std::to_string(::getpid()) + "/fd/";
    return text == "/dev/stdin" || text.starts_with(own);
  };
  fs::path p(path);
  // A few links at most: /dev/stdin -> /proc/self/fd/0 -> pipe:[1234].
  for (int hop = 0; hop < 8; ++hop) {
    if (descriptorPath(p)) return true;
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return false;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) return false;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return false;
}

std::optional<Diagnostic> wouldBlockOnOpen(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  if (!S_ISFIFO(st.st_mode) && !S_ISSOCK(st.st_mode)) return std::nullopt;
  if (S_ISFIFO(st.st_mode) && isOpenDescriptor(path)) return std::nullopt;
  return notAnOrdinaryFile(path);
}

ReadResult<std::string> readFileLimited(const std::string& path, std::size_t maxBytes) {
  ReadResult<std::string> result;
  result.value = detail::readFileBytes(path, result.diagnostics, maxBytes);
  return result;
}

std::string sizeLimitText(std::size_t maxBytes) {
  constexpr std::size_t kMb = 1024u * 1024u;
  return maxBytes % kMb == 0 ? std::to_string(maxBytes / kMb) + " MB" : std::to_string(maxBytes) + " bytes";
}

}  // namespace klueng::core::io
