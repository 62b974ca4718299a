#pragma once
// The open file's life in the window (issue 12, the way Tiled's DocumentManager
// does it): new, open (read off the GUI thread, then fed to the editor a few
// thousand lines per event-loop pass), save / save as (atomic), the unsaved-
// changes prompt, watching the file on disk and the recent-files menu. It owns
// no machining (a plain file's stock comes from the window's first check) and
// the window hears `replaced`, `loaded` and `saved`.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <functional>
#include <optional>

#include "gui/document.h"
#include "gui/recovery.h"

class QFileSystemWatcher;
class QMenu;
class QTimer;
class QWidget;

namespace klueng::gui {

class CodeEditor;
class Settings;

class DocumentManager : public QObject {
  Q_OBJECT
 public:
  DocumentManager(QWidget* window, CodeEditor* editor, Settings* settings);
  ~DocumentManager() override;

  // The setup the window holds for the document (issue 30 item 2): it is part of what is
  // unsaved, saved, autosaved and recovered.
  struct SetupHooks {
    std::function<bool()> modified;
    // Writes what is edited (tools.cfg, offset.cfg; the stations set for `programPath`
    // when it is not empty); false when the user cancelled or a write failed.
    std::function<bool(const QString& programPath)> save;
    std::function<RecoverySetup()> recovery;  // what an autosave keeps of it
    std::function<void(const RecoverySetup&)> restore;
    // Every file the run reads besides the program (setup, pictures, library, subprograms):
    // Save As onto one of them is refused, F126 (issue 42 item 2).
    std::function<std::vector<std::string>()> inputs;
  };
  void setSetupHooks(SetupHooks hooks) { setup_ = std::move(hooks); }
  // A setup edit or its undo: a new revision for the autosave, the title's '*'.
  void setupChanged();

  Document* document() const { return document_; }
  // The program (text or header) or the setup has unsaved changes.
  bool isModified() const;
  bool isProgramModified() const;
  bool isSetupModified() const { return setup_.modified && setup_.modified(); }
  // True while a file is read or still going into the editor.
  bool isLoading() const { return loadInFlight_; }
  // True while the editor is being filled: its changes are not the user's.
  bool isFillingEditor() const { return fillingEditor_; }

  // Save / Discard / Cancel when there are unsaved changes; true = go on.
  bool maybeSave();
  void newFile();
  // A new, unsaved program holding `fileText` (a Klueng file: its header
  // becomes the job details), e.g. the part designer's generated program.
  void newFromProgram(const QString& fileText);
  void open();
  bool openFile(const QString& path);  // false when the user cancelled
  bool save();
  bool saveAs();
  bool saveFile(const QString& path);  // atomic; false (with a message box) on failure
  // Fills File > Recent Files.
  void fillRecentMenu(QMenu* menu);

  // Autosave (recovery.h): writes the unsaved program to the recovery folder
  // now if it changed since the last copy; removes the copy when nothing is unsaved.
  void autosave();
  // The window closes or drops its changes: no copy is left behind.
  void discardRecovery();
  const Recovery& recovery() const { return recovery_; }
  QString sessionId() const { return sessionId_; }
  // Opens a copy a crash left behind as the program it belongs to (modified,
  // not saved); the copy is removed once it is in the editor.
  void restoreRecovery(const RecoveryCopy& copy);

 signals:
  // The editor is about to get another program (stop the run, clear alarms).
  void aboutToReplace();
  // A new untitled program is in the editor.
  void cleared();
  // A file is wholly in the editor; `text` is its G-code (no need to read it back).
  void loaded(const QString& path, const QString& text);
  void loadFailed(const QString& path);
  void saved(const QString& path);
  void autosaveFailed(const QString& error);
  void modificationChanged();
  void busyChanged();

 private:
  // New's work once the old program may go: an empty program with `header`.
  void newFileUnchecked(const core::io::JobHeader& header);
  void startLoad(const QString& path, const QString& detailsFor = {});
  void onLoadFinished();
  void showLoadFailure(const LoadedProgram& loaded);
  void appendNextChunk();
  void finishLoad();
  void watchFile(const QString& path);
  void onFileChangedOnDisk(const QString& path);
  void rememberFile();

  QWidget* window_;
  CodeEditor* editor_;
  Settings* settings_;
  Document* document_;
  QFileSystemWatcher* watcher_;
  QTimer* diskChangeTimer_;
  QFutureWatcher<LoadedProgram> loadWatcher_;
  QString pendingText_;  // G-code still to go into the editor
  qsizetype pendingOffset_ = 0;
  bool fillingEditor_ = false;
  bool loadInFlight_ = false;
  quint64 fillGeneration_ = 0;
  Recovery recovery_;
  QString sessionId_ = Recovery::newId();
  QTimer* autosaveTimer_;
  quint64 revision_ = 0;           // counts edits of the text and the header
  quint64 autosavedRevision_ = 0;  // the revision the recovery copy holds
  bool hasRecoveryCopy_ = false;
  std::optional<RecoveryCopy> restoring_;  // a recovery copy being loaded
  SetupHooks setup_;
};

}  // namespace klueng::gui
