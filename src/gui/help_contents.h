#pragma once
// Help > Contents: help for self-learners. Every G and M code of the core's
// code table with its name and an example, in the UI language with the other
// language beneath, plus the program file layout and the word letters.
// Regenerated when the language or dialect changes.
#include <QDialog>

#include "klueng/core/gcode/code_table.h"

class QTextBrowser;

namespace klueng::gui {

class HelpContents : public QDialog {
  Q_OBJECT
 public:
  explicit HelpContents(QWidget* parent = nullptr);

  void setDialect(core::gcode::Dialect dialect);
  QTextBrowser* browser() const { return browser_; }
  // The page as HTML (thai: UI language is Thai).
  static QString buildHtml(bool thai, core::gcode::Dialect dialect);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void rebuild();
  QTextBrowser* browser_;
  core::gcode::Dialect dialect_ = core::gcode::Dialect::Fanuc;
};

}  // namespace klueng::gui
