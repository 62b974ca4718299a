#include "klueng/core/io/file_read.h"

#include "io/text_util.h"

namespace klueng::core::io {

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
