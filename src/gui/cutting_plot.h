#pragma once
// The run's spindle power and cutting speed over the cycle time (issue 39 item 4), under the
// output view: power in kW (blue, the machine's spindle_power_kw as a red line when known),
// Vc in m/min (ft/min under G20, green, its own scale), and the run's time as a cursor.
// It draws the cutting data the explain bar measured (core::cut::measureCuts); hidden until then.
#include <QWidget>
#include <memory>

#include "klueng/core/cut/cutting_data.h"

namespace klueng::gui {

class RunController;

class CuttingPlot : public QWidget {
  Q_OBJECT
 public:
  CuttingPlot(RunController* runner, QWidget* parent = nullptr);
  // The run's cutting data (nullptr: none yet, the plot hides); the spindle's power, 0 = not known.
  void setData(std::shared_ptr<const core::cut::CuttingData> data, double cycleTime, double spindlePowerKw, bool inch);
  QSize sizeHint() const override { return {400, 72}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  RunController* runner_;
  std::shared_ptr<const core::cut::CuttingData> data_;
  double cycleTime_ = 0.0;
  double spindlePowerKw_ = 0.0;
  bool inch_ = false;
};

}  // namespace klueng::gui
