#include "gui/first_steps_bar.h"

#include "gui/note_bar.h"

#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QIcon>
#include <QLabel>
#include <QPushButton>
#include <QToolButton>

namespace klueng::gui {

FirstStepsBar::FirstStepsBar(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("firstSteps"));
  label_ = new QLabel(this);
  label_->setWordWrap(true);
  openSample_ = new QPushButton(this);
  openSample_->setObjectName(QStringLiteral("firstStepsOpenSample"));
  browse_ = new QPushButton(this);
  browse_->setObjectName(QStringLiteral("firstStepsBrowse"));
  auto* buttons = new QVBoxLayout;
  buttons->addWidget(openSample_);
  buttons->addWidget(browse_);
  buttons->addStretch(1);
  QToolButton* close = layOutNoteBar(this, label_, buttons, 4);
  connect(openSample_, &QPushButton::clicked, this, [this] {
    hide();
    emit openRequested(sample_);
  });
  connect(browse_, &QPushButton::clicked, this, [this] { emit browseRequested(); });
  connect(close, &QToolButton::clicked, this, &QWidget::hide);
  hide();
  retranslate();
}

void FirstStepsBar::offer(const QString& samplesFolder) {
  const QString sample = QDir(samplesFolder).filePath(QStringLiteral("01-step-shaft.txt"));
  if (samplesFolder.isEmpty() || !QFileInfo(sample).isFile()) return;
  sample_ = sample;
  retranslate();
  show();
}

QString FirstStepsBar::text() const { return isVisible() ? label_->text() : QString(); }

void FirstStepsBar::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

void FirstStepsBar::retranslate() {
  label_->setText(
      tr("<b>What to do first:</b> 1. open a sample program (sample 01 turns a step shaft); "
         "2. press <b>Go</b> (F5) and watch the tool cut the bar; "
         "3. click a line of the program to read what it does."));
  openSample_->setText(tr("Open sample 01"));
  browse_->setText(tr("All samples…"));
}

}  // namespace klueng::gui
