#pragma once
// Per-user settings, recovery copies and the user's tool tables of a GUI test go to a
// fresh folder of this process: tests running side by side (ctest -j) never share
// them, and a run never sees what an earlier run saved. (QStandardPaths' test mode is
// one folder under $HOME shared by every test.)
#include <QByteArray>
#include <QDir>
#include <QSettings>
#include <QTemporaryDir>

namespace klueng::test {

inline QString freshUserFolders() {
  static QTemporaryDir home;
  static const bool once = [] {
    const QString config = home.filePath(QStringLiteral("config"));
    const QString data = home.filePath(QStringLiteral("data"));
    QDir().mkpath(config);
    QDir().mkpath(data);
    qputenv("XDG_CONFIG_HOME", config.toUtf8());
    qputenv("XDG_DATA_HOME", data.toUtf8());
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, config);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, config);
    return true;
  }();
  (void)once;
  return home.path();
}

}  // namespace klueng::test
