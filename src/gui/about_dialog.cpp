#include "gui/about_dialog.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace klueng::gui {

AboutDialog::AboutDialog(QWidget* parent) : QDialog(parent) {
  title_ = new QLabel(this);
  QFont f = title_->font();
  f.setPointSizeF(f.pointSizeF() * 1.6);
  f.setBold(true);
  title_->setFont(f);
  body_ = new QLabel(this);
  body_->setWordWrap(true);
  body_->setOpenExternalLinks(true);
  body_->setMinimumWidth(420);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Close, this);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(title_);
  layout->addWidget(body_, 1);
  layout->addWidget(buttons_);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  retranslate();
}

void AboutDialog::retranslate() {
  setWindowTitle(tr("About Klueng"));
  title_->setText(tr("Klueng %1").arg(QStringLiteral("0.1.0")));
  body_->setText(tr("<p>A CNC lathe simulator for students and instructors: write a Fanuc-style lathe program, "
                    "see every mistake explained, and watch bitmap tools cut the stock, block by block.</p>"
                    "<p>Klueng descends from the 1999 Thai thesis program “Rook.IE Lathe”.</p>"
                    "<p>Built with Qt %1, Eigen, fmt and libpng.</p>")
                     .arg(QString::fromLatin1(qVersion())));
}

void AboutDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

}  // namespace klueng::gui
