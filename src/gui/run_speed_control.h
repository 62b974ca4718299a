#pragma once
// The animation speed control (SPEC 10 ext): a slider from slow motion through
// 1x real machine time to "as fast as possible", with its value as text.
//
// Public API (F1 puts it on the Run toolbar)
//   RunSpeedControl speed(parent); speed.setRunController(&controller);
//   setSpeed(factor) / speed()   factor as RunController::setSpeed (0 = as fast as possible)
//   signal speedChanged(double factor)
//   static steps()               the slider's stops: 0.1 0.25 0.5 1 2 5 10 25 100, fastest
#include <QWidget>
#include <vector>

class QLabel;
class QSlider;

namespace klueng::gui {

class RunController;

class RunSpeedControl : public QWidget {
  Q_OBJECT
 public:
  explicit RunSpeedControl(QWidget* parent = nullptr);
  void setRunController(RunController* controller);
  double speed() const;
  void setSpeed(double factor);
  static const std::vector<double>& steps();

 signals:
  void speedChanged(double factor);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  QLabel* caption_ = nullptr;
  QSlider* slider_ = nullptr;
  QLabel* value_ = nullptr;
};

}  // namespace klueng::gui
