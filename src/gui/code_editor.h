#pragma once
// The G-code editor: a QPlainTextEdit with a gutter (breakpoint margin + file
// line numbers), syntax colours, diagnostics underlined, the current line and
// the executing block highlighted, and tooltips that explain the G/M word
// under the mouse from the core's code table.
//
// Line numbers: the editor shows only the G-code part of the file; its first
// line is file line firstFileLine() (7 after the 6-line header, 1 for a plain
// G-code file). Every public line number here is a FILE line, as the core's
// diagnostics and timeline use.
#include <QList>
#include <QPlainTextEdit>
#include <QPointer>
#include <functional>
#include <optional>
#include <utility>

#include "klueng/core/diagnostic.h"
#include "klueng/core/gcode/code_table.h"

namespace klueng::gui {

class GcodeHighlighter;
class LineNumberArea;

class CodeEditor : public QPlainTextEdit {
  Q_OBJECT
 public:
  explicit CodeEditor(QWidget* parent = nullptr);

  void setFirstFileLine(int line);
  int firstFileLine() const { return firstFileLine_; }
  int editorLineFromFileLine(int fileLine) const { return fileLine - firstFileLine_; }  // 0-based block
  int fileLineFromBlock(int blockNumber) const { return blockNumber + firstFileLine_; }

  void setDialect(core::gcode::Dialect d) { dialect_ = d; }
  core::gcode::Dialect dialect() const { return dialect_; }
  // What the block on a file line does, added to the hover help (issue 11: Explain).
  void setLineExplainer(std::function<QString(int fileLine)> explain) { explainLine_ = std::move(explain); }
  // The value an expression word (X#101) had the last time its line ran: set by
  // the main window from the run (file line, 1-based column -> text, or empty).
  void setWordValueLookup(std::function<QString(int fileLine, int column)> lookup) { wordValue_ = std::move(lookup); }

  // Underline every diagnostic that falls on a G-code line (others are ignored here).
  void setDiagnostics(const std::vector<core::Diagnostic>& diags);
  GcodeHighlighter* highlighter() const { return highlighter_; }

  // Breakpoints move with their lines as the text is edited.
  QList<int> breakpointFileLines() const;
  bool hasBreakpoint(int fileLine) const;
  void toggleBreakpoint(int fileLine);
  void clearBreakpoints();

  int executingFileLine() const { return executingLine_; }
  int cursorFileLine() const { return fileLineFromBlock(textCursor().blockNumber()); }

  // Move the cursor to a file line and 1-based code-point column (0 = line start).
  void goToFileLine(int fileLine, int column = 0);

  // Help text for the word at a position in the document (empty when none).
  QString helpForPosition(int position) const;
  // The G or M code under (or just before) the text cursor: ('G', 71) on "G71".
  std::optional<std::pair<char, int>> codeAtCursor() const;

  // The window's Edit > Undo / Redo (issue 30 item 2): Ctrl+Z / Ctrl+Y and the context
  // menu's Undo / Redo trigger them, so the text's undo steps go through the document's
  // one stack, in order with the setup's; the editor never undoes on its own.
  void setUndoActions(QAction* undo, QAction* redo);
  // The next edit starts an undo step of its own (set when the document's stack moved
  // by another step): the text document would join typing that goes on where it stopped
  // to its last step, which may lie under a setup edit, or whose redo was given up.
  void setNewUndoStep(bool on) { newUndoStep_ = on; }

  // Gutter helpers used by LineNumberArea.
  int gutterWidth() const;
  int breakpointMarginWidth() const;
  void paintGutter(QPaintEvent* event);
  void gutterClicked(QPoint pos);

 public slots:
  // Highlight the block being executed (file line); 0 or negative clears.
  void setExecutingLine(int fileLine);

 signals:
  void breakpointsChanged();

 protected:
  void resizeEvent(QResizeEvent* event) override;
  bool viewportEvent(QEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void changeEvent(QEvent* event) override;
  bool event(QEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void contextMenuEvent(QContextMenuEvent* event) override;
  void insertFromMimeData(const QMimeData* source) override;

 private:
  void updateGutterWidth();
  void updateGutter(const QRect& rect, int dy);
  void updateExtraSelections();

  GcodeHighlighter* highlighter_ = nullptr;
  LineNumberArea* gutter_ = nullptr;
  int firstFileLine_ = 1;
  int executingLine_ = 0;
  int breakpointCount_ = 0;
  core::gcode::Dialect dialect_ = core::gcode::Dialect::Fanuc;
  std::function<QString(int, int)> wordValue_;
  std::function<QString(int)> explainLine_;
  QPointer<QAction> undoAction_, redoAction_;
  bool newUndoStep_ = false;
};

}  // namespace klueng::gui
