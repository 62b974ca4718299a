#pragma once
// What a comment says about a tool: the words real programs use, in English
// (Haas and Fanuc shop habits) and Thai (GLOSSARY.md). Private to machine.
#include <string>
#include <string_view>

#include "klueng/core/io/tool_library.h"

namespace klueng::core::machine::detail {

struct CommentTool {
  io::ToolKind kind = io::ToolKind::Unknown;
  bool finishing = false;     // FINISH / กลึงละเอียด: the small nose radius
  std::string insert;         // "vnmg", "dnmg", "cnmg" when the comment names one
  double drillMm = 0.0;       // a size written with the drill ("DRILL 16MM", "Ø10"); 0 = none
};

// Unknown kind when the comment names no tool.
CommentTool classifyComment(std::string_view comment);

}  // namespace klueng::core::machine::detail
