// klueng-gen-program BLOCKS OUT.txt
// Writes a Klueng program file (6-line header, O0001, then exactly BLOCKS
// N-numbered blocks) of a realistic lathe job, for benchmarks and tests.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "program_generator.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s BLOCKS OUT.txt\n  BLOCKS: number of body blocks (>= %d)\n", argv[0],
                 klueng::bench::ProgramGenerator::kMinimumBlocks);
    return 2;
  }
  char* end = nullptr;
  errno = 0;
  const long blocks = std::strtol(argv[1], &end, 10);
  if (errno != 0 || end == argv[1] || *end != '\0' || blocks < klueng::bench::ProgramGenerator::kMinimumBlocks ||
      blocks > 50'000'000) {
    std::fprintf(stderr, "%s: BLOCKS must be an integer from %d to 50000000, not '%s'\n", argv[0],
                 klueng::bench::ProgramGenerator::kMinimumBlocks, argv[1]);
    return 2;
  }
  const std::string text = klueng::bench::ProgramGenerator::generate(static_cast<int>(blocks));
  std::FILE* out = std::fopen(argv[2], "wb");
  if (!out) {
    std::fprintf(stderr, "%s: cannot write '%s': %s\n", argv[0], argv[2], std::strerror(errno));
    return 1;
  }
  const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (std::fclose(out) != 0 || !ok) {
    std::fprintf(stderr, "%s: error writing '%s'\n", argv[0], argv[2]);
    return 1;
  }
  return 0;
}
