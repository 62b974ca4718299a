#include "gui/recovery.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QUuid>
#include <algorithm>
#include <csignal>
#include <cerrno>
#include <unistd.h>

#include "gui/file_save.h"
#include "klueng/core/io/program_file.h"

namespace klueng::gui {

namespace {

QString noteOf(const QString& folder, const QString& id) { return QDir(folder).filePath(id + QStringLiteral(".ini")); }
QString copyOf(const QString& folder, const QString& id) { return QDir(folder).filePath(id + QStringLiteral(".nc")); }

bool processRunning(qint64 pid) {
  if (pid <= 0) return false;
  if (pid == static_cast<qint64>(::getpid())) return true;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

QStringList linesOf(const QString& path) {
  const auto read = core::io::readProgramFile(path.toStdString());
  if (!read.value) return {};
  return QString::fromStdString(read.value->gcode).split(QLatin1Char('\n'));
}

}  // namespace

Recovery::Recovery(QString folder) : folder_(std::move(folder)) {
  if (folder_.isEmpty())
    folder_ = QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
                  .filePath(QStringLiteral("klueng/recovery"));
}

QString Recovery::newId() { return QUuid::createUuid().toString(QUuid::WithoutBraces); }

bool Recovery::write(const QString& id, const std::string& contents, const QString& originalPath,
                     const QString& displayName, QString* error) const {
  if (!QDir().mkpath(folder_)) {
    if (error) *error = folder_;
    return false;
  }
  if (const QString why = writeFileChecked(copyOf(folder_, id), contents); !why.isEmpty()) {
    if (error) *error = why;
    return false;
  }
  QSettings note(noteOf(folder_, id), QSettings::IniFormat);
  note.setValue(QStringLiteral("path"), originalPath);
  note.setValue(QStringLiteral("name"), displayName);
  note.setValue(QStringLiteral("written"), QDateTime::currentDateTime());
  note.setValue(QStringLiteral("pid"), static_cast<qint64>(::getpid()));
  note.sync();
  return note.status() == QSettings::NoError;
}

void Recovery::remove(const QString& id) const {
  QFile::remove(copyOf(folder_, id));
  QFile::remove(noteOf(folder_, id));
}

QVector<RecoveryCopy> Recovery::orphans() const {
  QVector<RecoveryCopy> out;
  const QDir dir(folder_);
  for (const QString& name : dir.entryList({QStringLiteral("*.ini")}, QDir::Files)) {
    RecoveryCopy c;
    c.id = QFileInfo(name).completeBaseName();
    c.copyPath = copyOf(folder_, c.id);
    if (!QFileInfo::exists(c.copyPath)) continue;
    const QSettings note(dir.filePath(name), QSettings::IniFormat);
    c.originalPath = note.value(QStringLiteral("path")).toString();
    c.displayName = note.value(QStringLiteral("name")).toString();
    c.written = note.value(QStringLiteral("written")).toDateTime();
    c.pid = note.value(QStringLiteral("pid")).toLongLong();
    if (processRunning(c.pid)) continue;  // another Klueng's live copy
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const RecoveryCopy& a, const RecoveryCopy& b) { return a.written > b.written; });
  return out;
}

RecoveryDifference Recovery::difference(const RecoveryCopy& copy) {
  RecoveryDifference d;
  const QStringList mine = linesOf(copy.copyPath);
  if (copy.originalPath.isEmpty() || !QFileInfo::exists(copy.originalPath)) {
    d.fileMissing = true;
    d.linesDiffering = static_cast<int>(mine.size());
    d.firstLine = mine.isEmpty() ? 0 : 1;
    return d;
  }
  const auto original = core::io::readProgramFile(copy.originalPath.toStdString());
  const QStringList theirs = linesOf(copy.originalPath);
  const int first = original.value ? original.value->gcodeFirstLine : 1;
  const qsizetype n = std::max(mine.size(), theirs.size());
  for (qsizetype i = 0; i < n; ++i) {
    const bool same = i < mine.size() && i < theirs.size() && mine[i] == theirs[i];
    if (same) continue;
    ++d.linesDiffering;
    if (d.firstLine == 0) d.firstLine = first + static_cast<int>(i);
  }
  return d;
}

}  // namespace klueng::gui
