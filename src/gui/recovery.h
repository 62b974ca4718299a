#pragma once
// Autosave and recovery (issue 13): a window's unsaved program is written
// every 30 s and when Klueng loses the focus to a recovery folder (the
// per-user data folder's "recovery"), as exactly what Save would write, with
// a note of where it belongs. Saving, discarding or opening another file
// removes the copy; a copy whose Klueng is no longer running (a crash, a kill,
// a power cut) is offered at the next start (RecoveryBar).
//
// "Still running" is a lock, not a process id: the window holds an flock() on
// <id>.lock from its first autosave until the copy is removed. The kernel drops
// it when the process ends (a zombie holds none) and no lock outlives a reboot,
// so neither a dead editor's zombie nor a process id reused after a reboot
// hides a copy. Copies written before the lock (no .lock file) fall back to the
// process id, a zombie counting as gone.
#include <QByteArray>
#include <QDateTime>
#include <QString>
#include <QStringList>
#include <QVector>
#include <string>

namespace klueng::gui {

// The unsaved setup edits of the window (issue 30 item 2): tools.cfg and offset.cfg as
// held in memory and the stations set for the program, so a crash loses none of them.
struct RecoverySetup {
  bool present = false;
  QString dir;                // the setup folder they belong to
  QByteArray tools, offsets;  // the files' text as Save would write it
  QStringList overrides;      // "3=cnmg-80-r04"
};

struct RecoveryCopy {
  QString id;            // the window session that wrote it
  QString copyPath;      // the recovered program (as Save would write it)
  QString originalPath;  // where it belongs; empty for an untitled program
  QString displayName;   // "01-step-shaft.txt", "untitled.txt"
  QDateTime written;
  qint64 pid = 0;  // the Klueng process that wrote it
  RecoverySetup setup;
};

// One run of lines that differ between the file on disk and the copy (a line
// diff): `fileCount` lines of the file from `fileStart` are `copyCount` lines of
// the copy from `copyStart` (0-based; a count of 0 is a pure insertion/deletion).
struct RecoveryHunk {
  int fileStart = 0, fileCount = 0;
  int copyStart = 0, copyCount = 0;
};

// What differs between a copy and the file on disk, for the offer.
struct RecoveryDifference {
  // Lines that differ: per hunk the larger of the lines removed and the lines
  // added, so one inserted, deleted or changed line is 1.
  int linesDiffering = 0;
  int firstLine = 0;         // line (1-based, header included) of the first difference (0 = none)
  bool fileMissing = false;  // the original is gone (or the program was untitled)
  QVector<RecoveryHunk> hunks;
  QStringList fileLines, copyLines;  // the texts compared, one entry per line
};

// The shortest edit (Myers' O(ND) line diff) that turns `from` into `to`. Past
// `maxEdits` changed lines the middle that differs is one hunk.
QVector<RecoveryHunk> diffLines(const QStringList& from, const QStringList& to, int maxEdits = 2000);

class Recovery {
 public:
  // `folder` empty: the per-user data folder's "recovery".
  explicit Recovery(QString folder = {});

  QString folder() const { return folder_; }
  // A new session id for one window.
  static QString newId();

  // Writes (atomically) the copy of window `id`, holding its lock from the first
  // write on; false with `error` (what failed and why, in the UI language) on failure.
  bool write(const QString& id, const std::string& contents, const QString& originalPath, const QString& displayName,
             QString* error = nullptr, const RecoverySetup& setup = {}) const;
  // Removes the copy, its note and its lock (this window's or a dead one's).
  void remove(const QString& id) const;
  // Copies whose Klueng is not running any more, newest first.
  QVector<RecoveryCopy> orphans() const;
  static RecoveryDifference difference(const RecoveryCopy& copy);

 private:
  QString folder_;
};

}  // namespace klueng::gui
