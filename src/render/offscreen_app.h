#pragma once
// Text needs Qt's font database, and that a GUI application object: the
// picture module makes an offscreen one, once, when the CLI has none.
#include <QCoreApplication>
#include <QGuiApplication>

namespace klueng::render {

inline void ensureGuiApplication() {
  if (QCoreApplication::instance()) return;
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  static int argc = 1;
  static char name[] = "klueng-cli";
  static char* argv[] = {name, nullptr};
  static QGuiApplication* app = new QGuiApplication(argc, argv);
  (void)app;
}

}  // namespace klueng::render
