#include "gui/document_manager.h"
#include "gui/file_save.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QTextCursor>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/code_editor.h"
#include "gui/language.h"
#include "gui/settings.h"
#include "klueng/core/io/file_read.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

DocumentManager::DocumentManager(QWidget* window, CodeEditor* editor, Settings* settings)
    : QObject(window),
      window_(window),
      editor_(editor),
      settings_(settings),
      document_(new Document(this)),
      watcher_(new QFileSystemWatcher(this)),
      diskChangeTimer_(new QTimer(this)),
      autosaveTimer_(new QTimer(this)) {
  connect(watcher_, &QFileSystemWatcher::fileChanged, this, &DocumentManager::onFileChangedOnDisk);
  diskChangeTimer_->setSingleShot(true);
  diskChangeTimer_->setInterval(250);
  connect(&loadWatcher_, &QFutureWatcherBase::finished, this, &DocumentManager::onLoadFinished);
  connect(editor_->document(), &QTextDocument::modificationChanged, this, &DocumentManager::modificationChanged);
  connect(document_, &Document::headerChanged, this, &DocumentManager::modificationChanged);
  // Every real edit of the text or the header is a new revision for the autosave.
  connect(editor_->document(), &QTextDocument::contentsChange, this, [this](int, int removed, int added) {
    if ((removed || added) && !fillingEditor_) ++revision_;
  });
  connect(document_, &Document::headerChanged, this, [this] { ++revision_; });
  autosaveTimer_->setInterval(settings_->autosaveSeconds() * 1000);
  connect(autosaveTimer_, &QTimer::timeout, this, &DocumentManager::autosave);
  autosaveTimer_->start();
}

DocumentManager::~DocumentManager() {
  // Never wait on a load here: one that is still reading works on its own
  // copies and its result goes nowhere. Quitting is never held up by a file.
  discardRecovery();  // an orderly end (a crash never gets here): nothing to recover
}

void DocumentManager::autosave() {
  if (fillingEditor_ || restoring_) return;
  if (!isModified()) {
    discardRecovery();
    return;
  }
  if (hasRecoveryCopy_ && autosavedRevision_ == revision_) return;
  QString error;
  const RecoverySetup setup = isSetupModified() && setup_.recovery ? setup_.recovery() : RecoverySetup{};
  if (!recovery_.write(sessionId_, document_->formatted(editor_->toPlainText()), document_->filePath(),
                       document_->displayName(), &error, setup)) {
    emit autosaveFailed(error);
    return;
  }
  hasRecoveryCopy_ = true;
  autosavedRevision_ = revision_;
}

void DocumentManager::discardRecovery() {
  if (!hasRecoveryCopy_) return;
  recovery_.remove(sessionId_);
  hasRecoveryCopy_ = false;
}

void DocumentManager::restoreRecovery(const RecoveryCopy& copy) {
  if (!maybeSave()) return;
  restoring_ = copy;
  startLoad(copy.copyPath, copy.originalPath);
}

bool DocumentManager::isProgramModified() const {
  return editor_->document()->isModified() || document_->isHeaderModified();
}

bool DocumentManager::isModified() const { return isProgramModified() || isSetupModified(); }

void DocumentManager::setupChanged() {
  ++revision_;
  emit modificationChanged();
}

bool DocumentManager::maybeSave() {
  if (!isModified()) return true;
  QMessageBox box(window_);
  box.setObjectName(QStringLiteral("unsavedChangesBox"));
  box.setIcon(QMessageBox::Warning);
  box.setWindowTitle(tr("Unsaved changes"));
  // Say what is unsaved: the program, the tool and offset tables, or both.
  if (!isProgramModified())
    box.setText(tr("The tool or offset tables have been changed."));
  else if (isSetupModified())
    box.setText(
        tr("The program \"%1\" and the tool or offset tables have been changed.").arg(document_->displayName()));
  else
    box.setText(tr("The program \"%1\" has been changed.").arg(document_->displayName()));
  box.setInformativeText(tr("Do you want to save your changes?"));
  QPushButton* saveButton = box.addButton(tr("&Save"), QMessageBox::AcceptRole);
  QPushButton* discardButton = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
  QPushButton* cancelButton = box.addButton(tr("Cancel"), QMessageBox::RejectRole);
  saveButton->setObjectName(QStringLiteral("saveButton"));
  discardButton->setObjectName(QStringLiteral("discardButton"));
  cancelButton->setObjectName(QStringLiteral("cancelButton"));
  box.setDefaultButton(saveButton);
  box.setEscapeButton(cancelButton);
  box.exec();
  if (box.clickedButton() == saveButton) return save();
  return box.clickedButton() == discardButton;
}

