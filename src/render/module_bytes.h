#pragma once
// How the picture module (klueng-png.so) hands a file's bytes to klueng-cli:
// malloc'd, so the CLI frees them without Qt. The module never writes files
// itself; the CLI writes the bytes with core/io/file_write.h, which checks
// every write and keeps the old file when one fails.
#include <QByteArray>
#include <cstdlib>
#include <cstring>

namespace klueng::render {

// 1 with *bytes and *size set; 0 when there is nothing to hand back or no memory.
inline int handBytes(const QByteArray& data, char** bytes, std::size_t* size) {
  if (data.isEmpty() || !bytes || !size) return 0;
  *bytes = static_cast<char*>(std::malloc(static_cast<std::size_t>(data.size())));
  if (!*bytes) return 0;
  *size = static_cast<std::size_t>(data.size());
  std::memcpy(*bytes, data.constData(), *size);
  return 1;
}

}  // namespace klueng::render
