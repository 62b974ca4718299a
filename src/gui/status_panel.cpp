#include "gui/status_panel.h"

#include "gui/language.h"
#include "render/report_sheets.h"

#include <cmath>

#include <QEvent>
#include <QHBoxLayout>
#include <QLocale>
#include <QPainter>
#include <QRadialGradient>
#include <QStringList>

namespace klueng::gui {

namespace {

QString number(double v, int decimals = 3) { return QString::number(v, 'f', decimals); }

bool uiIsThai() { return Language::coreLang() == core::Lang::Th; }

}  // namespace

// ---------------------------------------------------------------- StatusFields

StatusFields::StatusFields(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(2, 0, 2, 0);
  layout->setSpacing(3);
  for (int i = 0; i < kCount; ++i) {
    names_[i] = new QLabel(this);
    values_[i] = new QLabel(this);
    values_[i]->setFrameShape(QFrame::StyledPanel);
    values_[i]->setFrameShadow(QFrame::Sunken);
    values_[i]->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    values_[i]->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(names_[i]);
    layout->addWidget(values_[i]);
    if (i + 1 < kCount) layout->addSpacing(2);
  }
  // Wide enough for "-999.999" (inches: "-99.9999", as wide) so the bar does not
  // jump while the tool moves on a lathe's travel (a larger number widens its
  // field; at 1366 px the Thai bar has no room for four fields of "-9999.999").
  const int wide = values_[0]->fontMetrics().horizontalAdvance(QStringLiteral("-999.999")) + 8;
  for (Field f : {Field::ToolX, Field::ToolZ, Field::OffsetX, Field::OffsetZ})
    values_[static_cast<int>(f)]->setMinimumWidth(wide);
  retranslate();
  setStatus(RunStatus{});
}

QString StatusFields::formatShortDate(const QDate& date, bool thai) {
  return render::reportDate(date, thai ? render::ReportLanguage::Thai : render::ReportLanguage::English,
                            render::DateLength::Short);
}

QString StatusFields::formatDate(const QDate& date, bool thai) {
  return render::reportDate(date, thai ? render::ReportLanguage::Thai : render::ReportLanguage::English);
}

QString StatusFields::formatClock(double seconds) {
  const double tenths = std::round(std::max(0.0, seconds) * 10.0);
  const auto minutes = static_cast<long long>(tenths / 600.0);
  const double rest = (tenths - 600.0 * static_cast<double>(minutes)) / 10.0;
  return QStringLiteral("%1:%2").arg(minutes).arg(rest, 4, 'f', 1, QLatin1Char('0'));
}

QString StatusFields::fieldText(Field f) const { return values_[static_cast<int>(f)]->text(); }

void StatusFields::setStatus(const RunStatus& s) {
  status_ = s;
  const auto& m = s.machine;
  auto set = [this](Field f, const QString& text) { values_[static_cast<int>(f)]->setText(text); };
  // Lengths through the one display conversion (core/units.h): 3 decimals in mm, 4 in inches.
  const core::UnitFormat& u = units_;
  const auto length = [&u](double mm) { return QString::fromStdString(u.position(mm)); };
  set(Field::ToolX, length(core::diameterOf(s.position)));
  set(Field::ToolZ, length(core::zOf(s.position)));
  const bool perRev = s.feedMode == core::machine::FeedMode::PerRev;
  const QString feed = QString::fromStdString(u.feed(s.programmedFeed, perRev));
  set(Field::Feed, s.programmedFeed <= 0 ? QStringLiteral("-")
                   : u.inch()            ? (perRev ? tr("%1 in/rev").arg(feed) : tr("%1 in/min").arg(feed))
                                         : (perRev ? tr("%1 mm/rev").arg(feed) : tr("%1 mm/min").arg(feed)));
  // FEED HOLD: the axes stand (the spindle field keeps its rpm).
  if (s.feedHold) set(Field::Feed, tr("FEED HOLD"));
  set(Field::Spindle, tr("%1 rpm").arg(number(s.rpm, 0)));
  set(Field::OffsetX, length(m.offsetX));
  set(Field::OffsetZ, length(m.offsetZ));
  set(Field::NoseRadius, length(m.noseRadius));
  set(Field::Tip, QString::number(m.tip));
  set(Field::Tool,
      m.tool > 0 ? QStringLiteral("T%1%2").arg(m.tool, 2, 10, QLatin1Char('0')).arg(m.offset, 2, 10, QLatin1Char('0'))
                 : QStringLiteral("-"));
  set(Field::Time, s.cycleTime > 0.0 ? QStringLiteral("%1 / %2").arg(formatClock(s.time), formatClock(s.cycleTime))
                                     : QStringLiteral("-"));
  // The cycle time per tool on hover.
  QStringList perTool{tr("Machine time: elapsed / cycle time of the whole program (min:s)")};
  for (const core::machine::ToolTime& t : s.toolTimes)
    if (t.tool > 0) perTool << tr("T%1: %2").arg(t.tool, 2, 10, QLatin1Char('0')).arg(formatClock(t.seconds));
  values_[static_cast<int>(Field::Time)]->setToolTip(perTool.join(QLatin1Char('\n')));
  // Short in the bar (a Thai status bar must fit 1366 pixels), in full on hover.
  set(Field::Date, formatShortDate(QDate::currentDate(), uiIsThai()));
  values_[static_cast<int>(Field::Date)]->setToolTip(formatDate(QDate::currentDate(), uiIsThai()));
}

void StatusFields::setUnits(const core::UnitFormat& units) {
  if (units_ == units) return;
  units_ = units;
  retranslate();  // the tips name the unit; the values are shown again in it
}

void StatusFields::retranslate() {
  const QString names[kCount] = {tr("Tool X"), tr("Tool Z"), tr("Feed"), tr("Spindle"), tr("X offset"), tr("Z offset"),
                                 tr("Nose R"), tr("Tip"),    tr("Tool"), tr("Time"),    tr("Date")};
  const bool in = units_.inch();
  const QString tips[kCount] = {
      in ? tr("Tool position X (diameter, inches)") : tr("Tool position X (diameter, mm)"),
      in ? tr("Tool position Z (inches)") : tr("Tool position Z (mm)"),
      tr("Feed rate as programmed"),
      tr("Spindle speed (rpm)"),
      in ? tr("X offset of the active tool offset (diameter, inches)")
         : tr("X offset of the active tool offset (diameter, mm)"),
      in ? tr("Z offset of the active tool offset (inches)") : tr("Z offset of the active tool offset (mm)"),
      in ? tr("Nose radius of the active offset (inches)") : tr("Nose radius of the active offset (mm)"),
      tr("Imaginary tool tip number of the active offset"),
      tr("Tool number and offset number"),
      tr("Machine time: elapsed / cycle time of the whole program (min:s)"),
      tr("Today's date")};
  for (int i = 0; i < kCount; ++i) {
    names_[i]->setText(names[i]);
    names_[i]->setToolTip(tips[i]);
    values_[i]->setToolTip(tips[i]);
  }
  setStatus(status_);
}

void StatusFields::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

// ---------------------------------------------------------------- StatusLamp

StatusLamp::StatusLamp(QWidget* parent) : QWidget(parent) { setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed); }

