#include "klueng/core/io/file_read.h"

#include <sys/stat.h>

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