void DocumentManager::newFile() {
  if (!maybeSave()) return;
  newFileUnchecked(Document::newProgramHeader(settings_->lastJobHeader()));
  emit cleared();
}

void DocumentManager::newFileUnchecked(const core::io::JobHeader& header) {
  emit aboutToReplace();
  discardRecovery();
  if (!document_->filePath().isEmpty()) watcher_->removePath(document_->filePath());
  ++fillGeneration_;  // drop the rest of a file still going into the editor
  pendingText_.clear();
  fillingEditor_ = false;
  loadInFlight_ = loadWatcher_.isRunning();
  editor_->setUndoRedoEnabled(true);
  editor_->setReadOnly(false);
  document_->reset(header);
  editor_->setFirstFileLine(document_->gcodeFirstLine());
  editor_->clearBreakpoints();
  editor_->setPlainText(QString());
  editor_->document()->setModified(false);
}

void DocumentManager::newFromProgram(const QString& fileText) {
  const auto file = core::io::parseProgramFile(fileText.toStdString());
  if (!file.value || !maybeSave()) return;
  newFileUnchecked(file.value->header);
  editor_->setPlainText(QString::fromStdString(file.value->gcode));
  editor_->document()->setModified(true);  // new and unsaved: Save asks for a name
  emit cleared();
}

void DocumentManager::open() {
  if (!maybeSave()) return;
  // The folder last used; the first time (or when it is gone) the samples, so a
  // new user finds something to open (issue 28 item 8).
  QString dir = settings_->lastDirectory();
  if (dir.isEmpty() || !QFileInfo(dir).isDir()) dir = QString::fromStdString(core::io::samplesDir());
  if (dir.isEmpty()) dir = QDir::homePath();
  const QString path = QFileDialog::getOpenFileName(window_, tr("Open program"), dir,
                                                    tr("Lathe programs (*.txt *.nc *.tap *.cnc *.gc);;All files (*)"));
  if (!path.isEmpty()) startLoad(path);
}

bool DocumentManager::openFile(const QString& path) {
  if (!maybeSave()) return false;
  startLoad(path);
  return true;
}

void DocumentManager::startLoad(const QString& path, const QString& detailsFor) {
  // A pipe, a device or a socket is refused before anything opens it: opening
  // a pipe waits for a writer for ever (issue 29 item 8). stat() never waits.
  if (auto refused = core::io::notAnOrdinaryFile(QFile::encodeName(path).toStdString())) {
    LoadedProgram failed;
    failed.path = QFileInfo(path).absoluteFilePath();
    failed.diagnostics.push_back(std::move(*refused));
    loadInFlight_ = false;
    showLoadFailure(failed);
    return;
  }
  // A load still running is left to finish on its own: its result is dropped
  // when the watcher follows the new one. The window never waits on a file.
  loadInFlight_ = true;
  // A plain file's stock: its own Job details, else inferred; never the last file's.
  const core::io::JobHeader defaults = settings_->lastJobHeader();
  const std::optional<core::io::JobHeader> details =
      detailsFor.isEmpty() && restoring_ ? std::nullopt
                                         : settings_->jobDetailsFor(detailsFor.isEmpty() ? path : detailsFor);
  loadWatcher_.setFuture(
      QtConcurrent::run([path, defaults, details] { return Document::load(path, defaults, details); }));
  emit busyChanged();
}

void DocumentManager::showLoadFailure(const LoadedProgram& loaded) {
  restoring_.reset();
  emit busyChanged();
  QStringList lines;
  for (const auto& d : loaded.diagnostics)
    lines << QString::fromStdString(
        core::formatWithPlace(QFileInfo(loaded.path).fileName().toStdString(), d, Language::coreLang()));
  QMessageBox::warning(window_, tr("Cannot open the program"),
                       tr("\"%1\" could not be read.").arg(QDir::toNativeSeparators(loaded.path)) +
                           (lines.isEmpty() ? QString() : QStringLiteral("\n\n") + lines.join(QLatin1Char('\n'))));
  settings_->removeRecentFile(loaded.path);
  emit loadFailed(loaded.path);
}

void DocumentManager::onLoadFinished() {
  LoadedProgram loaded = loadWatcher_.result();
  loadInFlight_ = false;
  if (!loaded.ok) {
    showLoadFailure(loaded);
    return;
  }
  // A recovery copy becomes the program it belongs to (untitled when it had no file).
  if (restoring_) loaded.path = restoring_->originalPath;
  emit aboutToReplace();
  discardRecovery();
  if (!document_->filePath().isEmpty()) watcher_->removePath(document_->filePath());
  document_->adopt(loaded);
  editor_->setFirstFileLine(document_->gcodeFirstLine());
  editor_->clearBreakpoints();
  editor_->setExecutingLine(0);
  editor_->setDiagnostics({});
  // The text goes into the editor a few thousand lines per event-loop pass, so
  // colouring a 100,000-line program never freezes the window.
  loadInFlight_ = true;
  fillingEditor_ = true;
  editor_->setReadOnly(true);
  editor_->setUndoRedoEnabled(false);
  editor_->clear();
  pendingText_ = loaded.gcode;
  pendingOffset_ = 0;
  ++fillGeneration_;
  appendNextChunk();
}

