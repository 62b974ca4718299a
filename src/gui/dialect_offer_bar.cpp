#include "gui/dialect_offer_bar.h"

#include "gui/note_bar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>

#include "gui/language.h"

namespace klueng::gui {

DialectOfferBar::DialectOfferBar(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("dialectOffer"));
  label_ = new QLabel(this);
  label_->setWordWrap(true);
  switchButton_ = new QPushButton(this);
  switchButton_->setObjectName(QStringLiteral("dialectOfferSwitch"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(switchButton_);
  QToolButton* close = layOutNoteBar(this, label_, buttons, 3);
  connect(switchButton_, &QPushButton::clicked, this, [this] {
    hide();
    emit switchRequested(dialect_);
  });
  connect(close, &QToolButton::clicked, this, [this] {
    dismissed_ = true;
    hide();
  });
  hide();
}

void DialectOfferBar::offer(core::gcode::Dialect dialect, int blocks) {
  if (dismissed_ && dialect == dialect_) return;
  dismissed_ = false;
  dialect_ = dialect;
  blocks_ = blocks;
  retranslate();
  show();
}

void DialectOfferBar::clear() {
  dismissed_ = false;
  hide();
}

QString DialectOfferBar::text() const { return isVisible() ? label_->text() : QString(); }

void DialectOfferBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void DialectOfferBar::retranslate() {
  // The dialect as the Tool setting menu names it, in both languages (issue 28 item 8):
  // brand names stay in Latin letters ("Haas", never "ฮาส").
  const QString name = dialect_ == core::gcode::Dialect::Haas      ? tr("Haas ST (NGC)")
                       : dialect_ == core::gcode::Dialect::Classic ? tr("Rook classic (1999 rules)")
                                                                   : tr("Fanuc 0i-TF");
  label_->setText(tr("Blocks in %1 form that the current dialect refuses: %2. The %1 dialect accepts the "
                     "whole program.")
                      .arg(name)
                      .arg(blocks_));
  switchButton_->setText(tr("Switch to %1").arg(name));
}

}  // namespace klueng::gui
