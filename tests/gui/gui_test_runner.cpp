// main() of klueng_gui_tests: runs the one test class named by the first argument
// (see gui_test_runner.h), with the application QTEST_MAIN would make.
#include "gui_test_runner.h"

#include <QApplication>
#include <cstdio>
#include <cstring>
#include <vector>

namespace klueng::gui_test {

namespace {
std::vector<RunnerEntry>& registry() {
  static std::vector<RunnerEntry> entries;  // filled before main() by the test files
  return entries;
}
}  // namespace

bool registerGuiTest(RunnerEntry entry) {
  registry().push_back(entry);
  return true;
}

}  // namespace klueng::gui_test

int main(int argc, char** argv) {
  using klueng::gui_test::registry;
  const klueng::gui_test::RunnerEntry* entry = nullptr;
  if (argc > 1)
    for (const auto& e : registry())
      if (std::strcmp(e.name, argv[1]) == 0) entry = &e;
  if (!entry) {
    std::fprintf(stderr, "usage: %s TEST_CLASS [QTest options]\n%s%s%s", argv[0],
                 argc > 1 ? "unknown test class: " : "", argc > 1 ? argv[1] : "", argc > 1 ? "\n" : "");
    std::fprintf(stderr, "test classes:\n");
    for (const auto& e : registry()) std::fprintf(stderr, "  %s\n", e.name);
    return 2;
  }
  // QTest sees the program name and the options after the class, as if run alone.
  std::vector<char*> args{argv[0]};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  int qtArgc = argc - 1;
  entry->initMain();
  QApplication app(qtArgc, args.data());
  app.setAttribute(Qt::AA_Use96Dpi, true);
  return entry->run(qtArgc, args.data());
}
