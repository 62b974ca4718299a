#include <cstdio>

#include "commands.h"

namespace klueng::cli {

int runSimulate(const std::vector<std::string>&) {
  std::fputs("klueng-cli simulate: not built yet\n", stderr);
  return 2;
}

}  // namespace klueng::cli
