// klueng-gen-program [--roughing|--yardstick [--linuxcnc] [--steps]] BLOCKS OUT.txt
// Writes a Klueng program file (6-line header, O0001, then exactly BLOCKS
// N-numbered blocks) of a realistic lathe job, for benchmarks and tests.
// --roughing: the heavy roughing job (RoughingGenerator) instead; --yardstick:
// issue 40's CAM-style roughing job (YardstickGenerator, about BLOCKS blocks);
// --linuxcnc: its blocks in LinuxCNC's rs274ngc dialect, for timing `rs274` on them;
// --steps: the yardstick's chains one word a block (5,000,000 blocks fit in 64 MB).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "program_generator.h"

int main(int argc, char** argv) {
  bool roughing = false, yardstick = false, linuxcnc = false, steps = false;
  int arg = 1;
  for (; arg < argc && argv[arg][0] == '-' && argv[arg][1] == '-'; ++arg) {
    if (std::strcmp(argv[arg], "--roughing") == 0)
      roughing = true;
    else if (std::strcmp(argv[arg], "--yardstick") == 0)
      yardstick = true;
    else if (std::strcmp(argv[arg], "--steps") == 0)
      steps = true;
    else if (std::strcmp(argv[arg], "--linuxcnc") == 0)
      linuxcnc = true;
    else
      break;
  }
  const int minimum = yardstick  ? klueng::bench::YardstickGenerator::kMinimumBlocks
                      : roughing ? klueng::bench::RoughingGenerator::kMinimumBlocks
                                 : klueng::bench::ProgramGenerator::kMinimumBlocks;
  if (argc - arg != 2 || (linuxcnc && !roughing && !yardstick) || (roughing && yardstick) || (steps && !yardstick)) {
    std::fprintf(stderr,
                 "usage: %s [--roughing|--yardstick [--linuxcnc] [--steps]] BLOCKS OUT.txt\n"
                 "  BLOCKS: number of body blocks (>= %d)\n",
                 argv[0], minimum);
    return 2;
  }
  char* end = nullptr;
  errno = 0;
  const long blocks = std::strtol(argv[arg], &end, 10);
  if (errno != 0 || end == argv[arg] || *end != '\0' || blocks < minimum || blocks > 50'000'000) {
    std::fprintf(stderr, "%s: BLOCKS must be an integer from %d to 50000000, not '%s'\n", argv[0], minimum, argv[arg]);
    return 2;
  }
  const int n = static_cast<int>(blocks);
  const std::string text = yardstick  ? klueng::bench::YardstickGenerator::generate(n, linuxcnc, steps)
                           : roughing ? klueng::bench::RoughingGenerator::generate(n, linuxcnc)
                                      : klueng::bench::ProgramGenerator::generate(n);
  const char* path = argv[arg + 1];
  std::FILE* out = std::fopen(path, "wb");
  if (!out) {
    std::fprintf(stderr, "%s: cannot write '%s': %s\n", argv[0], path, std::strerror(errno));
    return 1;
  }
  const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (std::fclose(out) != 0 || !ok) {
    std::fprintf(stderr, "%s: error writing '%s'\n", argv[0], path);
    return 1;
  }
  return 0;
}
