#include "klueng/core/diagnostic.h"

#include <algorithm>

namespace klueng::core {

bool hasErrors(const std::vector<Diagnostic>& diags) {
  return std::any_of(diags.begin(), diags.end(),
                     [](const Diagnostic& d) { return isError(d.severity); });
}

}  // namespace klueng::core
