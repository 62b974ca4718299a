#pragma once
// File > Grade a class... (issues 11 and 28): every program in a folder against
// a reference program and/or the teacher's drawing with tolerances (a part file
// or DXF), as `klueng-cli class` grades them (core::job::gradeClass): one row per
// student with pass/fail, errors, alarm, cycle time, the largest leftover and
// gouge on the diameter, and how many of the drawing's dimensions are in
// tolerance; the selected student's dimensions (tolerance, limits, measured,
// in/out) below; double-click a row to open that program; Save CSV and Save PDF
// write what the CLI's --csv and --pdf write.
#include <QDialog>
#include <QFutureWatcher>
#include <vector>

#include "klueng/core/job/class_grading.h"
#include "klueng/core/machine/interpreter.h"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
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
  void setDrawing(const QString& path);
  void setGeneralTolerance(const QString& isoClass);  // "", "f", "m", "c", "v"
  void setTolerance(double mm);
  void grade();  // in the background; finished() when the table is full
  bool isGrading() const { return watcher_.isRunning(); }
  QTableWidget* table() const { return table_; }
  QTableWidget* details() const { return details_; }  // the selected student's dimensions
  QLabel* summary() const { return summary_; }
  const std::vector<core::job::ClassRow>& rows() const { return rows_; }
  // The table as CSV; false with `why` (UI language) when refused or not written, the old file kept.
  bool saveCsv(const QString& path, QString* why = nullptr);
  // The grades as the CLI's --pdf draws them, in the UI language; false with `why` as saveCsv.
  bool savePdf(const QString& path, QString* why = nullptr);

 signals:
  void openProgram(const QString& path);
  void finished();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void showRows();
  void showDetails(int row);
  void retranslate();
  core::machine::MachineSetup setup_;
  core::gcode::Dialect dialect_;
  QFormLayout* form_;
  QLineEdit* folder_;
  QLineEdit* reference_;
  QLineEdit* drawing_;
  QComboBox* general_;
  QDoubleSpinBox* tolerance_;
  QPushButton* browseFolder_;
  QPushButton* browseReference_;
  QPushButton* browseDrawing_;
  QPushButton* gradeButton_;
  QPushButton* saveButton_;
  QPushButton* pdfButton_;
  QLabel* summary_;
  QTableWidget* table_;
  QTableWidget* details_;
  std::vector<core::job::ClassRow> rows_;
  // What the rows were graded against (for the PDF and the columns shown).
  QString gradedReference_, gradedDrawing_;
  QString layer_, layerOf_;  // the DXF layer picked, and for which drawing
  double gradedTolerance_ = 0.05;
  bool noteShown_ = false;  // the summary holds a message, not counts
  QFutureWatcher<std::vector<core::job::ClassRow>> watcher_;
};

}  // namespace klueng::gui
