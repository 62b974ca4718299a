#pragma once
// The edits of a document as undo commands (issue 30 item 2, as Tiled does it):
// the command IS the edit. Each changes what the document holds in memory —
// its first redo() applies it, undo() puts back what was there — and nothing
// is written to disk until File ▸ Save. One stack per document
// (JobDocument::undoStack()); the window's QUndoGroup gives Edit ▸ Undo / Redo.
//
//   JobDetailsCommand  the document's header (and where a plain file's stock came from)
//   SetupCommand       tools.cfg / offset.cfg as held in memory, and the program's
//                      own station choices (Tool Select, Offset Define, touch-off)
//   TextEditCommand    one undo step of the editor's QTextDocument, so that text
//                      and setup edits share one history in the order they were made
#include <QPointer>
#include <QString>
#include <QPlainTextEdit>
#include <QUndoCommand>
#include <functional>

#include "gui/document.h"
#include "gui/job_document.h"

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
};

class SetupCommand : public QUndoCommand {
 public:
  using Apply = std::function<void(const SetupEdit&)>;
  SetupCommand(const QString& text, SetupEdit before, SetupEdit after, Apply apply);
  void undo() override;
  void redo() override;

 private:
  SetupEdit before_, after_;
  Apply apply_;
};

// Pushed when the QTextDocument adds an undo step (QTextDocument::undoCommandAdded):
// the edit is already in the text, so the first redo does nothing.
class TextEditCommand : public QUndoCommand {
 public:
  explicit TextEditCommand(QPlainTextEdit* editor);
  void undo() override;
  void redo() override;

 private:
  QPointer<QPlainTextEdit> editor_;  // its undo() shows where the text changed
  bool done_ = true;
};

}  // namespace klueng::gui
