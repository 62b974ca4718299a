#include "gui/code_editor.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QMimeData>
#include <QTextCursor>
#include <QMenu>
#include <memory>

#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/display_tokens.h"

#include <QFontDatabase>
#include <QHelpEvent>
#include <QPainter>
#include <QScrollBar>
#include <QTextBlock>
#include <QToolTip>

#include "gui/gcode_highlighter.h"
#include "gui/language.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

class LineNumberArea : public QWidget {
 public:
  explicit LineNumberArea(CodeEditor* editor) : QWidget(editor), editor_(editor) { setCursor(Qt::PointingHandCursor); }
  QSize sizeHint() const override { return {editor_->gutterWidth(), 0}; }

 protected:
  void paintEvent(QPaintEvent* e) override { editor_->paintGutter(e); }
  void mousePressEvent(QMouseEvent* e) override { editor_->gutterClicked(e->position().toPoint()); }

 private:
  CodeEditor* editor_;
};

namespace {

// Marks a block that carries a breakpoint; the data travels with the line.
class BreakpointData : public QTextBlockUserData {};

bool blockHasBreakpoint(const QTextBlock& b) { return dynamic_cast<BreakpointData*>(b.userData()) != nullptr; }

// Column conversion: the core counts code points, QString counts UTF-16 units.
int utf16Index(const QString& text, int codePointColumn1) {
  int cp = 1;
  int i = 0;
  while (i < text.size() && cp < codePointColumn1) {
    i += text[i].isHighSurrogate() && i + 1 < text.size() ? 2 : 1;
    ++cp;
  }
  return i;
}

}  // namespace

CodeEditor::CodeEditor(QWidget* parent) : QPlainTextEdit(parent) {
  QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  mono.setPointSize(11);
  setFont(mono);
  setLineWrapMode(QPlainTextEdit::NoWrap);
  setTabStopDistance(fontMetrics().horizontalAdvance(QLatin1Char(' ')) * 4);
  highlighter_ = new GcodeHighlighter(document());
  gutter_ = new LineNumberArea(this);
  connect(this, &QPlainTextEdit::blockCountChanged, this, &CodeEditor::updateGutterWidth);
  connect(this, &QPlainTextEdit::updateRequest, this, &CodeEditor::updateGutter);
  connect(this, &QPlainTextEdit::cursorPositionChanged, this, &CodeEditor::updateExtraSelections);
  updateGutterWidth();
  updateExtraSelections();
}

void CodeEditor::setFirstFileLine(int line) {
  firstFileLine_ = std::max(1, line);
  updateGutterWidth();
  gutter_->update();
}

int CodeEditor::breakpointMarginWidth() const { return fontMetrics().height() + 4; }

int CodeEditor::gutterWidth() const {
  int digits = 1;
  for (int max = std::max(1, blockCount() + firstFileLine_ - 1); max >= 10; max /= 10) ++digits;
  digits = std::max(digits, 3);
  return breakpointMarginWidth() + 6 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * digits;
}

void CodeEditor::updateGutterWidth() { setViewportMargins(gutterWidth(), 0, 0, 0); }

void CodeEditor::updateGutter(const QRect& rect, int dy) {
  if (dy)
    gutter_->scroll(0, dy);
  else
    gutter_->update(0, rect.y(), gutter_->width(), rect.height());
  if (rect.contains(viewport()->rect())) updateGutterWidth();
}

void CodeEditor::paintEvent(QPaintEvent* e) {
  // A long program is coloured where it is drawn (gcode_highlighter.h): the lines
  // about to be painted get their colours first.
  const qreal bottom = viewport()->rect().bottom();
  const QPointF offset = contentOffset();
  for (QTextBlock b = firstVisibleBlock(); b.isValid(); b = b.next()) {
    if (blockBoundingGeometry(b).translated(offset).top() > bottom) break;
    highlighter_->colourBlock(b);
  }
  QPlainTextEdit::paintEvent(e);
}

void CodeEditor::resizeEvent(QResizeEvent* e) {
  QPlainTextEdit::resizeEvent(e);
  const QRect cr = contentsRect();
  gutter_->setGeometry(QRect(cr.left(), cr.top(), gutterWidth(), cr.height()));
}

