#pragma once
// Autosave and recovery (issue 13): a window's unsaved program is written
// every 30 s and when Klueng loses the focus to a recovery folder (the
// per-user data folder's "recovery"), as exactly what Save would write, with
// a note of where it belongs. Saving, discarding or opening another file
// removes the copy; a copy whose Klueng is no longer running (a crash, a kill,
// a power cut) is offered at the next start (RecoveryBar).
#include <QDateTime>
#include <QString>
#include <QVector>
#include <string>

namespace klueng::gui {

struct RecoveryCopy {
  QString id;            // the window session that wrote it
  QString copyPath;      // the recovered program (as Save would write it)
  QString originalPath;  // where it belongs; empty for an untitled program
  QString displayName;   // "01-step-shaft.txt", "untitled.txt"
  QDateTime written;
  qint64 pid = 0;        // the Klueng process that wrote it
};

// What differs between a copy and the file on disk, for the offer.
struct RecoveryDifference {
  int linesDiffering = 0;   // lines of the copy that the file does not have at the same place
  int firstLine = 0;        // file line of the first difference (0 = none)
  bool fileMissing = false; // the original is gone (or the program was untitled)
};

class Recovery {
 public:
  // `folder` empty: the per-user data folder's "recovery".
  explicit Recovery(QString folder = {});

  QString folder() const { return folder_; }
  // A new session id for one window.
  static QString newId();

  // Writes (atomically) the copy of window `id`; false with `error` on failure.
  bool write(const QString& id, const std::string& contents, const QString& originalPath,
             const QString& displayName, QString* error = nullptr) const;
  void remove(const QString& id) const;
  // Copies whose Klueng is not running any more, newest first.
  QVector<RecoveryCopy> orphans() const;
  static RecoveryDifference difference(const RecoveryCopy& copy);

 private:
  QString folder_;
};

}  // namespace klueng::gui
