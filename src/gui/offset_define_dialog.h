#pragma once
// Offset Define (SPEC 11-12): 16 rows of X (diameter) Z R T, validated as you
// type, each row's tip number shown as a small picture.
//
// Public API
//   OffsetDefineDialog dlg(configDir, parent);   reads configDir/offset.cfg
//   dlg.exec() == Accepted -> offset.cfg written (to savedConfigDir(): configDir, or the
//                             per-user copy when configDir is read-only)
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

  core::io::OffsetTable offsetTable() const;
  QString savedConfigDir() const { return savedDir_; }
  void setCell(int row, int column, const QString& text);
  QString cellText(int row, int column) const;
  bool isValid() const;
  QString errorText() const;

 public slots:
  void accept() override;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void validate();
  QString cellError(int row, int column) const;

  QString configDir_;
  QString savedDir_;
  QTableWidget* table_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* intro_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
  bool filling_ = false;
};

}  // namespace klueng::gui
