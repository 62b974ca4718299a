#include "gui/gcode_highlighter.h"

#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/display_tokens.h"

#include <algorithm>
#include <iterator>
#include <string_view>

#include <QColor>
#include <QSet>
#include <QTextBlock>
#include <QTextDocument>

namespace klueng::gui {

namespace {
// QTextBlock::userState of a block whose colours are up to date (new and edited blocks are not).
constexpr int kColouredState = 1;
}  // namespace

GcodeHighlighter::GcodeHighlighter(QTextDocument* document) : QObject(document), doc_(document) {
  auto set = [this](Kind k, const QColor& c, bool bold = false, bool italic = false) {
    QTextCharFormat f;
    f.setForeground(c);
    if (bold) f.setFontWeight(QFont::Bold);
    f.setFontItalic(italic);
    formats_[static_cast<int>(k)] = f;
  };
  set(Kind::GCode, QColor(0x1f, 0x4e, 0xc8), true);    // blue
  set(Kind::MCode, QColor(0xa0, 0x22, 0xa8), true);    // purple
  set(Kind::Tool, QColor(0xc4, 0x5a, 0x00), true);     // orange
  set(Kind::Axis, QColor(0x0b, 0x7a, 0x3e));           // green
  set(Kind::FeedSpeed, QColor(0x00, 0x7c, 0x8c));      // teal
  set(Kind::Sequence, QColor(0x88, 0x88, 0x88));       // grey
  set(Kind::Program, QColor(0x8b, 0x00, 0x00), true);  // dark red
  set(Kind::Comment, QColor(0x6a, 0x73, 0x7d), false, true);
  set(Kind::Skip, QColor(0xd0, 0x60, 0x00), true);
  set(Kind::Macro, QColor(0x00, 0x5f, 0x73), true);  // macro B keywords and functions
  set(Kind::Variable, QColor(0x9a, 0x5b, 0x00));     // #101
  if (doc_) connect(doc_, &QTextDocument::contentsChange, this, &GcodeHighlighter::onContentsChange);
}

bool GcodeHighlighter::isColoured(const QTextBlock& block) { return block.userState() == kColouredState; }

void GcodeHighlighter::colourBlock(const QTextBlock& block) {
  if (block.isValid() && !isColoured(block)) colour(block);
}

void GcodeHighlighter::onContentsChange(int from, int removed, int added) {
  Q_UNUSED(removed);
  if (!doc_) return;
  const bool eager = doc_->blockCount() <= kEagerBlocks;
  const QTextBlock last = doc_->findBlock(std::max(from, from + added));
  for (QTextBlock b = doc_->findBlock(from); b.isValid(); b = b.next()) {
    // A line already coloured (shown, or a short document) is coloured again now;
    // another one waits until it is drawn.
    if (eager || isColoured(b))
      colour(b);
    else
      b.setUserState(-1);
    if (b == last) break;
  }
}

GcodeHighlighter::Kind GcodeHighlighter::kindOf(QChar letter) {
  const QChar upper = letter.toUpper();
  if (upper.unicode() >= 128) return Kind::Other;
  // The core's address table says what a letter is; this only picks its colour.
  const core::gcode::AddressInfo* a = core::gcode::addressInfo(static_cast<char>(upper.unicode()));
  if (!a) return Kind::Other;
  switch (a->kind) {
    case core::gcode::AddressKind::GCode: return Kind::GCode;
    case core::gcode::AddressKind::MCode: return Kind::MCode;
    case core::gcode::AddressKind::Tool: return Kind::Tool;
    case core::gcode::AddressKind::Axis: return Kind::Axis;
    case core::gcode::AddressKind::FeedSpeed:
    case core::gcode::AddressKind::Parameter: return Kind::FeedSpeed;
    case core::gcode::AddressKind::Sequence: return Kind::Sequence;
    case core::gcode::AddressKind::Program: return Kind::Program;
  }
  return Kind::Other;
}

QTextCharFormat GcodeHighlighter::format(Kind kind) const { return formats_[static_cast<int>(kind)]; }

void GcodeHighlighter::setUnderlines(QHash<int, QVector<Underline>> byLine) {
  QSet<int> changed;
  for (auto it = underlines_.cbegin(); it != underlines_.cend(); ++it) {
    auto other = byLine.constFind(it.key());
    if (other == byLine.cend() || other->size() != it->size())
      changed.insert(it.key());
    else
      for (int i = 0; i < it->size(); ++i)
        if ((*it)[i].start != (*other)[i].start || (*it)[i].length != (*other)[i].length ||
            (*it)[i].severity != (*other)[i].severity)
          changed.insert(it.key());
  }
  for (auto it = byLine.cbegin(); it != byLine.cend(); ++it)
    if (!underlines_.contains(it.key())) changed.insert(it.key());
  underlines_ = std::move(byLine);
  if (!doc_) return;
  const bool eager = doc_->blockCount() <= kEagerBlocks;
  for (int line : changed) {
    QTextBlock block = doc_->findBlockByNumber(line);
    if (!block.isValid()) continue;
    if (eager || isColoured(block))
      colour(block);
    else
      block.setUserState(-1);
  }
}

QList<QTextLayout::FormatRange> GcodeHighlighter::rangesFor(const QString& text, int blockNumber) const {
  const int n = static_cast<int>(text.size());
  QVector<QTextCharFormat> chars(n);  // one format a character, merged into ranges below
  const auto setFormat = [&chars, n](int start, int count, const QTextCharFormat& f) {
    for (int i = std::max(0, start); i < std::min(n, start + count); ++i) chars[i] = f;
  };
  // The core cuts the line into tokens; this only picks their colours.
  const std::u16string_view line(reinterpret_cast<const char16_t*>(text.utf16()), static_cast<std::size_t>(n));
  for (const core::gcode::DisplayToken& t : core::gcode::displayTokens(line)) {
    Kind kind = Kind::Other;
    switch (t.kind) {
      case core::gcode::DisplayTokenKind::Comment: kind = Kind::Comment; break;
      case core::gcode::DisplayTokenKind::Skip: kind = Kind::Skip; break;
      case core::gcode::DisplayTokenKind::Variable: kind = Kind::Variable; break;
      case core::gcode::DisplayTokenKind::MacroWord: kind = Kind::Macro; break;
      case core::gcode::DisplayTokenKind::Address: kind = kindOf(QChar::fromLatin1(t.letter)); break;
    }
    if (kind != Kind::Other) setFormat(t.start, t.length, format(kind));
  }
  const auto it = underlines_.constFind(blockNumber);
  if (it != underlines_.cend() && n > 0) {
    for (const Underline& u : *it) {
      const int start = std::clamp(u.start, 0, n - 1);
      const int len = u.length > 0 ? std::min(u.length, n - start) : n - start;
      const QColor colour = core::isError(u.severity)            ? QColor(0xd0, 0x10, 0x10)
                            : u.severity == core::Severity::Note ? QColor(0x20, 0x60, 0xc0)
                                                                 : QColor(0xe0, 0x8a, 0x00);
      for (int k = start; k < std::min(n, start + std::max(len, 1)); ++k) {
        // Keep the syntax colour; add the underline on top of it.
        chars[k].setUnderlineStyle(QTextCharFormat::WaveUnderline);
        chars[k].setUnderlineColor(colour);
      }
    }
  }
  QList<QTextLayout::FormatRange> ranges;
  const QTextCharFormat empty;
  for (int i = 0; i < n;) {
    if (chars[i] == empty) {
      ++i;
      continue;
    }
    QTextLayout::FormatRange r;
    r.start = i;
    r.format = chars[i];
    while (i < n && chars[i] == r.format) ++i;
    r.length = i - r.start;
    ranges << r;
  }
  return ranges;
}

void GcodeHighlighter::colour(const QTextBlock& block) {
  QList<QTextLayout::FormatRange> ranges = rangesFor(block.text(), block.blockNumber());
  QTextBlock b = block;
  b.setUserState(kColouredState);
  QTextLayout* layout = b.layout();
  // Text being composed by an input method (Thai) sits inside the layout's text.
  const int preeditStart = layout->preeditAreaPosition();
  const int preeditLength = static_cast<int>(layout->preeditAreaText().size());
  if (preeditLength > 0)
    for (QTextLayout::FormatRange& r : ranges) {
      if (r.start >= preeditStart)
        r.start += preeditLength;
      else if (r.start + r.length >= preeditStart)
        r.length += preeditLength;
    }
  if (layout->formats() == ranges) return;
  layout->setFormats(ranges);
  doc_->markContentsDirty(block.position(), block.length());
}

}  // namespace klueng::gui
