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

// Whether `path` names a descriptor this process already holds open:
// /dev/stdin, /dev/fd/N, /proc/self/fd/N (a shell's `<(cmd)`), or a link to
// one. Such a pipe has its writer already: it is read until its end, with
// the same size limit as a file (issue 42 item 4).
bool isOpenDescriptor(const std::string& path);

// F157 when opening `path` to read could wait for ever: a named pipe (FIFO)
// that is not one of our open descriptors (it waits for a writer), or a
// socket. Every reader of the io module asks it before it opens a file, so a
// program, a setup table, a part design or a machine file that is a FIFO is
// refused at once. Only lstat/stat/readlink are called. nullopt otherwise.
std::optional<Diagnostic> wouldBlockOnOpen(const std::string& path);

// The limit as F103 says it: "64 MB", "1 MB", "1500 bytes".
std::string sizeLimitText(std::size_t maxBytes);

}  // namespace klueng::core::io
