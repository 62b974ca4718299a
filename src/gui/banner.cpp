#include "gui/banner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace klueng::gui {

Banner::Banner(QWidget* parent) : QWidget(parent), label_(new QLabel(this)) {
  setObjectName(QStringLiteral("banner"));
  label_->setWordWrap(true);
  label_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto* close = new QToolButton(this);
  close->setIcon(QIcon(QStringLiteral(":/icons/close.svg")));
  close->setAutoRaise(true);
  connect(close, &QToolButton::clicked, this, &Banner::dismiss);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(8, 4, 4, 4);
  layout->addWidget(label_, 1);
  layout->addWidget(close, 0, Qt::AlignTop);
  setAutoFillBackground(true);
  hide();
}

void Banner::showMessage(const QString& text, bool error) {
  QPalette p = palette();
  p.setColor(QPalette::Window, error ? QColor(0xfd, 0xe2, 0xe2) : QColor(0xfd, 0xf4, 0xd0));
  p.setColor(QPalette::WindowText, error ? QColor(0x80, 0x10, 0x10) : QColor(0x60, 0x48, 0x00));
  setPalette(p);
  label_->setText(text);
  show();
}

void Banner::dismiss() {
  hide();
  label_->clear();
}

QString Banner::text() const { return isVisible() ? label_->text() : QString(); }

}  // namespace klueng::gui