void CodeEditor::paintGutter(QPaintEvent* event) {
  QPainter p(gutter_);
  p.fillRect(event->rect(), palette().color(QPalette::Window));
  const int margin = breakpointMarginWidth();
  p.fillRect(QRect(0, event->rect().top(), margin, event->rect().height()), palette().color(QPalette::AlternateBase));
  p.setRenderHint(QPainter::Antialiasing);
  QTextBlock block = firstVisibleBlock();
  int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
  int bottom = top + qRound(blockBoundingRect(block).height());
  const int lineH = fontMetrics().height();
  const QColor numberColour = palette().color(QPalette::PlaceholderText);
  while (block.isValid() && top <= event->rect().bottom()) {
    if (block.isVisible() && bottom >= event->rect().top()) {
      const int fileLine = fileLineFromBlock(block.blockNumber());
      if (blockHasBreakpoint(block)) {
        const int d = lineH - 6;
        p.setPen(QColor(0x90, 0x10, 0x10));
        p.setBrush(QColor(0xd8, 0x24, 0x24));
        p.drawEllipse(QRect((margin - d) / 2, top + 3, d, d));
      }
      if (fileLine == executingLine_) {
        // A green arrow points at the block being executed.
        const int h = lineH - 6;
        QPolygon arrow;
        arrow << QPoint(3, top + 3) << QPoint(margin - 3, top + 3 + h / 2) << QPoint(3, top + 3 + h);
        p.setPen(QColor(0x10, 0x70, 0x20));
        p.setBrush(QColor(0x2e, 0xa0, 0x40));
        p.drawPolygon(arrow);
      }
      p.setPen(block == textCursor().block() ? palette().color(QPalette::Text) : numberColour);
      p.drawText(margin, top, gutter_->width() - margin - 4, lineH, Qt::AlignRight | Qt::AlignVCenter,
                 QString::number(fileLine));
    }
    block = block.next();
    top = bottom;
    bottom = top + qRound(blockBoundingRect(block).height());
  }
}

void CodeEditor::gutterClicked(QPoint pos) {
  const QTextCursor c = cursorForPosition(QPoint(0, pos.y()));
  toggleBreakpoint(fileLineFromBlock(c.blockNumber()));
}

QList<int> CodeEditor::breakpointFileLines() const {
  QList<int> lines;
  if (breakpointCount_ == 0) return lines;
  for (QTextBlock b = document()->begin(); b.isValid(); b = b.next())
    if (blockHasBreakpoint(b)) lines.append(fileLineFromBlock(b.blockNumber()));
  return lines;
}

bool CodeEditor::hasBreakpoint(int fileLine) const {
  const QTextBlock b = document()->findBlockByNumber(editorLineFromFileLine(fileLine));
  return b.isValid() && blockHasBreakpoint(b);
}

void CodeEditor::toggleBreakpoint(int fileLine) {
  QTextBlock b = document()->findBlockByNumber(editorLineFromFileLine(fileLine));
  if (!b.isValid()) return;
  if (blockHasBreakpoint(b)) {
    b.setUserData(nullptr);
    --breakpointCount_;
  } else {
    b.setUserData(new BreakpointData);
    ++breakpointCount_;
  }
  gutter_->update();
  emit breakpointsChanged();
}

void CodeEditor::clearBreakpoints() {
  for (QTextBlock b = document()->begin(); b.isValid(); b = b.next()) b.setUserData(nullptr);
  breakpointCount_ = 0;
  gutter_->update();
  emit breakpointsChanged();
}

void CodeEditor::setExecutingLine(int fileLine) {
  executingLine_ = fileLine > 0 ? fileLine : 0;
  if (executingLine_ > 0) {
    const QTextBlock b = document()->findBlockByNumber(editorLineFromFileLine(executingLine_));
    if (b.isValid()) {
      // Scroll only when the block is off screen, so stepping does not jump the view.
      const QRectF r = blockBoundingGeometry(b).translated(contentOffset());
      if (r.top() < 0 || r.bottom() > viewport()->height()) {
        // Without line wrap the scroll bar counts blocks: centre the block.
        const int visibleLines = std::max(1, viewport()->height() / fontMetrics().height());
        verticalScrollBar()->setValue(std::max(0, b.blockNumber() - visibleLines / 2));
      }
    }
  }
  updateExtraSelections();
  gutter_->update();
}

void CodeEditor::updateExtraSelections() {
  QList<QTextEdit::ExtraSelection> sel;
  if (!isReadOnly()) {
    QTextEdit::ExtraSelection current;
    current.format.setBackground(QColor(0xff, 0xf8, 0xd8));
    current.format.setProperty(QTextFormat::FullWidthSelection, true);
    current.cursor = textCursor();
    current.cursor.clearSelection();
    sel.append(current);
  }
  if (executingLine_ > 0) {
    const QTextBlock b = document()->findBlockByNumber(editorLineFromFileLine(executingLine_));
    if (b.isValid()) {
      QTextEdit::ExtraSelection exec;
      exec.format.setBackground(QColor(0xc8, 0xf0, 0xc8));
      exec.format.setProperty(QTextFormat::FullWidthSelection, true);
      exec.cursor = QTextCursor(b);
      sel.append(exec);
    }
  }
  setExtraSelections(sel);
  gutter_->update();
}

