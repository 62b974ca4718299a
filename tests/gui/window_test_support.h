#pragma once
// The main window as most GUI tests start it: English, fresh user folders, a
// shipped sample open at the classroom's screen size and checked.
#include <QString>
#include <QTest>

#include "fresh_user_folders.h"
#include "gui/language.h"
#include "gui/main_window.h"
#include "gui/resources.h"

namespace klueng::test {

// initTestCase of a window test: its own user folders, the resources, English.
inline void startInEnglish() {
  freshUserFolders();
  gui::initResources();
  gui::Language::instance()->setLanguage(QStringLiteral("en"));
}

// Shows `w` at 1366 × 728 with the sample open and its check done; false when it
// could not be opened or checked within 30 s.
inline bool showSample(gui::MainWindow& w, const QString& sample = QStringLiteral("01-step-shaft.txt")) {
  w.resize(1366, 728);
  w.show();
  return w.openFile(QStringLiteral(KLUENG_SAMPLES_DIR "/") + sample) &&
         QTest::qWaitFor([&w] { return !w.isBusy(); }, 30000);
}

}  // namespace klueng::test
