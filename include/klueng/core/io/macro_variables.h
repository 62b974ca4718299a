#pragma once
// The persistent common variables #500-#999 of custom macro B (issue 9). A
// control keeps them through power-off; Klueng keeps them in a text file in
// the program's folder (the folder is the control's memory), shared by every
// program there:
//
//   ; Klueng macro variables #500-#999
//   #500 = 12.5
//   #501 = -3
//
// One `#n = value` per line; blank lines and `;` comments are ignored. A bad
// line is reported (F170, F171) with its line and column and skipped.
#include <map>
#include <string>
#include <string_view>

#include "klueng/core/io/result.h"

namespace klueng::core::io {

inline constexpr std::string_view kMacroVariablesFile = "macro_variables.cfg";

using MacroVariables = std::map<int, double>;

ReadResult<MacroVariables> parseMacroVariables(std::string_view text, const std::string& fileName);
// A missing file is an empty set without diagnostics.
ReadResult<MacroVariables> readMacroVariables(const std::string& path);
std::string formatMacroVariables(const MacroVariables& values);
// The file's path in `folder`.
std::string macroVariablesPath(const std::string& folder);

// An exclusive lock on `folder`'s #500-#999 from construction to destruction,
// so that parallel runs read, change and write macro_variables.cfg one after
// another (issue 42 item 5: twenty runs of #500=#500+1 add twenty). It is an
// flock on the folder itself: nothing is left behind, and a crashed run's lock
// goes with its process. Not locked (locked() false) when the folder is missing.
class MacroVariablesLock {
 public:
  explicit MacroVariablesLock(const std::string& folder);
  ~MacroVariablesLock();
  MacroVariablesLock(const MacroVariablesLock&) = delete;
  MacroVariablesLock& operator=(const MacroVariablesLock&) = delete;
  bool locked() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

}  // namespace klueng::core::io
