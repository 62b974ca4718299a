#pragma once
// Offset Define (SPEC 11-12): 16 rows of X (diameter) Z R T, validated as you
// type, each row's tip number shown as a small picture.
//
// Public API
//   OffsetDefineDialog dlg(offsets, parent);     the table the document holds
//   OffsetDefineDialog dlg(configDir, parent);   reads configDir/offset.cfg
//   dlg.exec() == Accepted -> offsetTable() is the edited table, every cell valid; the
//                             dialog writes no file (issue 30 item 2: File > Save does)
//   offsetTable()           the edited table
//   setCell(row, column, text) / cellText(row, column)   row 0..15, column 0..3 = X Z R T
//   isValid()               every cell valid (OK is disabled otherwise)
//   errorText()             why not, for the first invalid cell
#include <QDialog>
#include <QString>

#include "klueng/core/io/tool_config.h"

class QTableWidget;
class QLabel;
class QDialogButtonBox;

namespace klueng::gui {

class OffsetDefineDialog : public QDialog {
  Q_OBJECT
 public:
  explicit OffsetDefineDialog(const QString& configDir, QWidget* parent = nullptr);
  explicit OffsetDefineDialog(const core::io::OffsetTable& offsets, QWidget* parent = nullptr);

  core::io::OffsetTable offsetTable() const;
  void setCell(int row, int column, const QString& text);
  QString cellText(int row, int column) const;
  bool isValid() const;
  QString errorText() const;

 public slots:
  void accept() override;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void build(const core::io::OffsetTable& table);
  void retranslate();
  void validate();
  QString cellError(int row, int column) const;

  QTableWidget* table_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* intro_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  bool filling_ = false;
};

}  // namespace klueng::gui
