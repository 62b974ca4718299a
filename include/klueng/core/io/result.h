#pragma once
// Readers return the value plus every diagnostic found (F1xx codes with file
// line/column); value is empty only when nothing usable could be read.
#include <optional>
#include <string>
#include <vector>

#include "klueng/core/diagnostic.h"

namespace klueng::core::io {

template <typename T>
struct ReadResult {
  std::optional<T> value;
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return value.has_value() && !hasErrors(diagnostics); }
};

}  // namespace klueng::core::io
