// klueng-cli: the command-line twin of the simulator.
#include <cstdio>
#include <string>
#include <vector>

#include "batch_memory.h"
#include "cli_common.h"
#include "commands.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/file_write.h"

namespace {

void printUsage(std::FILE* out, klueng::core::Lang lang) {
  const std::string text = klueng::cli::cliText(klueng::core::codes::kCliUsage, lang);
  std::fwrite(text.data(), 1, text.size(), out);
}

}  // namespace

int main(int argc, char** argv) {
  klueng::cli::prepareBatchMemory();
  // Ctrl+C or a kill during a write leaves no `.out.csv.tmp-*` behind (issue 42).
  klueng::core::io::removeTemporaryFilesOnSignals();
  const klueng::core::Lang lang = klueng::cli::langOfArgs(std::vector<std::string>(argv + 1, argv + argc));
  if (argc < 2) {
    printUsage(stderr, lang);
    return 2;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "check") return klueng::cli::runCheck(args);
  if (command == "simulate") return klueng::cli::runSimulate(args);
  if (command == "class") return klueng::cli::runClass(args);
  if (command == "print") return klueng::cli::runPrint(args);
  if (command == "generate") return klueng::cli::runGenerate(args);
  if (command == "--version") {
    std::printf("klueng-cli %s\n", KLUENG_VERSION);
    return 0;
  }
  if (command == "--help" || command == "-h" || command == "help") {
    printUsage(stdout, lang);
    return 0;
  }
  klueng::cli::printCliError("", klueng::core::codes::kCliUnknownCommand, lang, {command});
  printUsage(stderr, lang);
  return 2;
}
