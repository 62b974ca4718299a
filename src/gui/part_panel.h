#pragma once
// The Part dock (issue 10, items 2-4): the finished part's features (the
// dimensions panel: a click marks the feature on the output screen), the part
// check (gouges red, leftovers yellow, a click goes to the block that made it)
// and the compensation comparison (the part without G41/G42 or with a sharp
// nose, outlined over the section, each difference measured and put on its
// block). Everything is the core's (cut::partFeatures, checkPart,
// compareCompensation); the panel only runs them and lists what they say.
#include <QDockWidget>
#include <functional>
#include <string>

#include "gui/part_overlay.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/machine/interpreter.h"
#include "klueng/core/units.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace klueng::gui {

class PartPanel : public QDockWidget {
  Q_OBJECT
 public:
  struct Source {
    core::io::ProgramFile program;
    core::machine::MachineSetup setup;
    core::machine::RunOptions run;
    std::string folder;  // subprogram files
  };
  PartPanel(QWidget* parent, std::function<Source()> source);

  // Runs the program and lists its part; `compare` 0 = no comparison,
  // 1 = without G41/G42, 2 = sharp nose (R 0).
  void analyse();
  void setComparison(int compare);
  // The unit features and findings are written in (View ▸ Units shown): a list on
  // screen is said again in the new unit.
  void setUnits(const core::UnitFormat& units);
  // The program or its setup changed: what is listed no longer holds (cleared, and the marks with it).
  void invalidate();
  QTreeWidget* list() const { return list_; }
  QPushButton* measureButton() const { return measure_; }
  QLabel* summary() const { return summary_; }
  void retranslateUi();

 signals:
  void overlayChanged(const klueng::gui::PartOverlay& overlay);
  void lineActivated(int line);
  void measuringToggled(bool on);  // the Measure button: clicks on the output screen measure

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void select(QTreeWidgetItem* item);

  std::function<Source()> source_;
  QPushButton* check_ = nullptr;
  QPushButton* measure_ = nullptr;
  QComboBox* compare_ = nullptr;
  QLabel* summary_ = nullptr;
  QTreeWidget* list_ = nullptr;
  QTreeWidgetItem* features_ = nullptr;
  QTreeWidgetItem* defects_ = nullptr;
  QTreeWidgetItem* differences_ = nullptr;
  PartOverlay base_;                       // defects and the comparison's outline; a selection adds its highlight
  std::function<QString()> summaryMaker_;  // the summary line in the current language
  core::UnitFormat units_;
};

}  // namespace klueng::gui
