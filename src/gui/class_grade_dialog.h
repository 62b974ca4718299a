#pragma once
// File > Grade a class... (issue 11): every program in a folder against a
// reference program, as `klueng-cli class` grades them (core::cut::gradeClass):
// one row per student with pass/fail, errors, alarm, cycle time and the largest
// leftover and gouge on the diameter; double-click a row to open that program;
// Save CSV writes the same table the CLI writes.
#include <QDialog>
#include <QFutureWatcher>
#include <vector>

#include "klueng/core/cut/class_grading.h"
#include "klueng/core/machine/interpreter.h"

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTableWidget;

namespace klueng::gui {

class ClassGradeDialog : public QDialog {
  Q_OBJECT
 public:
  ClassGradeDialog(const core::machine::MachineSetup& setup, core::gcode::Dialect dialect, const QString& reference,
                   QWidget* parent = nullptr);

  void setFolder(const QString& folder);
  void setReference(const QString& path);
  void setTolerance(double mm);
  void grade();        // in the background; finished() when the table is full
  bool isGrading() const { return watcher_.isRunning(); }
  QTableWidget* table() const { return table_; }
  const std::vector<core::cut::ClassRow>& rows() const { return rows_; }
  // The table as CSV; false with `why` (UI language) when refused or not written, the old file kept.
  bool saveCsv(const QString& path, QString* why = nullptr);

 signals:
  void openProgram(const QString& path);
  void finished();

 private:
  void showRows();
  void retranslate();
  core::machine::MachineSetup setup_;
  core::gcode::Dialect dialect_;
  QLineEdit* folder_;
  QLineEdit* reference_;
  QDoubleSpinBox* tolerance_;
  QPushButton* gradeButton_;
  QPushButton* saveButton_;
  QLabel* summary_;
  QTableWidget* table_;
  std::vector<core::cut::ClassRow> rows_;
  QFutureWatcher<std::vector<core::cut::ClassRow>> watcher_;
};

}  // namespace klueng::gui
