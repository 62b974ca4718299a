#include "gui/find_dialog.h"

#include <QCheckBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QTextBlock>
#include <QVBoxLayout>

namespace klueng::gui {

FindDialog::FindDialog(QPlainTextEdit* editor, QWidget* parent) : QDialog(parent), editor_(editor) {
  setObjectName(QStringLiteral("findDialog"));
  findLabel_ = new QLabel(this);
  replaceLabel_ = new QLabel(this);
  findEdit_ = new QLineEdit(this);
  replaceEdit_ = new QLineEdit(this);
  findLabel_->setBuddy(findEdit_);
  replaceLabel_->setBuddy(replaceEdit_);
  caseBox_ = new QCheckBox(this);
  wordsBox_ = new QCheckBox(this);
  nextButton_ = new QPushButton(this);
  prevButton_ = new QPushButton(this);
  replaceButton_ = new QPushButton(this);
  replaceAllButton_ = new QPushButton(this);
  closeButton_ = new QPushButton(this);
  status_ = new QLabel(this);
  nextButton_->setDefault(true);

  auto* grid = new QGridLayout;
  grid->addWidget(findLabel_, 0, 0);
  grid->addWidget(findEdit_, 0, 1);
  grid->addWidget(replaceLabel_, 1, 0);
  grid->addWidget(replaceEdit_, 1, 1);
  grid->addWidget(caseBox_, 2, 1);
  grid->addWidget(wordsBox_, 3, 1);
  grid->addWidget(status_, 4, 0, 1, 2);
  auto* buttons = new QVBoxLayout;
  for (QPushButton* b : {nextButton_, prevButton_, replaceButton_, replaceAllButton_}) buttons->addWidget(b);
  buttons->addStretch();
  buttons->addWidget(closeButton_);
  auto* top = new QHBoxLayout(this);
  top->addLayout(grid, 1);
  top->addLayout(buttons);

  connect(nextButton_, &QPushButton::clicked, this, [this] { findNext(false); });
  connect(prevButton_, &QPushButton::clicked, this, [this] { findNext(true); });
  connect(replaceButton_, &QPushButton::clicked, this, &FindDialog::replaceCurrent);
  connect(replaceAllButton_, &QPushButton::clicked, this, &FindDialog::replaceAll);
  connect(closeButton_, &QPushButton::clicked, this, &QDialog::hide);
  connect(findEdit_, &QLineEdit::returnPressed, this, [this] { findNext(false); });
  retranslateUi();
}

void FindDialog::setFindText(const QString& text) {
  findEdit_->setText(text);
  findEdit_->selectAll();
}
void FindDialog::setReplaceText(const QString& text) { replaceEdit_->setText(text); }
void FindDialog::setCaseSensitive(bool on) { caseBox_->setChecked(on); }
void FindDialog::setWholeWords(bool on) { wordsBox_->setChecked(on); }

QTextDocument::FindFlags FindDialog::flags(bool backward) const {
  QTextDocument::FindFlags f;
  if (backward) f |= QTextDocument::FindBackward;
  if (caseBox_->isChecked()) f |= QTextDocument::FindCaseSensitively;
  if (wordsBox_->isChecked()) f |= QTextDocument::FindWholeWords;
  return f;
}

bool FindDialog::findNext(bool backward) {
  const QString needle = findEdit_->text();
  status_->clear();
  if (needle.isEmpty()) return false;
  QTextDocument* doc = editor_->document();
  QTextCursor found = doc->find(needle, editor_->textCursor(), flags(backward));
  if (found.isNull()) {  // wrap around
    QTextCursor start(doc);
    if (backward) start.movePosition(QTextCursor::End);
    found = doc->find(needle, start, flags(backward));
  }
  if (found.isNull()) {
    status_->setText(tr("\"%1\" was not found.").arg(needle));
    return false;
  }
  editor_->setTextCursor(found);
  editor_->ensureCursorVisible();
  return true;
}

bool FindDialog::replaceCurrent() {
  QTextCursor c = editor_->textCursor();
  const Qt::CaseSensitivity cs = caseBox_->isChecked() ? Qt::CaseSensitive : Qt::CaseInsensitive;
  if (c.hasSelection() && c.selectedText().compare(findEdit_->text(), cs) == 0) {
    c.insertText(replaceEdit_->text());
    editor_->setTextCursor(c);
  }
  return findNext(false);
}

int FindDialog::replaceAll() {
  const QString needle = findEdit_->text();
  if (needle.isEmpty()) return 0;
  QTextDocument* doc = editor_->document();
  QTextCursor edit(doc);
  edit.beginEditBlock();
  int count = 0;
  QTextCursor found = doc->find(needle, QTextCursor(doc), flags(false));
  while (!found.isNull()) {
    found.insertText(replaceEdit_->text());
    ++count;
    found = doc->find(needle, found, flags(false));
  }
  edit.endEditBlock();
  status_->setText(tr("%n replacement(s) made.", nullptr, count));
  return count;
}

void FindDialog::retranslateUi() {
  setWindowTitle(tr("Find and Replace"));
  findLabel_->setText(tr("&Find:"));
  replaceLabel_->setText(tr("Replace &with:"));
  caseBox_->setText(tr("Match &case"));
  wordsBox_->setText(tr("Whole &words"));
  nextButton_->setText(tr("Find &Next"));
  prevButton_->setText(tr("Find &Previous"));
  replaceButton_->setText(tr("&Replace"));
  replaceAllButton_->setText(tr("Replace &All"));
  closeButton_->setText(tr("Close"));
}

void FindDialog::changeEvent(QEvent* event) {
  QDialog::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

}  // namespace klueng::gui
