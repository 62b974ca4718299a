// klueng-cli: the command-line twin of the simulator.
#include <cstdio>
#include <string>
#include <vector>

#include "commands.h"

namespace {

void printUsage(std::FILE* out) {
  std::fputs(
      "usage: klueng-cli check FILE... [--lang en|th] [--dialect fanuc|classic] [--json] [--tool N=ID]...\n"
      "       klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
      "                               [--lang en|th] [--dialect fanuc|classic] [--tool N=ID]...\n"
      "  --tool N=ID   library tool ID at turret station N for this run (e.g. --tool 12=parting-3mm);\n"
      "                see resources/tools/library/library.cfg and docs/tools.md for the IDs\n",
      out);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    printUsage(stderr);
    return 2;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "check") return klueng::cli::runCheck(args);
  if (command == "simulate") return klueng::cli::runSimulate(args);
  if (command == "--help" || command == "-h" || command == "help") {
    printUsage(stdout);
    return 0;
  }
  std::fprintf(stderr, "klueng-cli: unknown command '%s'\n", command.c_str());
  printUsage(stderr);
  return 2;
}
