#pragma once
// What a folder run (`check DIR`, `class DIR`, File > Grade a class) may read
// (issue 42 item 1): only regular files inside the folder. A link that leaves
// the folder is refused unread (a student's `evil.nc -> /etc/shadow` must not
// reach a PDF or a message); a pipe, a dangling link or a folder with a
// program's name is listed too, so that it gets a row instead of vanishing.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"

namespace klueng::core::io {

enum class FolderEntryKind {
  Program,        // a regular file inside the folder (or a link to one): read it
  OutsideFolder,  // a link whose target is not inside the folder: F158, never read
  NotAFile,       // a pipe, a device or a socket (or a link to one): F157, never opened
  Folder,         // a folder with a program's name: F102
  Dangling,       // a link to nothing: F101
};

struct FolderEntry {
  std::string path;  // folder / name
  std::string name;  // the name in the folder
  FolderEntryKind kind = FolderEntryKind::Program;
};

// The entries of `folder` named as programs (isProgramFileName), sorted by
// name; only lstat/stat and the link's target are looked at, nothing is opened.
std::vector<FolderEntry> programFolderEntries(const std::string& folder);

// Whether `path` (a link or a file in `folder`) resolves to a place inside `folder`.
bool insideFolder(const std::string& path, const std::string& folder);

// The diagnostic (no line) that says why a refused entry is not read; nullopt for a Program.
std::optional<Diagnostic> folderEntryRefusal(const FolderEntry& entry);

// Why decoded program text is not a G-code program, so that a folder run says
// so without quoting it: F159 for text with control characters (binary data)
// or without a G-code word in its first kGcodeProbeLines non-blank lines.
// nullopt for a program (an empty text too: its reader says F105).
inline constexpr int kGcodeProbeLines = 20;
std::optional<Diagnostic> notAGcodeProgram(std::string_view gcode, const std::string& fileName);

}  // namespace klueng::core::io
