#pragma once
// Undo for what is not the program's text (issue 12): Job details and the tool
// and offset tables. One QUndoStack per document (the window clears it with
// each new or opened file); the editor keeps its own text undo.
//
//   JobDetailsCommand  the document's header (and where a plain file's stock came from)
//   SetupFilesCommand  tools.cfg / offset.cfg as the dialogs wrote them, and the
//                      program's own station choices (Tool Select)
// A command is pushed after its change is made: its first redo does nothing.
#include <QByteArray>
#include <QString>
#include <QUndoCommand>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "gui/document.h"
#include "klueng/core/infer/tool_inference.h"

namespace klueng::gui {

class JobDetailsCommand : public QUndoCommand {
 public:
  using Apply = std::function<void(const Document::HeaderState&)>;
  JobDetailsCommand(Document::HeaderState before, Document::HeaderState after, Apply apply);
  void undo() override;
  void redo() override;

 private:
  Document::HeaderState before_, after_;
  Apply apply_;
  bool done_ = true;  // the dialog already applied it
};

// The files of a setup folder the dialogs write, and the program's station choices.
struct SetupSnapshot {
  std::map<QString, std::optional<QByteArray>> files;  // name -> contents (nullopt: no such file)
  std::vector<core::machine::StationOverride> overrides;
  bool operator==(const SetupSnapshot& o) const;
  // tools.cfg and offset.cfg of `dir`.
  static SetupSnapshot read(const QString& dir, std::vector<core::machine::StationOverride> overrides);
};

class SetupFilesCommand : public QUndoCommand {
 public:
  // Reloads the setup from `dir` with these station choices; `error` is empty when the files were written.
  using Reload = std::function<void(const QString& dir, const std::vector<core::machine::StationOverride>& overrides,
                                    const QString& error)>;
  SetupFilesCommand(const QString& text, QString dir, SetupSnapshot before, SetupSnapshot after, Reload reload);
  void undo() override;
  void redo() override;

 private:
  void restore(const SetupSnapshot& snapshot);

  QString dir_;
  SetupSnapshot before_, after_;
  Reload reload_;
  bool done_ = true;
};

}  // namespace klueng::gui
