#include "gui/recovery.h"

#include <QCoreApplication>
#include <QDir>
#include <QHash>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QUuid>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include "gui/file_save.h"
#include "klueng/core/io/program_file.h"

namespace klueng::gui {

namespace {

QString noteOf(const QString& folder, const QString& id) { return QDir(folder).filePath(id + QStringLiteral(".ini")); }
QString copyOf(const QString& folder, const QString& id) { return QDir(folder).filePath(id + QStringLiteral(".nc")); }
QString lockOf(const QString& folder, const QString& id) { return QDir(folder).filePath(id + QStringLiteral(".lock")); }

QString tr(const char* text) { return QCoreApplication::translate("klueng::gui::Recovery", text); }

// The locks this process holds: lock file -> its open descriptor (flock LOCK_EX).
struct HeldLocks {
  std::mutex mutex;
  QHash<QString, int> fds;
};
HeldLocks& heldLocks() {
  static HeldLocks held;
  return held;
}

bool holdsLock(const QString& path) {
  HeldLocks& held = heldLocks();
  const std::lock_guard guard(held.mutex);
  return held.fds.contains(path);
}

// 0 when this process holds the lock `path` (now or already), else the errno.
int holdLock(const QString& path) {
  HeldLocks& held = heldLocks();
  const std::lock_guard guard(held.mutex);
  if (held.fds.contains(path)) return 0;
  const QByteArray native = QFile::encodeName(path);
  const int fd = ::open(native.constData(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return errno;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(fd);
    return err;
  }
  held.fds.insert(path, fd);
  return 0;
}

// Removes the lock file; closing this process's descriptor (if any) drops the lock.
void dropLock(const QString& path) {
  HeldLocks& held = heldLocks();
  const std::lock_guard guard(held.mutex);
  QFile::remove(path);
  if (const auto it = held.fds.constFind(path); it != held.fds.cend()) {
    ::close(it.value());
    held.fds.erase(it);
  }
}

enum class LockState { Held, Free, Missing };

// Held: a running Klueng (this one included) holds it; Free: nobody does (its
// writer ended, however); Missing: no lock file (a copy from before the lock).
LockState lockState(const QString& path) {
  if (holdsLock(path)) return LockState::Held;
  const QByteArray native = QFile::encodeName(path);
  const int fd = ::open(native.constData(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return LockState::Missing;
  LockState state = LockState::Free;
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0)
    ::flock(fd, LOCK_UN);
  else
    state = errno == EWOULDBLOCK ? LockState::Held : LockState::Missing;
  ::close(fd);
  return state;
}

// For copies without a lock file: is process `pid` alive? A zombie (dead, not yet
// reaped) is not.
bool processRunning(qint64 pid) {
  if (pid <= 0) return false;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return false;
  QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
  if (stat.open(QIODevice::ReadOnly)) {
    // "pid (name) S ...": the state follows the last ')'.
    const QByteArray text = stat.readAll();
    const qsizetype paren = text.lastIndexOf(')');
    if (paren >= 0 && paren + 2 < text.size() && (text[paren + 2] == 'Z' || text[paren + 2] == 'X')) return false;
  }
  return true;
}

// Why a folder could not be made, from the errno, in the UI language.
QString reasonOf(int err, const QString& folder) {
  switch (err) {
    case EACCES:
    case EPERM: return tr("permission denied");
    case EROFS: return tr("the disk is read-only");
    case ENOSPC:
#ifdef EDQUOT
    case EDQUOT:
#endif
      return tr("the disk is full");
    case ENOTDIR:
    case EEXIST: {
      // Name the file in the way: the deepest existing part of the path.
      QString part = QDir::cleanPath(folder);
      while (!part.isEmpty() && !QFileInfo::exists(part) && part != QFileInfo(part).path())
        part = QFileInfo(part).path();
      if (QFileInfo(part).exists() && !QFileInfo(part).isDir()) return tr("%1 is a file, not a folder").arg(part);
      break;
    }
    default: break;
  }
  return QString::fromLocal8Bit(std::strerror(err));
}

// The text of a program file as Save writes it, one entry per line (no empty
// entry after a final line end); nullopt when it cannot be read.
std::optional<QStringList> linesOf(const QString& path) {
  const auto read = core::io::readProgramFile(path.toStdString());
  if (!read.value) return std::nullopt;
  QString text = QString::fromStdString(core::io::formatProgramFile(*read.value));
  if (text.endsWith(QLatin1Char('\n'))) text.chop(1);
  return text.isEmpty() ? QStringList() : text.split(QLatin1Char('\n'));
}

}  // namespace

QVector<RecoveryHunk> diffLines(const QStringList& from, const QStringList& to, int maxEdits) {
  // Lines as numbers, so the search compares integers.
  QHash<QString, int> ids;
  const auto number = [&ids](const QStringList& lines) {
    std::vector<int> out;
    out.reserve(static_cast<std::size_t>(lines.size()));
    for (const QString& line : lines) {
      auto it = ids.constFind(line);
      if (it == ids.cend()) it = ids.insert(line, static_cast<int>(ids.size()));
      out.push_back(it.value());
    }
    return out;
  };
  const std::vector<int> a = number(from), b = number(to);
  // The common start and end are no part of the search.
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  int pre = 0;
  while (pre < n && pre < m && a[static_cast<std::size_t>(pre)] == b[static_cast<std::size_t>(pre)]) ++pre;
  int suf = 0;
  while (suf < n - pre && suf < m - pre &&
         a[static_cast<std::size_t>(n - 1 - suf)] == b[static_cast<std::size_t>(m - 1 - suf)])
    ++suf;
  const int N = n - pre - suf, M = m - pre - suf;
  const auto A = [&](int i) { return a[static_cast<std::size_t>(pre + i)]; };
  const auto B = [&](int i) { return b[static_cast<std::size_t>(pre + i)]; };
  QVector<RecoveryHunk> hunks;
  if (N == 0 && M == 0) return hunks;
  const RecoveryHunk whole{pre, N, pre, M};
  if (N == 0 || M == 0) return {whole};

  // Myers: V[k] = furthest x on diagonal k = x - y after d edits; trace[d] keeps V[-d..d].
  const int limit = std::min(N + M, std::max(maxEdits, 1));
  const int offset = limit + 1;
  std::vector<int> v(static_cast<std::size_t>(2 * limit + 3), 0);
  const auto V = [&](int k) -> int& { return v[static_cast<std::size_t>(k + offset)]; };
  std::vector<std::vector<int>> trace;
  int found = -1;
  for (int d = 0; d <= limit && found < 0; ++d) {
    for (int k = -d; k <= d; k += 2) {
      int x = (k == -d || (k != d && V(k - 1) < V(k + 1))) ? V(k + 1) : V(k - 1) + 1;
      int y = x - k;
      while (x < N && y < M && A(x) == B(y)) ++x, ++y;
      V(k) = x;
      if (x >= N && y >= M) found = d;
    }
    trace.emplace_back(v.begin() + (offset - d), v.begin() + (offset + d + 1));
  }
  if (found < 0) return {whole};  // too different to tell line by line

  // Back from (N, M): the matched lines, last first.
  std::vector<std::pair<int, int>> matches;
  int x = N, y = M;
  for (int d = found; d > 0; --d) {
    const std::vector<int>& prev = trace[static_cast<std::size_t>(d - 1)];
    const auto P = [&](int k) { return prev[static_cast<std::size_t>(k + d - 1)]; };
    const int k = x - y;
    const int prevK = (k == -d || (k != d && P(k - 1) < P(k + 1))) ? k + 1 : k - 1;
    const int prevX = P(prevK), prevY = prevX - prevK;
    const int startX = prevK == k + 1 ? prevX : prevX + 1;  // after the one edit
    while (x > startX) {
      --x, --y;
      matches.emplace_back(x, y);
    }
    x = prevX;
    y = prevY;
  }
  while (x > 0 && y > 0) {
    --x, --y;
    matches.emplace_back(x, y);
  }
  std::reverse(matches.begin(), matches.end());
  int ai = 0, bi = 0;
  for (const auto& [mx, my] : matches) {
    if (mx > ai || my > bi) hunks.push_back({pre + ai, mx - ai, pre + bi, my - bi});
    ai = mx + 1;
    bi = my + 1;
  }
  if (ai < N || bi < M) hunks.push_back({pre + ai, N - ai, pre + bi, M - bi});
  return hunks;
}

Recovery::Recovery(QString folder) : folder_(std::move(folder)) {
  if (folder_.isEmpty())
    folder_ = QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation))
                  .filePath(QStringLiteral("klueng/recovery"));
}

QString Recovery::newId() { return QUuid::createUuid().toString(QUuid::WithoutBraces); }

bool Recovery::write(const QString& id, const std::string& contents, const QString& originalPath,
                     const QString& displayName, QString* error, const RecoverySetup& setup) const {
  std::error_code made;
  std::filesystem::create_directories(std::filesystem::path(QFile::encodeName(folder_).toStdString()), made);
  if (made || !QFileInfo(folder_).isDir()) {
    if (error)
      *error = tr("cannot create the recovery folder %1: %2")
                   .arg(QDir::toNativeSeparators(folder_), reasonOf(made ? made.value() : ENOTDIR, folder_));
    return false;
  }
  // The lock first: a note is never without its (held) lock.
  if (const int err = holdLock(lockOf(folder_, id)); err != 0) {
    if (error) *error = tr("cannot lock %1: %2").arg(lockOf(folder_, id), reasonOf(err, folder_));
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
  note.remove(QStringLiteral("setup"));
  if (setup.present) {
    note.setValue(QStringLiteral("setup/dir"), setup.dir);
    note.setValue(QStringLiteral("setup/tools"), setup.tools);
    note.setValue(QStringLiteral("setup/offsets"), setup.offsets);
    note.setValue(QStringLiteral("setup/overrides"), setup.overrides);
  }
  note.sync();
  if (note.status() != QSettings::NoError) {
    if (error)
      *error = tr("cannot write %1: the folder cannot be written to, or the disk is full").arg(noteOf(folder_, id));
    return false;
  }
  return true;
}

void Recovery::remove(const QString& id) const {
  QFile::remove(copyOf(folder_, id));
  QFile::remove(noteOf(folder_, id));
  dropLock(lockOf(folder_, id));
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
    c.setup.present = note.contains(QStringLiteral("setup/tools"));
    c.setup.dir = note.value(QStringLiteral("setup/dir")).toString();
    c.setup.tools = note.value(QStringLiteral("setup/tools")).toByteArray();
    c.setup.offsets = note.value(QStringLiteral("setup/offsets")).toByteArray();
    c.setup.overrides = note.value(QStringLiteral("setup/overrides")).toStringList();
    const LockState lock = lockState(lockOf(folder_, c.id));
    if (lock == LockState::Held) continue;                              // a running Klueng's live copy
    if (lock == LockState::Missing && processRunning(c.pid)) continue;  // an older copy: its process id
    out.push_back(c);
  }
  std::sort(out.begin(), out.end(), [](const RecoveryCopy& a, const RecoveryCopy& b) { return a.written > b.written; });
  return out;
}

RecoveryDifference Recovery::difference(const RecoveryCopy& copy) {
  RecoveryDifference d;
  d.copyLines = linesOf(copy.copyPath).value_or(QStringList());
  const std::optional<QStringList> file = copy.originalPath.isEmpty() ? std::nullopt : linesOf(copy.originalPath);
  if (!file) {
    d.fileMissing = true;
    d.linesDiffering = static_cast<int>(d.copyLines.size());
    d.firstLine = d.copyLines.isEmpty() ? 0 : 1;
    return d;
  }
  d.fileLines = *file;
  d.hunks = diffLines(d.fileLines, d.copyLines);
  for (const RecoveryHunk& h : d.hunks) d.linesDiffering += std::max(h.fileCount, h.copyCount);
  if (!d.hunks.isEmpty()) d.firstLine = d.hunks.front().copyStart + 1;
  return d;
}

}  // namespace klueng::gui
