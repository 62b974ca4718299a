#include "klueng/core/io/text_encoding.h"

#include <algorithm>

#include <cstdint>
#include <cstring>

namespace klueng::core::io {

namespace {

// Length of the valid UTF-8 sequence starting at bytes[i], or 0 when invalid
// (overlong forms, surrogates and code points above U+10FFFF are invalid).
std::size_t utf8SequenceLength(std::string_view bytes, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(bytes[i]);
  if (b0 < 0x80) return 1;
  std::size_t n = 0;
  std::uint32_t cp = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    n = 2;
    cp = b0 & 0x1Fu;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    n = 3;
    cp = b0 & 0x0Fu;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    n = 4;
    cp = b0 & 0x07u;
  } else {
    return 0;
  }
  if (i + n > bytes.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto b = static_cast<unsigned char>(bytes[i + k]);
    if ((b & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b & 0x3Fu);
  }
  if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) || cp > 0x10FFFF) return 0;
  if (cp >= 0xD800 && cp <= 0xDFFF) return 0;
  return n;
}

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

constexpr std::uint32_t kReplacement = 0xFFFD;

// Windows-874 code points of bytes 0x80..0x9F (0 = undefined).
constexpr std::uint32_t kWindows874High[32] = {
    0x20AC, 0,      0,      0,      0,      0x2026, 0,      0,       // 80-87
    0,      0,      0,      0,      0,      0,      0,      0,       // 88-8F
    0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022, 0x2013, 0x2014,  // 90-97
    0,      0,      0,      0,      0,      0,      0,      0,       // 98-9F
};

std::uint32_t tis620CodePoint(unsigned char b) {
  if (b < 0x80) return b;
  if (b < 0xA0) {
    const std::uint32_t cp = kWindows874High[b - 0x80];
    return cp ? cp : kReplacement;
  }
  if (b == 0xA0) return 0x00A0;                                    // no-break space (Windows-874)
  if ((b >= 0xDB && b <= 0xDE) || b >= 0xFC) return kReplacement;  // unassigned in TIS-620
  return 0x0E01 + (b - 0xA1);                                      // Thai block, in TIS-620 order
}

}  // namespace

bool isValidUtf8(std::string_view bytes) {
  for (std::size_t i = 0; i < bytes.size();) {
    // Programs are mostly ASCII: skip it eight bytes at a time.
    while (i + 8 <= bytes.size()) {
      std::uint64_t word;
      std::memcpy(&word, bytes.data() + i, 8);
      if (word & 0x8080808080808080ull) break;
      i += 8;
    }
    if (i >= bytes.size()) break;
    const std::size_t n = utf8SequenceLength(bytes, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string tis620ToUtf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size() * 2);
  for (char c : bytes) appendUtf8(out, tis620CodePoint(static_cast<unsigned char>(c)));
  return out;
}

int utf8Length(std::string_view text) {
  int count = 0;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8SequenceLength(text, i);
    i += n == 0 ? 1 : n;
    ++count;
  }
  return count;
}

}  // namespace klueng::core::io

namespace klueng::core::io {

std::optional<std::string> utf16ToUtf8(std::string_view bytes) {
  if (bytes.size() < 2) return std::nullopt;
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  bool little = true;
  std::size_t start = 0;
  if (byte(0) == 0xFF && byte(1) == 0xFE) {
    start = 2;
  } else if (byte(0) == 0xFE && byte(1) == 0xFF) {
    little = false;
    start = 2;
  } else {
    // No BOM: ASCII text in UTF-16 has a NUL in every other byte.
    if (bytes.size() % 2 != 0 || bytes.size() < 4) return std::nullopt;
    std::size_t evenNul = 0, oddNul = 0;
    const std::size_t n = std::min<std::size_t>(bytes.size(), 4096);
    for (std::size_t i = 0; i + 1 < n; i += 2) {
      evenNul += byte(i) == 0;
      oddNul += byte(i + 1) == 0;
    }
    const std::size_t pairs = n / 2;
    // Mostly ASCII (a G-code program is): at least half the high bytes are NUL, no low byte is.
    if (oddNul * 2 >= pairs && evenNul == 0)
      little = true;
    else if (evenNul * 2 >= pairs && oddNul == 0)
      little = false;
    else
      return std::nullopt;
  }
  if ((bytes.size() - start) % 2 != 0) return std::nullopt;
  std::string out;
  out.reserve((bytes.size() - start) / 2);
  const auto unit = [&](std::size_t i) -> unsigned {
    return little ? byte(i) | (byte(i + 1) << 8) : (byte(i) << 8) | byte(i + 1);
  };
  for (std::size_t i = start; i + 1 < bytes.size(); i += 2) {
    unsigned cp = unit(i);
    if (cp >= 0xD800 && cp <= 0xDBFF && i + 3 < bytes.size()) {
      const unsigned lo = unit(i + 2);
      if (lo >= 0xDC00 && lo <= 0xDFFF) {
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
        i += 2;
      }
    }
    if (cp == 0) return std::nullopt;  // a real NUL: binary after all
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  return out;
}

}  // namespace klueng::core::io