void CodeEditor::setDiagnostics(const std::vector<core::Diagnostic>& diags) {
  QHash<int, QVector<Underline>> byLine;
  for (const auto& d : diags) {
    const int block = editorLineFromFileLine(d.range.line);
    const QTextBlock b = document()->findBlockByNumber(block);
    if (block < 0 || !b.isValid()) continue;
    const QString text = b.text();
    Underline u;
    u.severity = d.severity;
    if (d.range.column <= 0) {
      u.start = 0;
      u.length = 0;
    } else {
      u.start = utf16Index(text, d.range.column);
      u.length = d.range.length > 0 ? utf16Index(text, d.range.column + d.range.length) - u.start : 1;
      if (u.start >= text.size()) {  // a point past the end: mark the last character
        u.start = std::max(0, static_cast<int>(text.size()) - 1);
        u.length = 1;
      }
    }
    byLine[block].append(u);
  }
  highlighter_->setUnderlines(std::move(byLine));
}

void CodeEditor::goToFileLine(int fileLine, int column) {
  const int blockNo = std::clamp(editorLineFromFileLine(fileLine), 0, std::max(0, blockCount() - 1));
  const QTextBlock b = document()->findBlockByNumber(blockNo);
  QTextCursor c(b);
  if (column > 1)
    c.setPosition(b.position() + std::min(utf16Index(b.text(), column), static_cast<int>(b.length()) - 1));
  setTextCursor(c);
  centerCursor();
  setFocus();
}

QString CodeEditor::helpForPosition(int position) const {
  const QTextBlock b = document()->findBlock(position);
  if (!b.isValid()) return {};
  const QString text = b.text();
  int i = position - b.position();
  if (i < 0 || i >= text.size()) return {};
  // The word under the cursor, as the core cuts the line; a comment explains nothing.
  const std::u16string_view line(reinterpret_cast<const char16_t*>(text.utf16()),
                                 static_cast<std::size_t>(text.size()));
  const core::gcode::DisplayToken* word = nullptr;
  const std::vector<core::gcode::DisplayToken> tokens = core::gcode::displayTokens(line);
  for (const core::gcode::DisplayToken& t : tokens)
    if (i >= t.start && i < t.start + t.length) word = &t;
  if (!word || word->kind != core::gcode::DisplayTokenKind::Address) return {};
  const QChar letter = QChar::fromLatin1(word->letter);
  i = word->start;
  const int end = word->start + word->length;
  // X#101, Z-[#1+2.]: a macro expression; its value when the line last ran, if it has run.
  QString lastValue;
  if (end < text.size() && (text[end] == u'#' || text[end] == u'[') && wordValue_) {
    const QString v = wordValue_(firstFileLine() + b.blockNumber(), i + 1);
    if (!v.isEmpty())
      lastValue = QStringLiteral("<br>= %1 ").arg(v.toHtmlEscaped()) + tr("(the last time this line ran)");
  }
  const QString number = text.mid(i + 1, end - i - 1);
  const bool thai = Language::coreLang() == core::Lang::Th;
  if ((letter == u'G' || letter == u'M') && !number.isEmpty()) {
    bool ok = false;
    const int code = number.toInt(&ok);
    if (!ok) return {};
    const auto info = core::gcode::lookupCode(static_cast<char>(letter.unicode()), code, dialect_);
    const QString word = QStringLiteral("%1%2").arg(letter).arg(code, 2, 10, QLatin1Char('0'));
    if (!info) return tr("<b>%1</b>: not a code of this dialect").arg(word);
    const auto name = thai ? info->nameTh : info->nameEn;
    const auto example = thai ? info->exampleTh : info->exampleEn;
    return QStringLiteral("<b>%1</b> — %2<br><tt>%3</tt>")
        .arg(word, QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())),
             QString::fromUtf8(example.data(), static_cast<qsizetype>(example.size())).toHtmlEscaped());
  }
  const core::gcode::AddressInfo* address = core::gcode::addressInfo(static_cast<char>(letter.unicode()));
  if (!address) return {};
  const std::string_view meaning = thai ? address->meaningTh : address->meaningEn;
  const QString what = QString::fromUtf8(meaning.data(), static_cast<qsizetype>(meaning.size()));
  return QStringLiteral("<b>%1%2</b> — %3").arg(QString(letter), number.toHtmlEscaped(), what) + lastValue;
}

