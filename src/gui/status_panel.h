#pragma once
// The status bar fields and the five status lamps (SPEC 12).
//
// Public API (F1 adds both to the main window's status bar / a dock)
//   StatusFields  tool X (diameter), tool Z, feed, spindle speed, X offset, Z offset,
//                 nose radius, tip number, tool number, machine time (elapsed / cycle time),
//                 today's date (Buddhist era in Thai).
//                 setStatus(RunStatus) — connect RunController::statusChanged.
//                 fieldText(Field) for tests.
//   StatusLamp    one small painted lamp with a label; setOn(bool), setColor(QColor).
//   StatusLamps   spindle direction (CW green / CCW amber / off), optional stop, coolant,
//                 position check, brake. setStatus(RunStatus); lamp(Lamp) for tests.
// Both retranslate on QEvent::LanguageChange.
#include <QColor>
#include <QDate>
#include <QLabel>
#include <QWidget>
#include <array>

#include "gui/run_controller.h"
#include "klueng/core/units.h"

namespace klueng::gui {

class StatusFields : public QWidget {
  Q_OBJECT
 public:
  enum class Field { ToolX, ToolZ, Feed, Spindle, OffsetX, OffsetZ, NoseRadius, Tip, Tool, Time, Date, Count };
  explicit StatusFields(QWidget* parent = nullptr);
  QString fieldText(Field f) const;  // the value part, e.g. "45.000"
  // Today's date as shown ("22 พฤศจิกายน พ.ศ. 2569" / "November 22, 2026").
  static QString formatDate(const QDate& date, bool thai);
  // The same, short, as the status bar shows it ("26 พ.ย. 2569" / "Nov 26, 2026").
  static QString formatShortDate(const QDate& date, bool thai);
  // A machine time as a clock: "0:07.5", "12:34.0" (minutes:seconds).
  static QString formatClock(double seconds);
  // The unit positions, offsets and the feed are shown in (View ▸ Units shown; issue 28 item 4).
  void setUnits(const core::UnitFormat& units);
  const core::UnitFormat& units() const { return units_; }

 public slots:
  void setStatus(const klueng::gui::RunStatus& status);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  static constexpr int kCount = static_cast<int>(Field::Count);
  std::array<QLabel*, kCount> names_{};
  std::array<QLabel*, kCount> values_{};
  RunStatus status_;
  core::UnitFormat units_;
};

class StatusLamp : public QWidget {
  Q_OBJECT
 public:
  explicit StatusLamp(QWidget* parent = nullptr);
  void setOn(bool on);
  bool isOn() const { return on_; }
  void setColor(const QColor& c);
  QColor color() const { return color_; }
  void setText(const QString& text);
  QString text() const { return text_; }
  QSize sizeHint() const override;
  QSize minimumSizeHint() const override { return sizeHint(); }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  bool on_ = false;
  QColor color_{40, 200, 60};
  QString text_;
};

class StatusLamps : public QWidget {
  Q_OBJECT
 public:
  enum class Lamp { Spindle, OptionalStop, Coolant, PositionCheck, Brake, Count };
  explicit StatusLamps(QWidget* parent = nullptr);
  StatusLamp* lamp(Lamp l) const { return lamps_[static_cast<int>(l)]; }

 public slots:
  void setStatus(const klueng::gui::RunStatus& status);
  // The Optional Stop switch is shown even before a run.
  void setOptionalStopSwitch(bool on);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  std::array<StatusLamp*, static_cast<int>(Lamp::Count)> lamps_{};
  core::machine::SpindleDir spindle_ = core::machine::SpindleDir::Stopped;
};

}  // namespace klueng::gui
