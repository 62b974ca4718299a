#pragma once
// Help > Contents: help for self-learners. Every G and M code of the core's
// code table with its name and an example, in the UI language with the other
// language beneath, plus the program file layout and the word letters; a
// worked example per code that runs as it is; a search field (core::machine::
// searchHelp: "roughing" and "กลึงปอกหยาบ" find G71); F1 opens a code's entry.
// Regenerated when the language or dialect changes.
#include <QDialog>

#include "klueng/core/gcode/code_table.h"

class QLineEdit;
class QListWidget;
class QListWidgetItem;
class QTextBrowser;

namespace klueng::gui {

class HelpContents : public QDialog {
  Q_OBJECT
 public:
  explicit HelpContents(QWidget* parent = nullptr);

  void setDialect(core::gcode::Dialect dialect);
  // Open at a code's entry (F1 on a word in the editor).
  void showCode(char letter, int number);
  static QString anchorOf(char letter, int number);  // "G71", "M08"
  // Codes whose worked example comes with a picture of its path: the roughing and threading cycles by action
  // (G71-G73, G76 in G-code system A).
  static bool pictured(const core::gcode::CodeInfo& row);
  QTextBrowser* browser() const { return browser_; }
  QLineEdit* searchField() const { return search_; }
  QListWidget* hits() const { return hits_; }
  QString shownAnchor() const { return shownAnchor_; }
  // The page as HTML (thai: UI language is Thai).
  static QString buildHtml(bool thai, core::gcode::Dialect dialect);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void rebuild();
  void search(const QString& text);
  void showHit(QListWidgetItem* item);
  QLineEdit* search_;
  QListWidget* hits_;
  QTextBrowser* browser_;
  QString shownAnchor_;
  core::gcode::Dialect dialect_ = core::gcode::Dialect::Fanuc;
};

}  // namespace klueng::gui
