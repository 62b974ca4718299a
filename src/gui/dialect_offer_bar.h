#pragma once
// A thin bar above the editor that offers, in one click, the dialect that
// accepts a program the current dialect refuses ("13 blocks are Haas forms").
#include <QWidget>

#include "klueng/core/gcode/machine_profile.h"

class QLabel;
class QPushButton;

namespace klueng::gui {

class DialectOfferBar : public QWidget {
  Q_OBJECT
 public:
  explicit DialectOfferBar(QWidget* parent = nullptr);

  // Shows the offer (blocks = how many blocks the other dialect accepts);
  // a dismissed offer stays hidden for the same dialect until clear().
  void offer(core::gcode::Dialect dialect, int blocks);
  // No offer (the program checks clean, or nothing fits better).
  void clear();
  bool isOffering() const { return isVisible(); }
  QString text() const;

 signals:
  void switchRequested(core::gcode::Dialect dialect);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QLabel* label_ = nullptr;
  QPushButton* switchButton_ = nullptr;
  core::gcode::Dialect dialect_ = core::gcode::Dialect::Fanuc;
  int blocks_ = 0;
  bool dismissed_ = false;
};

}  // namespace klueng::gui
