#pragma once
// Scratch folders named PREFIX + the process id go with the test process (ctest runs each test in
// a process of its own), so a run leaves nothing in the temporary folder.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace klueng::test {

class ScratchFoldersCleanup : public ::testing::Environment {
 public:
  explicit ScratchFoldersCleanup(std::vector<std::string> prefixes) : prefixes_(std::move(prefixes)) {}
  void TearDown() override {
    for (const std::string& prefix : prefixes_) {
      std::error_code ec;
      std::filesystem::remove_all(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid())), ec);
    }
  }

 private:
  std::vector<std::string> prefixes_;
};

// Once per test file, at namespace scope: `const auto* const kCleanup = removeScratchFoldersAtExit({"x-"});`
inline ::testing::Environment* removeScratchFoldersAtExit(std::vector<std::string> prefixes) {
  return ::testing::AddGlobalTestEnvironment(new ScratchFoldersCleanup(std::move(prefixes)));
}

}  // namespace klueng::test
