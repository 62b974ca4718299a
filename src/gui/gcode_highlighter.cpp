#include "gui/gcode_highlighter.h"

#include "klueng/core/gcode/address_table.h"
#include "klueng/core/gcode/display_tokens.h"

#include <algorithm>
#include <iterator>
#include <string_view>

#include <QColor>
#include <QSet>
#include <QTextDocument>

namespace klueng::gui {

GcodeHighlighter::GcodeHighlighter(QTextDocument* document) : QSyntaxHighlighter(document) {
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
  set(Kind::Macro, QColor(0x00, 0x5f, 0x73), true);     // macro B keywords and functions
  set(Kind::Variable, QColor(0x9a, 0x5b, 0x00));        // #101
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
    if (other == byLine.cend() || other->size() != it->size()) changed.insert(it.key());
    else
      for (int i = 0; i < it->size(); ++i)
        if ((*it)[i].start != (*other)[i].start || (*it)[i].length != (*other)[i].length ||
            (*it)[i].severity != (*other)[i].severity)
          changed.insert(it.key());
  }
  for (auto it = byLine.cbegin(); it != byLine.cend(); ++it)
    if (!underlines_.contains(it.key())) changed.insert(it.key());
  underlines_ = std::move(byLine);
  QTextDocument* doc = document();
  if (!doc) return;
  for (int line : changed) {
    const QTextBlock block = doc->findBlockByNumber(line);
    if (block.isValid()) rehighlightBlock(block);
  }
}

void GcodeHighlighter::highlightBlock(const QString& text) {
  const int n = static_cast<int>(text.size());
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
  const auto it = underlines_.constFind(currentBlock().blockNumber());
  if (it == underlines_.cend()) return;
  for (const Underline& u : *it) {
    const int start = std::clamp(u.start, 0, std::max(0, n - 1));
    const int len = u.length > 0 ? std::min(u.length, n - start) : n - start;
    const QColor colour = core::isError(u.severity)                ? QColor(0xd0, 0x10, 0x10)
                         : u.severity == core::Severity::Note ? QColor(0x20, 0x60, 0xc0)
                                                              : QColor(0xe0, 0x8a, 0x00);
    for (int k = start; k < start + std::max(len, 1) && k <= n; ++k) {
      // Keep the syntax colour; add the underline on top of it.
      QTextCharFormat f = QSyntaxHighlighter::format(std::min(k, std::max(0, n - 1)));
      f.setUnderlineStyle(QTextCharFormat::WaveUnderline);
      f.setUnderlineColor(colour);
      setFormat(k, 1, f);
    }
  }
}

}  // namespace klueng::gui
