// trace_compare EXPECTED ACTUAL: compares two trace CSVs field by field;
// numbers may differ by 2e-4 (the traces print 4 decimals), text must match.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> readLines(const char* path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) lines.push_back(line);
  }
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

bool asNumber(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fputs("usage: trace_compare EXPECTED ACTUAL\n", stderr);
    return 2;
  }
  const auto expected = readLines(argv[1]);
  const auto actual = readLines(argv[2]);
  int failures = 0;
  if (expected.size() != actual.size()) {
    std::fprintf(stderr, "row count: expected %zu, got %zu\n", expected.size(), actual.size());
    ++failures;
  }
  for (std::size_t r = 0; r < std::min(expected.size(), actual.size()); ++r) {
    const auto e = split(expected[r]), a = split(actual[r]);
    bool same = e.size() == a.size();
    for (std::size_t c = 0; same && c < e.size(); ++c) {
      double x = 0, y = 0;
      if (asNumber(e[c], x) && asNumber(a[c], y))
        same = std::abs(x - y) <= 2e-4;
      else
        same = e[c] == a[c];
    }
    if (!same) {
      std::fprintf(stderr, "row %zu differs:\n  expected %s\n  actual   %s\n", r + 1, expected[r].c_str(),
                   actual[r].c_str());
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
