#pragma once
// The GUI tests share one executable, klueng_gui_tests (issue 29 item 13: one link of
// klueng_gui and Qt instead of one per test file). A test file ends with
// KLUENG_GUI_TEST(Class) where a stand-alone test would say QTEST_MAIN(Class);
// `klueng_gui_tests Class [QTest options]` runs that class alone in its own process,
// as ctest does, one entry per class. A file that needs its own main() keeps it and
// stays a separate executable (tests/gui/CMakeLists.txt tells them apart).
#include <QObject>
#include <QTest>

namespace klueng::gui_test {

struct RunnerEntry {
  const char* name;
  void (*initMain)();  // before the QApplication exists, as QTEST_MAIN does
  int (*run)(int argc, char** argv);
};

// Called at static initialisation by KLUENG_GUI_TEST; returns a dummy for the static.
bool registerGuiTest(RunnerEntry entry);

}  // namespace klueng::gui_test

#define KLUENG_GUI_TEST(TestObject)                                                                          \
  static const bool klueng_gui_test_registered_##TestObject =                                                \
      ::klueng::gui_test::registerGuiTest({#TestObject, [] { QTest::Internal::callInitMain<TestObject>(); }, \
                                           [](int argc, char** argv) {                                       \
                                             TestObject tc;                                                  \
                                             QTEST_SET_MAIN_SOURCE_PATH                                      \
                                             return QTest::qExec(&tc, argc, argv);                           \
                                           }});
