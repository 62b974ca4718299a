// The #500-#999 file (macro_variables.h).
#include "klueng/core/io/macro_variables.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "io/text_util.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/number_read.h"

#ifndef _WIN32
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#endif

namespace klueng::core::io {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

}  // namespace

ReadResult<MacroVariables> parseMacroVariables(std::string_view text, const std::string& fileName) {
  ReadResult<MacroVariables> result;
  MacroVariables values;
  int lineNumber = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++lineNumber;
    if (detail::configProblemsFull(result.diagnostics, fileName, lineNumber)) break;
    if (const std::size_t c = line.find(';'); c != std::string_view::npos) line = line.substr(0, c);
    const std::string_view body = trim(line);
    if (body.empty()) continue;
    const int column = static_cast<int>(body.data() - line.data()) + 1;
    const auto bad = [&](const char* code, std::string arg) {
      result.diagnostics.push_back(detail::makeDiagnostic(Severity::Warning, code, lineNumber, column,
                                                          static_cast<int>(body.size()), {fileName, std::move(arg)}));
    };
    const std::size_t eq = body.find('=');
    if (body.front() != '#' || eq == std::string_view::npos) {
      bad(codes::kNotVariableLine, std::string(body.substr(0, 40)));
      continue;
    }
    const std::string_view name = trim(body.substr(1, eq - 1));
    const std::string_view value = trim(body.substr(eq + 1));
    int number = 0;
    double v = 0.0;
    const auto n1 = std::from_chars(name.data(), name.data() + name.size(), number);
    const auto n2 = readDouble(value.data(), value.data() + value.size(), v);
    if (name.empty() || n1.ec != std::errc() || n1.ptr != name.data() + name.size() || value.empty() ||
        n2.ec != std::errc() || n2.ptr != value.data() + value.size() || !std::isfinite(v)) {
      bad(codes::kNotVariableLine, std::string(body.substr(0, 40)));
      continue;
    }
    if (number < 500 || number > 999) {
      bad(codes::kVariableNotKept, std::to_string(number));
      continue;
    }
    values[number] = v;
  }
  result.value = std::move(values);
  return result;
}

ReadResult<MacroVariables> readMacroVariables(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return ReadResult<MacroVariables>{MacroVariables{}, {}};
  ReadResult<MacroVariables> result;
  std::optional<std::string> bytes = detail::readFileBytes(path, result.diagnostics, 1024 * 1024);
  if (!bytes) return result;
  return parseMacroVariables(*bytes, path);
}

std::string formatMacroVariables(const MacroVariables& values) {
  std::string out = "; Klueng macro variables #500-#999 (kept between runs, as a control keeps them)\n";
  for (const auto& [n, v] : values) {
    std::string text = fmt::format("{:.6f}", v);
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    if (text == "-0") text = "0";
    out += fmt::format("#{} = {}\n", n, text);
  }
  return out;
}

std::string macroVariablesPath(const std::string& folder) {
  return (std::filesystem::path(folder.empty() ? "." : folder) / std::string(kMacroVariablesFile)).string();
}

}  // namespace klueng::core::io

namespace klueng::core::io {

MacroVariablesLock::MacroVariablesLock(const std::string& folder) {
#ifndef _WIN32
  fd_ = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) return;
  while (::flock(fd_, LOCK_EX) != 0) {
    if (errno == EINTR) continue;
    ::close(fd_);  // a file system without locks: run unlocked, as before
    fd_ = -1;
    return;
  }
#else
  (void)folder;
#endif
}

MacroVariablesLock::~MacroVariablesLock() {
#ifndef _WIN32
  if (fd_ >= 0) ::close(fd_);  // closing releases the lock
#endif
}

}  // namespace klueng::core::io