void StatusLamp::setOn(bool on) {
  if (on_ == on) return;
  on_ = on;
  update();
}

void StatusLamp::setColor(const QColor& c) {
  if (color_ == c) return;
  color_ = c;
  update();
}

void StatusLamp::setText(const QString& text) {
  text_ = text;
  updateGeometry();
  update();
}

QSize StatusLamp::sizeHint() const {
  const QFontMetrics fm = fontMetrics();
  const int h = std::max(fm.height(), 14) + 2;
  return {h + 4 + fm.horizontalAdvance(text_) + 4, h};
}

void StatusLamp::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setRenderHint(QPainter::Antialiasing);
  const int d = std::min(height(), 16) - 2;
  const QRectF lampRect(2, (height() - d) / 2.0, d, d);
  const QColor base = on_ ? color_ : QColor(110, 110, 110);
  QRadialGradient g(lampRect.center() - QPointF(d * 0.2, d * 0.2), d * 0.7);
  g.setColorAt(0.0, on_ ? base.lighter(170) : QColor(170, 170, 170));
  g.setColorAt(1.0, on_ ? base : base.darker(130));
  p.setBrush(g);
  p.setPen(QPen(QColor(40, 40, 40), 1.0));
  p.drawEllipse(lampRect);
  p.setPen(palette().color(QPalette::WindowText));
  p.drawText(QRectF(lampRect.right() + 5, 0, width() - lampRect.right() - 5, height()),
             Qt::AlignVCenter | Qt::AlignLeft, text_);
}

