#pragma once
// Explain (issue 11): one line under the editor that says, in the UI language,
// what the block at the green arrow does — "G01 X30. Z-20. F0.2: cut in a
// straight line to Ø30 at Z-20, 0.2 mm per revolution; at 180 m/min (G96) the
// spindle turns 1910 rpm here" — while a run is paused, stepping or ended; the
// editor's hover help adds the same for the line under the mouse. The words come
// from core::machine::explainBlock (the GUI only picks the block and the state).
// A second line gives the block's cutting data (issue 39: Vc, f, ap, Rz/Ra, power,
// core::cut::measureCuts, computed once a run on a worker thread) and its first
// cutting-data warning.
#include <QFutureWatcher>
#include <QLabel>
#include <QString>
#include <memory>

#include "klueng/core/cut/cutting_data.h"

namespace klueng::gui {

class CodeEditor;
class RunController;

class ExplainBar : public QLabel {
  Q_OBJECT
 public:
  ExplainBar(RunController* runner, CodeEditor* editor, QWidget* parent = nullptr);
  // What the block on fileLine (of the program in the editor) does: with the
  // state it left the last time it ran, else from its words alone.
  QString explainLine(int fileLine) const;
  // The cutting-data line of a block (empty when it cuts nothing or the data is not ready).
  QString cuttingDataLine(int fileLine) const;
  // The run's cutting data (nullptr until computed for the run's timeline; never for a run of
  // more than kCuttingDataMoveLimit moves).
  static constexpr std::size_t kCuttingDataMoveLimit = 250000;
  const core::cut::CuttingData* cuttingData() const { return data_.get(); }
  // The drawing's roughness marks the finishing feeds are judged by (W332): the next run's.
  void setFinishMarks(std::vector<core::cut::FinishMark> marks) { finishMarks_ = std::move(marks); }

 signals:
  // The run's cutting data is measured (the plot under the output view draws it).
  void cuttingDataReady(std::shared_ptr<const klueng::core::cut::CuttingData> data, double cycleTime,
                        double spindlePowerKw, bool inch);

 public slots:
  void refresh();  // the arrow moved, the run state or the language changed

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void measureRun();  // starts the cutting data of the run's timeline on a worker thread

  RunController* runner_;
  CodeEditor* editor_;
  std::shared_ptr<const core::cut::CuttingData> data_;
  core::DisplayUnits dataUnits_ = core::DisplayUnits::Mm;
  std::vector<core::cut::FinishMark> finishMarks_;
  std::weak_ptr<const core::machine::Timeline> dataFor_;  // the timeline data_ (or the one computing) is of
  QFutureWatcher<std::shared_ptr<const core::cut::CuttingData>> watcher_;
};

}  // namespace klueng::gui
