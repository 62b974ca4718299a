#pragma once
// File > Part designer... (issue 14): a turned part drawn as a table of
// features — outside cylinders, tapers, arcs with their chamfers and rounds,
// bore steps, grooves, threads — with the bar and material from Job details.
// Every change (undoable) generates the program in the chosen dialect, runs
// and cuts it with the machine's tools in the background and shows the cut
// part against the drawing (2-D and 3-D) with the verdict: "the cut part
// matches the drawing within 0.01 mm", or why it cannot be turned, or where it
// differs. Open and save part files (JSON), import DXF half sections; Create
// program puts the program in the editor as a new file.
#include <QDialog>
#include <QFutureWatcher>
#include <memory>

#include "klueng/core/design/design_loop.h"
#include "klueng/core/io/program_file.h"

class QCheckBox;
class QComboBox;
class QHBoxLayout;
class QLabel;
class QListWidget;
class QPushButton;
class QSplitter;
class QTabWidget;
class QTableView;
class QTimer;
class QToolButton;
class QUndoStack;

namespace klueng::gui {

class DesignPreview;
class DesignTableModel;
class Part3DWidget;

class PartDesignerDialog : public QDialog {
  Q_OBJECT
 public:
  PartDesignerDialog(const core::machine::MachineSetup& setup, core::gcode::Dialect dialect,
                     const core::io::JobHeader& job, QWidget* parent = nullptr);
  ~PartDesignerDialog() override;

  // The tools, offsets and machine the program is cut with (the window's, when they change).
  void setMachineSetup(const core::machine::MachineSetup& setup);
  // The bar and the material come from Job details.
  void setJobHeader(const core::io::JobHeader& job);
  // A new design through the undo stack (its bar is replaced by the job's).
  void setDesign(const core::design::PartDesign& design, const QString& what);
  const core::design::PartDesign& design() const;
  // JSON part file or DXF drawing; false (with the reasons listed) when it cannot be read.
  bool openFile(const QString& path, const QString& layer = {});
  bool saveFile(const QString& path);

  DesignTableModel* model() const { return model_; }
  QTableView* table() const { return table_; }
  QListWidget* findings() const { return findings_; }
  QUndoStack* undoStack() const { return undo_; }
  bool isRunning() const;  // a change waiting to run, or running
  const core::design::DesignLoop* lastLoop() const { return loop_.get(); }
  QString verdict() const;
  void setDialect(core::gcode::Dialect dialect);
  core::gcode::Dialect dialect() const;

 signals:
  void programReady(const QString& fileText);
  void jobDetailsRequested();
  void useStock(double diameter, double length, double bore);  // the opened file's bar, for Job details
  void loopFinished();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void buildUi();  // its steps:
  void addRowButtons(QHBoxLayout* top);
  void addChoices(QHBoxLayout* top);
  QHBoxLayout* buildBarLine();
  QSplitter* buildTableAndViews();
  QHBoxLayout* buildFindingsAndButtons();
  void retranslate();
  void apply(const core::design::PartDesign& design);  // the undo stack's commands land here
  void scheduleLoop();
  void startLoop();
  void showLoop();
  void addRow(int kind);
  void removeRow();
  void moveRow(int by);
  void openDialog();
  void saveDialog();
  void updateSelection();
  core::design::GenerateOptions options() const;

  core::machine::MachineSetup setup_;
  core::io::JobHeader job_;
  std::vector<core::design::CuttingSpeed> speeds_;
  DesignTableModel* model_;
  QUndoStack* undo_;
  QTableView* table_ = nullptr;
  DesignPreview* preview_ = nullptr;
  Part3DWidget* view3d_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  QListWidget* findings_ = nullptr;
  QLabel* barLabel_ = nullptr;
  QLabel* fileBar_ = nullptr;
  QPushButton* useFileBar_ = nullptr;
  QPushButton* jobButton_ = nullptr;
  QPushButton* createButton_ = nullptr;
  QComboBox* dialect_ = nullptr;
  QComboBox* material_ = nullptr;
  QComboBox* toolMaterial_ = nullptr;
  QCheckBox* partOff_ = nullptr;
  QLabel* dialectLabel_ = nullptr;
  QLabel* materialLabel_ = nullptr;
  QLabel* toolMaterialLabel_ = nullptr;
  QToolButton* addButton_ = nullptr;
  QToolButton* removeButton_ = nullptr;
  QToolButton* upButton_ = nullptr;
  QToolButton* downButton_ = nullptr;
  QToolButton* undoButton_ = nullptr;
  QToolButton* redoButton_ = nullptr;
  QToolButton* openButton_ = nullptr;
  QToolButton* saveButton_ = nullptr;
  QTimer* debounce_ = nullptr;
  bool pending_ = false;
  bool running_ = false;  // from starting a run until its result is shown (the future ends before that)
  std::shared_ptr<const core::design::DesignLoop> loop_;
  std::shared_ptr<const core::cut::Stock> cut_;
  QFutureWatcher<std::shared_ptr<const core::design::DesignLoop>> watcher_;
  double fileStock_[3] = {0.0, 0.0, 0.0};  // the opened file's bar: Ø, length, hole
};

}  // namespace klueng::gui
