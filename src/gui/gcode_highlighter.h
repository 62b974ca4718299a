#pragma once
// Syntax colours for the G-code editor (G, M, T, axis words, F/S, N, O,
// comments, block skip) plus the checker's diagnostics as wavy underlines.
// Diagnostics are stored per editor line, so a new check result only
// re-highlights the lines whose underlines changed (fast on 100,000 lines).
#include <QHash>
#include <QSyntaxHighlighter>
#include <QTextCharFormat>
#include <QVector>

#include "klueng/core/diagnostic.h"

namespace klueng::gui {

struct Underline {
  int start = 0;    // UTF-16 index in the line
  int length = 0;   // UTF-16 units; 0 = to the end of the line
  core::Severity severity = core::Severity::Error;
};

class GcodeHighlighter : public QSyntaxHighlighter {
  Q_OBJECT
 public:
  enum class Kind { GCode, MCode, Tool, Axis, FeedSpeed, Sequence, Program, Comment, Skip, Macro, Variable, Other };

  explicit GcodeHighlighter(QTextDocument* document);

  // Replace all underlines; `byLine` is keyed by 0-based editor block number.
  void setUnderlines(QHash<int, QVector<Underline>> byLine);
  const QHash<int, QVector<Underline>>& underlines() const { return underlines_; }

  // The kind of word starting with `letter` (upper case), for tests and tooltips.
  static Kind kindOf(QChar letter);
  QTextCharFormat format(Kind kind) const;

 protected:
  void highlightBlock(const QString& text) override;

 private:
  QHash<int, QVector<Underline>> underlines_;
  QTextCharFormat formats_[static_cast<int>(Kind::Other) + 1];
};

}  // namespace klueng::gui