void DocumentManager::appendNextChunk() {
  constexpr int kChunkLines = 1500;
  const qsizetype size = pendingText_.size();
  qsizetype end = pendingOffset_;
  for (int n = 0; n < kChunkLines && end < size; ++n) {
    const qsizetype nl = pendingText_.indexOf(QLatin1Char('\n'), end);
    end = nl < 0 ? size : nl + 1;
  }
  QTextCursor c(editor_->document());
  c.movePosition(QTextCursor::End);
  c.insertText(pendingText_.mid(pendingOffset_, end - pendingOffset_));
  pendingOffset_ = end;
  const quint64 generation = fillGeneration_;
  QTimer::singleShot(0, this, [this, generation, done = pendingOffset_ >= size] {
    if (generation != fillGeneration_) return;  // a newer file took over
    if (done)
      finishLoad();
    else
      appendNextChunk();
  });
}

void DocumentManager::finishLoad() {
  const QString loadedText = std::exchange(pendingText_, QString());
  fillingEditor_ = false;
  loadInFlight_ = false;
  editor_->setUndoRedoEnabled(true);
  editor_->setReadOnly(false);
  editor_->moveCursor(QTextCursor::Start);
  std::optional<RecoverySetup> restoredSetup;
  if (restoring_) {
    // Unsaved work again, as it was: modified until the user saves it.
    recovery_.remove(restoring_->id);
    if (restoring_->setup.present) restoredSetup = restoring_->setup;
    restoring_.reset();
    editor_->document()->setModified(true);
    ++revision_;
    if (!document_->filePath().isEmpty()) watchFile(document_->filePath());
    autosave();  // this window's own copy from now on
  } else {
    editor_->document()->setModified(false);
    rememberFile();
  }
  emit loaded(document_->filePath(), loadedText);
  // The unsaved setup edits the copy kept are in memory again, unsaved.
  if (restoredSetup && setup_.restore) {
    setup_.restore(*restoredSetup);
    setupChanged();
    autosave();
  }
}

void DocumentManager::rememberFile() {
  const QString path = document_->filePath();
  settings_->addRecentFile(path);
  settings_->setLastDirectory(QFileInfo(path).absolutePath());
  // Opening a file never makes its job header the next program's (issue 28 item 3):
  // only what the user types in Job details is remembered.
  watchFile(path);
}

bool DocumentManager::save() {
  // Only the setup changed in an untitled program: its files are written, no name is asked
  // (unless stations set for this program need the program's file to belong to).
  if (document_->isUntitled() && !isProgramModified() && isSetupModified()) {
    if (!setup_.save(QString())) return false;
    emit modificationChanged();
    if (!isSetupModified()) return true;
  }
  if (document_->isUntitled()) return saveAs();
  return saveFile(document_->filePath());
}

bool DocumentManager::saveAs() {
  QString suggestion = document_->filePath();
  if (suggestion.isEmpty()) {
    const QString dir = settings_->lastDirectory().isEmpty() ? QDir::homePath() : settings_->lastDirectory();
    suggestion = QDir(dir).filePath(document_->displayName());
  }
  const QString path = QFileDialog::getSaveFileName(window_, tr("Save program as"), suggestion,
                                                    tr("Lathe programs (*.txt *.nc);;All files (*)"));
  if (path.isEmpty()) return false;
  return saveFile(path);
}

