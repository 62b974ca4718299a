#pragma once
// Helpers for the machine tests: run a G-code text (line 1 = first line) with
// a known machine setup.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "klueng/core/gcode/parser.h"
#include "klueng/core/machine/interpreter.h"

namespace klueng::core::machine::testing {

// A scratch folder of its own per test (and process), removed afterwards:
// `prefix` names the suite, `sub` a folder made inside it.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::string& prefix, const std::string& sub = {}) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("klueng-" + prefix + "-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(sub.empty() ? path_ : path_ / sub);
  }
  ~ScratchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return (path_ / name).string();
  }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// The shipped defaults: rapids X 4000 / Z 8000 mm/min, max 3000 rpm, tool at
// X0 Z300 = reference point. Offset 01: R0.8 tip 3 (outside turning tool),
// 02: X +0.4 (diameter) Z -0.2, R0 tip 0; 03: R0 tip 8; 04: R0.4 tip 2.
inline MachineSetup testSetup() {
  MachineSetup s;
  s.offsets.offsets[0] = {0.0, 0.0, 0.8, 3};
  s.offsets.offsets[1] = {0.4, -0.2, 0.0, 0};
  s.offsets.offsets[2] = {0.0, 0.0, 0.0, 8};
  s.offsets.offsets[3] = {0.0, 0.0, 0.4, 2};
  for (auto& b : s.tools.bitmap) b = "tool.bmp";
  return s;
}

inline Timeline runText(std::string_view text, const RunOptions& options = {},
                        const MachineSetup& setup = testSetup()) {
  const gcode::Program program = gcode::parse(text, 1);
  EXPECT_TRUE(program.lexicalDiagnostics.empty()) << "the test program does not parse";
  return interpret(program, setup, options);
}

// Points in the tests are written as (X diameter, Z), like the program.
inline Vec2 at(double xDiameter, double z) { return Vec2(z, xDiameter / 2.0); }

}  // namespace klueng::core::machine::testing

#define EXPECT_POINT(actual, xDiameter, z)                          \
  do {                                                              \
    const ::klueng::core::Vec2 p_ = (actual);                       \
    EXPECT_NEAR(2.0 * p_.y(), (xDiameter), 1e-6) << "X (diameter)"; \
    EXPECT_NEAR(p_.x(), (z), 1e-6) << "Z";                          \
  } while (0)
