#include <cstdio>

int main() {
  std::puts("klueng-cli: not yet");
  return 0;
}
