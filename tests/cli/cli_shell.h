#pragma once
// Running the CLI under test through a shell, for the tests that need pipes, FIFOs or odd names.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace klueng::test {

// The CLI under test; KLUENG_CLI_UNDER_TEST runs the tests against another build (an older one, to see them fail).
inline std::string cliUnderTest(const char* builtPath) {
  const char* other = std::getenv("KLUENG_CLI_UNDER_TEST");
  return other ? other : builtPath;
}

// `s` as one word of a POSIX shell.
inline std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A shell command's output (stdout and stderr together) and its exit status (-1: it did not exit).
inline int runShell(const std::string& command, std::string& out) {
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buf[4096];
  out.clear();
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  const int status = ::pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The CLI in the C locale (English messages), cut off after `seconds` (exit 124 then).
inline std::string cliCommand(const std::string& cli, int seconds) {
  return "env LC_ALL= LC_MESSAGES= LANG=C timeout " + std::to_string(seconds) + " " + shellQuote(cli);
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void put(const std::filesystem::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

}  // namespace klueng::test
