#pragma once
// Job details (SPEC 2): project, part, material, stock diameter and length
// (each with mm/inch), bore (tube stock, in the diameter's unit; 0 = solid bar),
// programmer, and how the program's lengths without a decimal point are read
// (as its numbers show / whole / least input increments: JobHeader::calculatorInput),
// and the machine the program is written for (JobHeader::machine: the program
// names it at its head, `(MACHINE: romi-gl240m)`; none = the window's machine).
// Diameter and length must be > 0 and the bore less than the diameter: OK
// stays disabled and a line under the form says why.
//
// Public API
//   JobDetailsDialog dlg(header, parent);  if (dlg.exec()) header = dlg.header();
//   header() is the edited core::io::JobHeader (units as chosen)
#include <QDialog>

#include "klueng/core/io/program_file.h"

class QLineEdit;
class QDoubleSpinBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QDialogButtonBox;

namespace klueng::gui {

class JobDetailsDialog : public QDialog {
  Q_OBJECT
 public:
  explicit JobDetailsDialog(const core::io::JobHeader& header, QWidget* parent = nullptr);
  core::io::JobHeader header() const;

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void validate();
  QFormLayout* form_ = nullptr;
  QLineEdit* project_ = nullptr;
  QLineEdit* part_ = nullptr;
  QLineEdit* material_ = nullptr;
  QDoubleSpinBox* diameter_ = nullptr;
  QComboBox* diameterUnit_ = nullptr;
  QDoubleSpinBox* length_ = nullptr;
  QComboBox* lengthUnit_ = nullptr;
  QDoubleSpinBox* bore_ = nullptr;
  QLabel* boreUnit_ = nullptr;
  QLabel* problem_ = nullptr;
  QLineEdit* programmer_ = nullptr;
  QComboBox* decimalPoint_ = nullptr;  // objectName "decimalPoint": unset / whole / increments
  QComboBox* toolSide_ = nullptr;      // objectName "toolSide": unset / in front / beyond the centre line
  QComboBox* machine_ = nullptr;       // objectName "machine": none named / each loaded machine (its id as data)
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace klueng::gui
