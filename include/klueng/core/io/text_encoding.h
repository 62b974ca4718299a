#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace klueng::core::io {

bool isValidUtf8(std::string_view bytes);
// TIS-620 / Windows-874 bytes to UTF-8.
std::string tis620ToUtf8(std::string_view bytes);
// UTF-16 text (a BOM, or the NULs of ASCII text in UTF-16 without one) as UTF-8;
// nullopt when the bytes are not UTF-16 text. Notepad's "Unicode" saves this way.
std::optional<std::string> utf16ToUtf8(std::string_view bytes);
// Number of code points in the UTF-8 text (invalid bytes count one each).
int utf8Length(std::string_view text);

}  // namespace klueng::core::io
