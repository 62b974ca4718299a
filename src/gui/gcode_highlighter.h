#pragma once
// Syntax colours for the G-code editor (G, M, T, axis words, F/S, N, O,
// comments, block skip) plus the checker's diagnostics as wavy underlines.
// Diagnostics are stored per editor line, so a new check result only
// re-colours the lines whose underlines changed (fast on 100,000 lines).
//
// Colours live in each line's QTextLayout, which costs several hundred bytes
// a line: a document of up to kEagerBlocks lines is coloured as it changes
// (as QSyntaxHighlighter does), a longer one only where the editor draws it
// (CodeEditor calls colourBlock before painting), so a 2,000,000-line program
// does not hold two million layouts (issue 29 item 8).
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QTextCharFormat>
#include <QTextLayout>
#include <QVector>

#include "klueng/core/diagnostic.h"

class QTextBlock;
class QTextDocument;

namespace klueng::gui {

struct Underline {
  int start = 0;   // UTF-16 index in the line
  int length = 0;  // UTF-16 units; 0 = to the end of the line
  core::Severity severity = core::Severity::Error;
};

class GcodeHighlighter : public QObject {
  Q_OBJECT
 public:
  enum class Kind { GCode, MCode, Tool, Axis, FeedSpeed, Sequence, Program, Comment, Skip, Macro, Variable, Other };
  static constexpr int kEagerBlocks = 20000;

  explicit GcodeHighlighter(QTextDocument* document);
  QTextDocument* document() const { return doc_; }

  // Replace all underlines; `byLine` is keyed by 0-based editor block number.
  void setUnderlines(QHash<int, QVector<Underline>> byLine);
  const QHash<int, QVector<Underline>>& underlines() const { return underlines_; }

  // Colours a block of the document unless its colours are up to date.
  void colourBlock(const QTextBlock& block);
  // Whether the block's colours are up to date.
  static bool isColoured(const QTextBlock& block);

  // The kind of word starting with `letter` (upper case), for tests and tooltips.
  static Kind kindOf(QChar letter);
  QTextCharFormat format(Kind kind) const;

 private:
  void onContentsChange(int from, int removed, int added);
  void colour(const QTextBlock& block);
  // The format ranges of one line: syntax colours, underlines on top.
  QList<QTextLayout::FormatRange> rangesFor(const QString& text, int blockNumber) const;

  QPointer<QTextDocument> doc_;
  QHash<int, QVector<Underline>> underlines_;
  QTextCharFormat formats_[static_cast<int>(Kind::Other) + 1];
};

}  // namespace klueng::gui
