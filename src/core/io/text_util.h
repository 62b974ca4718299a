#pragma once
// Helpers shared by the io readers (private to the io module).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/io/program_file.h"

namespace klueng::core::io::detail {

constexpr std::size_t kMaxFileBytes = 64u * 1024u * 1024u;
constexpr int kMaxLineChars = 4096;

Diagnostic makeDiagnostic(Severity severity, std::string code, int line, int column, int length,
                          std::vector<std::string> args);

// Reads a whole file, refusing folders, missing files and files over maxBytes
// with F101/F102/F103 diagnostics. nullopt on failure.
std::optional<std::string> readFileBytes(const std::string& path, std::vector<Diagnostic>& diags,
                                         std::size_t maxBytes = kMaxFileBytes);

// Position (1-based line, byte column) of the first NUL byte, if any.
struct BytePosition {
  int line = 0;
  int column = 0;
};
std::optional<BytePosition> findNulByte(std::string_view bytes);

// UTF-8 text with the BOM removed; TIS-620 bytes converted when not valid UTF-8.
std::string decodeText(std::string_view bytes, SourceEncoding* encoding = nullptr);
// The same without a copy of UTF-8 text: a view into bytes, or into
// `converted` when the bytes were TIS-620.
std::string_view decodeTextView(std::string_view bytes, std::string& converted, SourceEncoding* encoding = nullptr);

// Lines split at LF, CRLF or CR; a line end after the last line does not start a new line.
std::vector<std::string_view> splitLines(std::string_view text);
bool endsWithLineBreak(std::string_view text);

std::string_view trim(std::string_view s);
// 1-based code point column of `part`, which must point into `line`.
int columnOf(std::string_view line, std::string_view part);

// A decimal number: optional sign, digits with an optional point, optional exponent.
// No hex, inf or nan; the whole text must be the number.
std::optional<double> parseNumber(std::string_view text);
// Shortest text that parseNumber reads back as the same double.
std::string formatNumber(double value);

// A setup file's readers stop at codes::kMaxConfigDiagnostics problems: true
// (and F129 at `line`, an error when any problem so far is one) once `diags`
// holds that many; the caller stops reading.
bool configProblemsFull(std::vector<Diagnostic>& diags, const std::string& fileName, int line);

// Whitespace-separated fields of a line.
std::vector<std::string_view> splitFields(std::string_view line);

}  // namespace klueng::core::io::detail
