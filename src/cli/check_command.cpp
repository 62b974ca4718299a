#include <cstdio>

#include "commands.h"

namespace klueng::cli {

int runCheck(const std::vector<std::string>&) {
  std::fputs("klueng-cli check: not built yet\n", stderr);
  return 2;
}

}  // namespace klueng::cli
