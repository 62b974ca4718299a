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

}  // namespace klueng::core::io