std::optional<std::pair<char, int>> CodeEditor::codeAtCursor() const {
  const QTextCursor c = textCursor();
  const QString text = c.block().text();
  const int at = c.positionInBlock();
  const std::u16string_view line(reinterpret_cast<const char16_t*>(text.utf16()),
                                 static_cast<std::size_t>(text.size()));
  for (const core::gcode::DisplayToken& t : core::gcode::displayTokens(line)) {
    if (t.kind != core::gcode::DisplayTokenKind::Address || (t.letter != 'G' && t.letter != 'M')) continue;
    if (at < t.start || at > t.start + t.length) continue;
    bool ok = false;
    const int number = text.mid(t.start + 1, t.length - 1).toInt(&ok);
    if (ok) return std::make_pair(t.letter, number);
  }
  return std::nullopt;
}

bool CodeEditor::viewportEvent(QEvent* event) {
  if (event->type() == QEvent::ToolTip) {
    auto* help = static_cast<QHelpEvent*>(event);
    const QTextCursor c = cursorForPosition(help->pos());
    // cursorForPosition gives the gap nearest the mouse; look at the character under it.
    const QRect r = cursorRect(c);
    int pos = c.position();
    if (help->pos().x() < r.x() && pos > c.block().position()) --pos;
    QString text = helpForPosition(pos);
    if (!text.isEmpty() && explainLine_) {
      const QString what = explainLine_(fileLineFromBlock(c.block().blockNumber()));
      if (!what.isEmpty()) text += QStringLiteral("<hr><i>%1</i>").arg(what.toHtmlEscaped());
    }
    if (text.isEmpty())
      QToolTip::hideText();
    else
      QToolTip::showText(help->globalPos(), text, viewport());
    return true;
  }
  return QPlainTextEdit::viewportEvent(event);
}

void CodeEditor::setUndoActions(QAction* undo, QAction* redo) {
  undoAction_ = undo;
  redoAction_ = redo;
}

// The undo keys, as the platform has them (Ctrl+Z; Ctrl+Y or Ctrl+Shift+Z).
static QAction* codeEditorUndoActionFor(QKeyEvent* key, QAction* undo, QAction* redo) {
  if (undo && key->matches(QKeySequence::Undo)) return undo;
  if (redo && key->matches(QKeySequence::Redo)) return redo;
  return nullptr;
}

bool CodeEditor::event(QEvent* event) {
  // Left to the window's shortcut: the text control would take Ctrl+Z for itself.
  if (event->type() == QEvent::ShortcutOverride &&
      codeEditorUndoActionFor(static_cast<QKeyEvent*>(event), undoAction_, redoAction_)) {
    event->ignore();
    return true;
  }
  return QPlainTextEdit::event(event);
}

void CodeEditor::keyPressEvent(QKeyEvent* event) {
  // Reaches here when the window's shortcut did not take it (e.g. nothing to undo).
  if (QAction* a = codeEditorUndoActionFor(event, undoAction_, redoAction_)) {
    if (a->isEnabled()) a->trigger();
    event->accept();
    return;
  }
  if (!newUndoStep_) {
    QPlainTextEdit::keyPressEvent(event);
    return;
  }
  // An edit block's step is never joined to the one before it (an empty block adds none).
  QTextCursor step(document());
  step.beginEditBlock();
  QPlainTextEdit::keyPressEvent(event);
  step.endEditBlock();
}

void CodeEditor::insertFromMimeData(const QMimeData* source) {
  QTextCursor step(document());
  step.beginEditBlock();
  QPlainTextEdit::insertFromMimeData(source);
  step.endEditBlock();
}

void CodeEditor::contextMenuEvent(QContextMenuEvent* event) {
  std::unique_ptr<QMenu> menu(createStandardContextMenu(event->pos()));
  // The menu's Undo / Redo are the window's, which know the setup's steps too.
  for (QAction* a : menu->actions()) {
    QAction* ours = a->objectName() == QLatin1String("edit-undo")   ? undoAction_.data()
                    : a->objectName() == QLatin1String("edit-redo") ? redoAction_.data()
                                                                    : nullptr;
    if (!ours) continue;
    menu->insertAction(a, ours);
    menu->removeAction(a);
  }
  menu->exec(event->globalPos());
}

void CodeEditor::changeEvent(QEvent* event) {
  QPlainTextEdit::changeEvent(event);
  if (event->type() == QEvent::FontChange) updateGutterWidth();
}

}  // namespace klueng::gui
