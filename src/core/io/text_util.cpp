#include "io/text_util.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "klueng/core/io/file_read.h"
#include "klueng/core/io/text_encoding.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/number_read.h"

namespace klueng::core::io::detail {

Diagnostic makeDiagnostic(Severity severity, std::string code, int line, int column, int length,
                          std::vector<std::string> args) {
  return Diagnostic{severity, std::move(code), SourceRange{line, column, length}, std::move(args)};
}

bool configProblemsFull(std::vector<Diagnostic>& diags, const std::string& fileName, int line) {
  if (diags.size() < codes::kMaxConfigDiagnostics) return false;
  const bool errors = std::any_of(diags.begin(), diags.end(), [](const Diagnostic& d) { return isError(d.severity); });
  diags.push_back(makeDiagnostic(errors ? Severity::Error : Severity::Warning, codes::kTooManyConfigProblems, line,
                                 line > 0 ? 1 : 0, 0, {fileName, std::to_string(codes::kMaxConfigDiagnostics)}));
  return true;
}

std::optional<std::string> readFileBytes(const std::string& path, std::vector<Diagnostic>& diags,
                                         std::size_t maxBytes) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec == std::errc::filename_too_long) {
    diags.push_back(
        makeDiagnostic(Severity::Error, codes::kPathTooLong, 0, 0, 0, {path, std::to_string(utf8Length(path))}));
    return std::nullopt;
  }
  if (!fs::exists(status)) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kNoSuchFile, 0, 0, 0, {path}));
    return std::nullopt;
  }
  if (fs::is_directory(status)) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kCannotReadFile, 0, 0, 0, {path}));
    return std::nullopt;
  }
  // A named pipe would wait for a writer for ever: refused unopened (F157). A
  // pipe we hold (standard input, a shell's <(cmd)) is read until its end below.
  if (std::optional<Diagnostic> refused = wouldBlockOnOpen(path)) {
    diags.push_back(std::move(*refused));
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kCannotReadFile, 0, 0, 0, {path}));
    return std::nullopt;
  }
  // Regular files report their size; read in chunks anyway so a pipe or a
  // growing file cannot push us past the limit.
  std::string bytes;
  const std::uintmax_t size = fs::is_regular_file(status) ? fs::file_size(path, ec) : 0;
  if (!ec && size > maxBytes) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kFileTooLarge, 0, 0, 0,
                                   {path, std::to_string(size), sizeLimitText(maxBytes)}));
    return std::nullopt;
  }
  // The size the file reports is read straight into the string (no copy
  // through a buffer); whatever follows, if it grew, is read in chunks.
  if (!ec && size > 0) {
    bytes.resize(static_cast<std::size_t>(size));
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
  }
  char buffer[65536];
  while (in && (in.read(buffer, sizeof buffer) || in.gcount() > 0)) {
    bytes.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (bytes.size() > maxBytes) {
      diags.push_back(makeDiagnostic(Severity::Error, codes::kFileTooLarge, 0, 0, 0,
                                     {path, std::to_string(bytes.size()), sizeLimitText(maxBytes)}));
      return std::nullopt;
    }
  }
  if (in.bad()) {
    diags.push_back(makeDiagnostic(Severity::Error, codes::kCannotReadFile, 0, 0, 0, {path}));
    return std::nullopt;
  }
  return bytes;
}

std::optional<BytePosition> findNulByte(std::string_view bytes) {
  const std::size_t nul = bytes.find('\0');
  if (nul == std::string_view::npos) return std::nullopt;
  BytePosition pos{1, 1};
  for (std::size_t i = 0; i < nul; ++i) {
    if (bytes[i] == '\n' || (bytes[i] == '\r' && (i + 1 >= bytes.size() || bytes[i + 1] != '\n'))) {
      ++pos.line;
      pos.column = 1;
    } else if (bytes[i] != '\r') {
      ++pos.column;
    }
  }
  return pos;
}

std::string decodeText(std::string_view bytes, SourceEncoding* encoding) {
  std::string converted;
  const std::string_view text = decodeTextView(bytes, converted, encoding);
  return converted.empty() ? std::string(text) : converted;
}

std::string_view decodeTextView(std::string_view bytes, std::string& converted, SourceEncoding* encoding) {
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  if (isValidUtf8(bytes)) {
    if (encoding) *encoding = SourceEncoding::Utf8;
    return bytes;
  }
  if (encoding) *encoding = SourceEncoding::Tis620;
  converted = tis620ToUtf8(bytes);
  return converted;
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  if (text.find('\r') == std::string_view::npos) {
    // LF only (the usual case): let find() (memchr) do the scanning, into one
    // allocation (std::count runs over the text in wide strides; a program has
    // 100,000 lines, and regrowth would copy them some 17 times).
    lines.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
    for (std::size_t end; (end = text.find('\n', start)) != std::string_view::npos; start = end + 1)
      lines.push_back(text.substr(start, end - start));
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
  }
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      lines.push_back(text.substr(start, i - start));
      // CRLF is one line end; so is CR CR LF (a CRLF file converted once more).
      if (text[i] == '\r' && i + 2 < text.size() && text[i + 1] == '\r' && text[i + 2] == '\n') i += 1;
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

bool endsWithLineBreak(std::string_view text) { return !text.empty() && (text.back() == '\n' || text.back() == '\r'); }

std::string_view trim(std::string_view s) {
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
  while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
  return s;
}

int columnOf(std::string_view line, std::string_view part) {
  const auto offset = static_cast<std::size_t>(part.data() - line.data());
  return utf8Length(line.substr(0, offset)) + 1;
}

std::optional<double> parseNumber(std::string_view text) {
  if (text.empty()) return std::nullopt;
  std::size_t i = 0;
  if (text[i] == '+' || text[i] == '-') ++i;
  std::size_t digits = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++digits;
  }
  if (digits == 0) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t expDigits = 0;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i, ++expDigits;
    if (expDigits == 0) return std::nullopt;
  }
  if (i != text.size()) return std::nullopt;
  // from_chars does not take a leading '+'.
  std::string_view body = text.front() == '+' ? text.substr(1) : text;
  double value = 0.0;
  const auto [end, ec] = readDouble(body.data(), body.data() + body.size(), value);
  if (ec != std::errc() || end != body.data() + body.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::string formatNumber(double value) {
  if (value == 0.0) return "0";  // also turns -0 into 0
  return fmt::format("{}", value);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  const auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; };
  while (i < line.size()) {
    while (i < line.size() && isSpace(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isSpace(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

}  // namespace klueng::core::io::detail
