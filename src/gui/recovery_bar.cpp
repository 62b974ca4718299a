#include "gui/recovery_bar.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>

namespace klueng::gui {

RecoveryBar::RecoveryBar(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("recoveryBar"));
  label_ = new QLabel(this);
  label_->setWordWrap(true);
  restore_ = new QPushButton(this);
  restore_->setObjectName(QStringLiteral("recoveryRestore"));
  compare_ = new QPushButton(this);
  compare_->setObjectName(QStringLiteral("recoveryCompare"));
  discard_ = new QPushButton(this);
  discard_->setObjectName(QStringLiteral("recoveryDiscard"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(8, 3, 4, 3);
  auto* icon = new QLabel(this);
  icon->setPixmap(QIcon(QStringLiteral(":/icons/save.svg")).pixmap(18, 18));
  layout->addWidget(icon, 0, Qt::AlignTop);
  layout->addWidget(label_, 1);
  layout->addWidget(restore_);
  layout->addWidget(compare_);
  layout->addWidget(discard_);
  QPalette p = palette();
  p.setColor(QPalette::Window, QColor(0xe6, 0xf4, 0xe4));
  p.setColor(QPalette::WindowText, QColor(0x1c, 0x4a, 0x17));
  setPalette(p);
  setAutoFillBackground(true);
  connect(restore_, &QPushButton::clicked, this, &RecoveryBar::restoreFirst);
  connect(discard_, &QPushButton::clicked, this, &RecoveryBar::discardFirst);
  connect(compare_, &QPushButton::clicked, this, &RecoveryBar::compareFirst);
  retranslate();
  hide();
}

void RecoveryBar::offer(QVector<RecoveryCopy> copies) {
  copies_ = std::move(copies);
  retranslate();
  setVisible(!copies_.isEmpty());
}

QString RecoveryBar::text() const { return isVisible() ? label_->text() : QString(); }

void RecoveryBar::restoreFirst() {
  if (copies_.isEmpty()) return;
  const RecoveryCopy c = copies_.front();
  next();
  emit restoreRequested(c);
}

void RecoveryBar::discardFirst() {
  if (copies_.isEmpty()) return;
  const RecoveryCopy c = copies_.front();
  next();
  emit discardRequested(c);
}

void RecoveryBar::next() {
  copies_.removeFirst();
  retranslate();
  setVisible(!copies_.isEmpty());
}

QString RecoveryBar::comparison() const {
  if (copies_.isEmpty()) return {};
  // The hunks of the line diff: the file's lines (-) and the copy's (+), at most 400 lines shown.
  const RecoveryDifference d = Recovery::difference(copies_.front());
  QStringList lines;
  if (d.fileMissing) {
    for (const QString& line : d.copyLines) lines << QStringLiteral("  + %1").arg(line);
  }
  for (const RecoveryHunk& h : d.hunks) {
    lines << tr("line %1").arg(h.copyStart + 1);
    for (int i = 0; i < h.fileCount; ++i) lines << QStringLiteral("  - %1").arg(d.fileLines[h.fileStart + i]);
    for (int i = 0; i < h.copyCount; ++i) lines << QStringLiteral("  + %1").arg(d.copyLines[h.copyStart + i]);
    if (lines.size() >= 400) break;
  }
  if (lines.size() > 400) lines.resize(400);
  return lines.join(QLatin1Char('\n'));
}

void RecoveryBar::compareFirst() {
  if (copies_.isEmpty()) return;
  QMessageBox box(this);
  box.setObjectName(QStringLiteral("recoveryCompareBox"));
  box.setIcon(QMessageBox::Information);
  box.setWindowTitle(tr("Unsaved work"));
  box.setText(label_->text());
  box.setInformativeText(tr("Lines marked - are in the file; lines marked + are in the unsaved copy."));
  box.setDetailedText(comparison());
  box.exec();
}

void RecoveryBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void RecoveryBar::retranslate() {
  restore_->setText(tr("Rest&ore"));
  compare_->setText(tr("Co&mpare"));
  discard_->setText(tr("Dis&card"));
  if (copies_.isEmpty()) {
    label_->clear();
    return;
  }
  const RecoveryCopy& c = copies_.front();
  const RecoveryDifference d = Recovery::difference(c);
  const QString when = QLocale().toString(c.written, QLocale::ShortFormat);
  QString what;
  if (d.fileMissing)
    what = tr("%n line(s) of unsaved work", nullptr, d.linesDiffering);
  else if (d.linesDiffering == 0)
    what = tr("the same as the file on disk");
  else
    what = tr("%n line(s) differ from the file, the first at line %1", nullptr, d.linesDiffering).arg(d.firstLine);
  QString text = tr("Klueng closed without saving \"%1\" (edited %2): %3.").arg(c.displayName, when, what);
  if (copies_.size() > 1)
    text += QLatin1Char(' ') + tr("%n more after this one.", nullptr, static_cast<int>(copies_.size() - 1));
  label_->setText(text);
}

}  // namespace klueng::gui
