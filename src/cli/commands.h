#pragma once
// klueng-cli subcommands. Each returns the process exit status.
#include <string>
#include <vector>

namespace klueng::cli {

// klueng-cli check FILE... [--lang en|th] [--dialect fanuc|haas|classic] [--json]
int runCheck(const std::vector<std::string>& args);
// klueng-cli simulate FILE [--trace out.csv] [--cycle-time] [--config DIR] [--lang en|th] ...
int runSimulate(const std::vector<std::string>& args);
// klueng-cli class DIR --reference REF.nc [--tolerance 0.05] [--csv OUT.csv] ...
int runClass(const std::vector<std::string>& args);
// klueng-cli print FILE --pdf OUT.pdf [--sheet program|drawing|both] [--lang en|th] ...
int runPrint(const std::vector<std::string>& args);
// klueng-cli generate PART.json -o OUT.nc [--dialect ...] [--material M] [--tool-material hss|carbide]
int runGenerate(const std::vector<std::string>& args);

}  // namespace klueng::cli
