#include "klueng/core/diagnostic.h"

#include <algorithm>

namespace klueng::core {

bool hasErrors(const std::vector<Diagnostic>& diags) {
  return std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return isError(d.severity); });
}

void sortByPlace(std::vector<Diagnostic>& diags) {
  std::stable_sort(diags.begin(), diags.end(), [](const Diagnostic& a, const Diagnostic& b) {
    if (a.range.file != b.range.file) return a.range.file < b.range.file;
    if (a.range.line != b.range.line) return a.range.line < b.range.line;
    return a.range.column < b.range.column;
  });
}

}  // namespace klueng::core