bool DocumentManager::saveFile(const QString& path) {
  // A line too long to edit was left out of the editor: writing over the file would delete it.
  if (const int omitted = document_->firstOmittedLine();
      omitted > 0 && QFileInfo(path).absoluteFilePath() == QFileInfo(document_->filePath()).absoluteFilePath()) {
    QMessageBox::warning(window_, tr("Cannot save over this file"),
                         tr("Line %1 of \"%2\" is too long to edit, so it is not in the editor. Saving over the file "
                            "would delete it: use Save As to write your version to another file.")
                             .arg(omitted)
                             .arg(document_->displayName()));
    return false;
  }
  // A file the run reads (tools.cfg, a tool picture, a subprogram file...) is never replaced by
  // the program: refused as the CLI refuses it, F126 (issue 42 item 2).
  if (setup_.inputs)
    if (const QString why = outputIsAnyInput(path, setup_.inputs()); !why.isEmpty()) {
      QMessageBox box(window_);
      box.setObjectName(QStringLiteral("outputIsInputBox"));
      box.setIcon(QMessageBox::Warning);
      box.setWindowTitle(tr("Cannot save the program"));
      box.setText(why);
      box.exec();
      return false;
    }
  // A read-only file is the owner's "keep this": never written over (not even by root),
  // never made writable behind the user's back; offer another name instead, as editors do.
  if (core::io::isReadOnlyFile(path.toStdString())) {
    QMessageBox box(window_);
    box.setObjectName(QStringLiteral("readOnlyBox"));
    box.setIcon(QMessageBox::Warning);
    box.setWindowTitle(tr("Read-only file"));
    box.setText(tr("\"%1\" is read-only, so Klueng will not write over it.").arg(QDir::toNativeSeparators(path)));
    box.setInformativeText(tr("Save your program under another name?"));
    QPushButton* saveAsButton = box.addButton(tr("Save &As..."), QMessageBox::AcceptRole);
    saveAsButton->setObjectName(QStringLiteral("saveAsButton"));
    box.addButton(tr("Cancel"), QMessageBox::RejectRole)->setObjectName(QStringLiteral("cancelButton"));
    box.setDefaultButton(saveAsButton);
    box.exec();
    return box.clickedButton() == saveAsButton && saveAs();
  }
  // A file still going into the editor is saved whole: put the rest in first.
  if (fillingEditor_) {
    QTextCursor c(editor_->document());
    c.movePosition(QTextCursor::End);
    c.insertText(pendingText_.mid(pendingOffset_));
    pendingOffset_ = pendingText_.size();
    ++fillGeneration_;  // the queued chunks and finishLoad() of this fill are void now
    finishLoad();
  }
  // The setup first: it may ask (a read-only setup folder), and a No saves nothing.
  if (isSetupModified() && !setup_.save(QFileInfo(path).absoluteFilePath())) return false;
  QString error;
  const QString old = document_->filePath();
  if (!old.isEmpty()) watcher_->removePath(old);
  if (!document_->save(path, editor_->toPlainText(), &error)) {
    if (!old.isEmpty()) watcher_->addPath(old);
    QMessageBox::critical(window_, tr("Cannot save the program"),
                          tr("\"%1\" could not be written:\n%2").arg(QDir::toNativeSeparators(path), error));
    return false;
  }
  editor_->document()->setModified(false);
  rememberFile();
  discardRecovery();
  emit modificationChanged();
  emit saved(document_->filePath());
  return true;
}

void DocumentManager::watchFile(const QString& path) {
  // An atomic save replaces the file; watch the new one.
  if (!watcher_->files().contains(path)) watcher_->addPath(path);
}

void DocumentManager::onFileChangedOnDisk(const QString& path) {
  if (path != document_->filePath()) return;
  // Editors often write in several steps: wait until the file settles.
  diskChangeTimer_->disconnect();
  connect(diskChangeTimer_, &QTimer::timeout, this, [this, path] {
    if (path != document_->filePath()) return;
    if (!QFileInfo::exists(path)) return;  // deleted or mid-rename; a later change re-triggers
    watchFile(path);
    QMessageBox box(window_);
    box.setObjectName(QStringLiteral("fileChangedBox"));
    box.setIcon(QMessageBox::Question);
    box.setWindowTitle(tr("File changed on disk"));
    box.setText(tr("\"%1\" was changed by another program.").arg(document_->displayName()));
    box.setInformativeText(isModified() ? tr("Reload it and lose your changes here?") : tr("Reload it?"));
    QPushButton* reload = box.addButton(tr("&Reload"), QMessageBox::AcceptRole);
    QPushButton* keep = box.addButton(tr("&Keep mine"), QMessageBox::RejectRole);
    reload->setObjectName(QStringLiteral("reloadButton"));
    keep->setObjectName(QStringLiteral("keepButton"));
    box.exec();
    if (box.clickedButton() == reload) startLoad(path);
  });
  diskChangeTimer_->start();
}

void DocumentManager::fillRecentMenu(QMenu* menu) {
  menu->clear();
  const QStringList files = settings_->recentFiles();
  for (int i = 0; i < files.size(); ++i) {
    QAction* a = menu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(
        QFileInfo(files[i]).fileName().replace(QLatin1Char('&'), QStringLiteral("&&"))));
    a->setToolTip(QDir::toNativeSeparators(files[i]));
    a->setStatusTip(QDir::toNativeSeparators(files[i]));
    const QString path = files[i];
    connect(a, &QAction::triggered, this, [this, path] { openFile(path); });
  }
  if (files.isEmpty()) menu->addAction(tr("(none)"))->setEnabled(false);
}

}  // namespace klueng::gui
