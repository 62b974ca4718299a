#pragma once
// The blue note bars above the editor (the dialect offer, the first steps): one
// look — the note icon, the wrapping text, the bar's buttons, a close button.
#include <QBoxLayout>
#include <QColor>
#include <QIcon>
#include <QLabel>
#include <QPalette>
#include <QToolButton>

namespace klueng::gui {

// Lays `bar` out and colours it; returns its close button for the caller to connect.
inline QToolButton* layOutNoteBar(QWidget* bar, QLabel* text, QLayout* buttons, int verticalMargin) {
  auto* close = new QToolButton(bar);
  close->setIcon(QIcon(QStringLiteral(":/icons/close.svg")));
  close->setAutoRaise(true);
  auto* layout = new QHBoxLayout(bar);
  layout->setContentsMargins(8, verticalMargin, 4, verticalMargin);
  auto* icon = new QLabel(bar);
  icon->setPixmap(QIcon(QStringLiteral(":/icons/note.svg")).pixmap(18, 18));
  layout->addWidget(icon, 0, Qt::AlignTop);
  layout->addWidget(text, 1);
  layout->addLayout(buttons, 0);
  layout->addWidget(close, 0, Qt::AlignTop);
  QPalette p = bar->palette();
  p.setColor(QPalette::Window, QColor(0xe3, 0xf0, 0xfd));
  p.setColor(QPalette::WindowText, QColor(0x0d, 0x3a, 0x6e));
  bar->setPalette(p);
  bar->setAutoFillBackground(true);
  return close;
}

}  // namespace klueng::gui