// ---------------------------------------------------------------- StatusLamps

StatusLamps::StatusLamps(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(2, 0, 2, 0);
  layout->setSpacing(10);
  for (auto*& lamp : lamps_) {
    lamp = new StatusLamp(this);
    layout->addWidget(lamp);
  }
  lamp(Lamp::OptionalStop)->setColor(QColor(240, 180, 0));
  lamp(Lamp::Coolant)->setColor(QColor(30, 140, 240));
  lamp(Lamp::PositionCheck)->setColor(QColor(40, 200, 60));
  lamp(Lamp::Brake)->setColor(QColor(220, 40, 40));
  retranslate();
}

void StatusLamps::setStatus(const RunStatus& s) {
  const auto& m = s.machine;
  if (spindle_ != m.spindle) {
    spindle_ = m.spindle;
    retranslate();
  }
  lamp(Lamp::Spindle)->setOn(m.spindle != core::machine::SpindleDir::Stopped);
  lamp(Lamp::Spindle)
      ->setColor(m.spindle == core::machine::SpindleDir::Ccw ? QColor(240, 140, 0) : QColor(40, 200, 60));
  lamp(Lamp::OptionalStop)->setOn(m.optionalStopSwitch);
  lamp(Lamp::Coolant)->setOn(m.coolant);
  lamp(Lamp::PositionCheck)->setOn(m.positionCheck);
  lamp(Lamp::Brake)->setOn(m.brake);
}

void StatusLamps::setOptionalStopSwitch(bool on) { lamp(Lamp::OptionalStop)->setOn(on); }

void StatusLamps::retranslate() {
  using core::machine::SpindleDir;
  lamp(Lamp::Spindle)
      ->setText(spindle_ == SpindleDir::Cw    ? tr("Spindle CW")
                : spindle_ == SpindleDir::Ccw ? tr("Spindle CCW")
                                              : tr("Spindle stop"));
  lamp(Lamp::Spindle)
      ->setToolTip(tr("Spindle direction: green clockwise (M03), amber counter-clockwise (M04), grey stopped (M05)"));
  lamp(Lamp::OptionalStop)->setText(tr("Optional stop"));
  lamp(Lamp::OptionalStop)->setToolTip(tr("Optional Stop switch: M01 stops the program when lit"));
  lamp(Lamp::Coolant)->setText(tr("Coolant"));
  lamp(Lamp::Coolant)->setToolTip(tr("Coolant on (M08) / off (M09)"));
  lamp(Lamp::PositionCheck)->setText(tr("Position check"));
  lamp(Lamp::PositionCheck)->setToolTip(tr("Lit when G27 found the tool at the reference point"));
  lamp(Lamp::Brake)->setText(tr("Brake"));
  lamp(Lamp::Brake)->setToolTip(tr("Spindle brake on (M86) / off (M87)"));
}

void StatusLamps::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QWidget::changeEvent(event);
}

}  // namespace klueng::gui
