// checkToolBitmaps (issues 12, 13): check() without the tool table plus the
// tool rule alone is exactly check() with it, so the tool table can be worked
// out on another thread while the rest of the check runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "klueng/core/gcode/checker.h"
#include "klueng/core/gcode/parser.h"

namespace klueng::core::gcode {
namespace {

std::vector<std::string> listed(std::vector<Diagnostic> ds) {
  std::stable_sort(ds.begin(), ds.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.range.line != b.range.line ? a.range.line < b.range.line : a.range.column < b.range.column;
  });
  std::vector<std::string> out;
  for (const Diagnostic& d : ds) {
    std::string args;
    for (const std::string& a : d.args) args += "|" + a;
    out.push_back(d.code + "@" + std::to_string(d.range.line) + ":" + std::to_string(d.range.column) + args);
  }
  return out;
}

TEST(ToolBitmaps, SplitCheckEqualsTheWholeCheck) {
  const std::string text =
      "O0001\nT0101\nT0505 (no bitmap)\nT1313 (off the turret)\nT5\nG65 P9000 T7. (an argument, not a tool)\n"
      "#1=5\nT#1\nT0909 T0202\n/T0606\nM30\nO9000\nM99\n";
  for (Dialect d : {Dialect::Fanuc, Dialect::Haas, Dialect::Classic}) {
    const Program p = parse(text, 1);
    CheckOptions with;
    with.dialect = d;
    with.toolsWithBitmap = std::vector<int>{1, 2, 3};
    CheckOptions without = with;
    without.toolsWithBitmap.reset();
    std::vector<Diagnostic> split = check(p, without);
    const std::vector<Diagnostic> tools = checkToolBitmaps(p, with);
    split.insert(split.end(), tools.begin(), tools.end());
    EXPECT_EQ(listed(split), listed(check(p, with))) << dialectName(d);
    EXPECT_TRUE(checkToolBitmaps(p, without).empty());
  }
  // Fanuc: T0505, T0909 and T0606 have no bitmap; T1313 is a bad word (E-code), T#1 is known at run time.
  CheckOptions fanuc;
  fanuc.toolsWithBitmap = std::vector<int>{1, 2, 3};
  const std::vector<std::string> e305 = listed(checkToolBitmaps(parse(text, 1), fanuc));
  EXPECT_EQ(e305, (std::vector<std::string>{"E305@3:1|T0505|05", "E305@9:1|T0909|09", "E305@10:2|T0606|06"}));
}

}  // namespace
}  // namespace klueng::core::gcode
