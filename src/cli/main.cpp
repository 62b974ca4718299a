// klueng-cli: the command-line twin of the simulator.
#include <cstdio>
#include <string>
#include <vector>

#include "batch_memory.h"
#include "commands.h"

namespace {

void printUsage(std::FILE* out) {
  std::fputs(
      "usage: klueng-cli check FILE... [--lang en|th] [--dialect fanuc|haas|classic] [--json]\n"
      "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
      "       klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR]\n"
      "                               [--lang en|th] [--dialect fanuc|haas|classic]\n"
      "                               [--stock DxL[xBORE][in]] [--units mm|inch] [--tool N=ID]...\n"
      "       klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv]\n"
      "                               [--dialect fanuc|haas|classic] [--config DIR]\n"
      "       klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th]\n"
      "                               [--dialect ...] [--stock ...] [--units ...] [--config DIR]\n"
      "       klueng-cli generate PART.json|PART.dxf -o OUT.nc [--dialect ...] [--material M]\n"
      "                               [--tool-material hss|carbide] [--layer NAME] [--stock DxL[xBORE]]\n"
      "  --dialect  fanuc (Fanuc 0i-TF, default), haas (Haas ST lathe), classic (1999 rules)\n"
      "  --stock  50x100 (mm), 2.1x4in, 118x80x90 (tube: bore 90); without it the file's\n"
      "           header, else the stock inferred from the program (a note says which)\n"
      "  --units  power-on units before any G20/G21: mm or inch\n"
      "  --decimal-point whole|increments  (check, simulate, print) a length without a decimal point:\n"
      "           X30 = 30 mm, or 0.030 mm as a standard Fanuc/Haas; default: the program's numbers\n"
      "  --tool N=ID   library tool ID at turret station N for this run (e.g. --tool 12=parting-3mm);\n"
      "                see resources/tools/library/library.cfg and docs/tools.md for the IDs\n",
      out);
}

}  // namespace

int main(int argc, char** argv) {
  klueng::cli::prepareBatchMemory();
  if (argc < 2) {
    printUsage(stderr);
    return 2;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  if (command == "check") return klueng::cli::runCheck(args);
  if (command == "simulate") return klueng::cli::runSimulate(args);
  if (command == "class") return klueng::cli::runClass(args);
  if (command == "print") return klueng::cli::runPrint(args);
  if (command == "generate") return klueng::cli::runGenerate(args);
  if (command == "--help" || command == "-h" || command == "help") {
    printUsage(stdout);
    return 0;
  }
  std::fprintf(stderr, "klueng-cli: unknown command '%s'\n", command.c_str());
  printUsage(stderr);
  return 2;
}
