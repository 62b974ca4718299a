#include "gui/header_strip.h"

#include <QEvent>
#include <QMouseEvent>

namespace klueng::gui {

HeaderStrip::HeaderStrip(QWidget* parent) : QLabel(parent) {
  setObjectName(QStringLiteral("headerStrip"));
  setContentsMargins(6, 2, 6, 2);
  setCursor(Qt::PointingHandCursor);
  // A long line (Thai at 1366 px, a long project name) wraps in the pane rather than
  // losing "(click to edit)" at its edge; it never widens the editor pane.
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  setWordWrap(true);
  setStyleSheet(QStringLiteral("QLabel { background: #f0f0ea; color: #606060; border-bottom: 1px solid #d8d8d0; }"));
  setVisible(false);
}

void HeaderStrip::showHeader(const core::io::JobHeader& header, bool plainGcode) {
  header_ = header;
  plain_ = plainGcode;
  retranslateUi();
}

void HeaderStrip::retranslateUi() {
  setVisible(!plain_);
  if (plain_) return;
  const QString project = QString::fromStdString(header_.project);
  const QString part = QString::fromStdString(header_.part);
  // The bar as the header writes it: an inch header (1.75, 3.0 in) stays in inches.
  const bool inch =
      header_.diameterUnit == core::io::LengthUnit::Inch && header_.lengthUnit == core::io::LengthUnit::Inch;
  const QString size = inch ? tr("Ø%1 × %2 in").arg(header_.diameter).arg(header_.length)  // "นิ้ว" in Thai
                            : tr("Ø%1 × %2 mm").arg(header_.diameterMm()).arg(header_.lengthMm());  // "มม." in Thai
  setText(tr("Lines 1–6: job header — %1, %2, %3 (click to edit)")
              .arg(project.isEmpty() ? tr("no project") : project, part.isEmpty() ? tr("no part") : part, size));
  setToolTip(
      tr("The file's first six lines hold the project, part, material, stock diameter, stock length and "
         "programmer; the program starts on line 7. File > Job Details edits them."));
}

void HeaderStrip::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) emit activated();
  QLabel::mousePressEvent(event);
}

void HeaderStrip::changeEvent(QEvent* event) {
  QLabel::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

}  // namespace klueng::gui
