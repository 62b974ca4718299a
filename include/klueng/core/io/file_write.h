#pragma once
// The one way Klueng writes a file (issue 29): a temporary file beside the
// target, every write, the flush and the close checked, then a rename. On any
// failure the old file keeps its bytes, and the caller gets a diagnostic that
// names the path and why, in English and Thai (messages_io.cpp).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"

namespace klueng::core::io {

// Writes `bytes` to `path`; nullopt when the whole file is in place.
// Refuses (the file untouched):
//   F119 a read-only file: no write permission bit at all (root included, as
//        editors do), or not writable for this user;
//   F127 a folder.
// Fails (an old file untouched, the temporary file removed):
//   F109 no space (a full disk, a quota, the file size limit);
//   F125 the folder is missing or cannot be written to;
//   F108 anything else, with the system's reason.
// A symbolic link is followed (the file it names is replaced, the link stays);
// a device or a pipe (/dev/stdout) is written into, never renamed over.
// The replaced file's permission bits are kept; new files get rw-r--r--.
std::optional<Diagnostic> writeFileAtomic(const std::string& path, std::string_view bytes);

// F126 when `output` names the same file as one of `inputs` (after links, `..`
// and hard links), so that writing it would destroy an input; nullopt otherwise.
// Devices (/dev/stdout, /dev/null) never clash.
std::optional<Diagnostic> outputOverwritesInput(const std::string& output, const std::vector<std::string>& inputs);

// True when `path` is an existing file writeFileAtomic would refuse as read-only (F119).
bool isReadOnlyFile(const std::string& path);

// SIGINT, SIGTERM, SIGHUP and SIGQUIT remove the temporary file of every write
// under way (`.NAME.tmp-XXXXXX`), then end the process by the same signal as
// before (issue 42 item 5). Call once at start; a signal the process ignores
// (a background job's SIGINT) stays ignored.
void removeTemporaryFilesOnSignals();

}  // namespace klueng::core::io
