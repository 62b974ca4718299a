#pragma once
// A whole file read with a size limit, as every reader of the io module reads
// its files, for readers outside it (the part designs and drawings of
// core/design, issue 29).
#include <cstddef>
#include <optional>
#include <string>

#include "klueng/core/diagnostic.h"

#include "klueng/core/io/result.h"

namespace klueng::core::io {

// F101 no such file, F102 a folder or unreadable, F103 over maxBytes: read in
// chunks, so a device that never ends (/dev/zero) is refused at the limit.
ReadResult<std::string> readFileLimited(const std::string& path, std::size_t maxBytes);

// F157 when the path is there but is no ordinary file: a pipe (FIFO), a
// device or a socket. Opening a pipe waits for a writer for ever, so a window
// asks this before it reads, and tool bitmaps are refused with it (issue 29).
// Only stat() is called: it never waits. nullopt for an ordinary file, a
// folder or a missing path (their own readers say F101/F102).
std::optional<Diagnostic> notAnOrdinaryFile(const std::string& path);

// The limit as F103 says it: "64 MB", "1 MB", "1500 bytes".
std::string sizeLimitText(std::size_t maxBytes);

}  // namespace klueng::core::io
