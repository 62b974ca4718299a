#pragma once
// Find / Replace over the G-code editor (non-modal). Replace All is one undo step.
#include <QDialog>
#include <QTextDocument>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace klueng::gui {

class FindDialog : public QDialog {
  Q_OBJECT
 public:
  FindDialog(QPlainTextEdit* editor, QWidget* parent = nullptr);

  void setFindText(const QString& text);
  void setReplaceText(const QString& text);
  void setCaseSensitive(bool on);
  void setWholeWords(bool on);

  // Select the next (or previous) match, wrapping around; false if none.
  bool findNext(bool backward = false);
  // Replace the selected match (if it is one) and find the next.
  bool replaceCurrent();
  // Replace every match; returns how many.
  int replaceAll();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  QTextDocument::FindFlags flags(bool backward) const;

  QPlainTextEdit* editor_;
  QLabel* findLabel_;
  QLabel* replaceLabel_;
  QLineEdit* findEdit_;
  QLineEdit* replaceEdit_;
  QCheckBox* caseBox_;
  QCheckBox* wordsBox_;
  QPushButton* nextButton_;
  QPushButton* prevButton_;
  QPushButton* replaceButton_;
  QPushButton* replaceAllButton_;
  QPushButton* closeButton_;
  QLabel* status_;
};

}  // namespace klueng::gui
