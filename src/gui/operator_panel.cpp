#include "gui/operator_panel.h"

#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDial>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPlainTextEdit>
#include <QScrollArea>
#include <QScrollBar>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "gui/language.h"
#include "gui/operator_touch_view.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/job/class_grading.h"
#include "klueng/core/job/job.h"
#include "klueng/core/messages.h"
#include "render/lathe_painters.h"
#include "render/tool_sprite.h"

namespace klueng::gui {

namespace ctl = core::control;

namespace {

QString panelMm(double v) { return QString::number(std::abs(v) < 0.0005 ? 0.0 : v, 'f', 3); }

QString panelMinSec(double s) {
  if (!std::isfinite(s)) return QStringLiteral("∞");
  const int m = static_cast<int>(s / 60.0);
  return QStringLiteral("%1:%2").arg(m).arg(s - m * 60.0, 4, 'f', 1, QLatin1Char('0'));
}

QToolButton* panelKey(const QString& objectName, bool checkable = false) {
  auto* b = new QToolButton;
  b->setObjectName(objectName);
  b->setCheckable(checkable);
  b->setToolButtonStyle(Qt::ToolButtonTextOnly);
  b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  return b;
}

bool panelSameOffsets(const core::io::OffsetTable& a, const core::io::OffsetTable& b) {
  for (int n = 1; n <= core::io::kOffsetCount; ++n) {
    const auto &p = a.at(n), &q = b.at(n);
    if (p.x != q.x || p.z != q.z || p.r != q.r || p.tip != q.tip) return false;
  }
  return true;
}

}  // namespace

OperatorPanel::OperatorPanel(QWidget* parent, std::function<Source()> source)
    : QDockWidget(parent), source_(std::move(source)) {
  setObjectName(QStringLiteral("operatorPanelDock"));
  build();
  retranslateUi();
}

OperatorPanel::~OperatorPanel() = default;

void OperatorPanel::build() {
  auto* body = new QWidget;
  auto* v = new QVBoxLayout(body);
  v->setContentsMargins(4, 4, 4, 4);
  v->setSpacing(4);

  auto* top = new QHBoxLayout;
  title_ = new QLabel;
  title_->setObjectName(QStringLiteral("operatorTitle"));
  QFont bold = title_->font();
  bold.setBold(true);
  title_->setFont(bold);
  powerOn_ = panelKey(QStringLiteral("operatorPowerOn"));
  powerOn_->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
  zoom_ = panelKey(QStringLiteral("operatorZoom"));
  zoom_->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
  top->addWidget(title_, 1);
  top->addWidget(zoom_);
  top->addWidget(powerOn_);
  v->addLayout(top);

  view_ = new TouchView(body);
  v->addWidget(view_, 1);

  // The position page: X as a diameter, as the control shows it.
  auto* pos = new QGridLayout;
  pos->setHorizontalSpacing(6);
  pos->setVerticalSpacing(0);
  const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  for (int c = 0; c < 4; ++c) {
    posHeads_[c] = new QLabel;
    QFont f = posHeads_[c]->font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    posHeads_[c]->setFont(f);
    posHeads_[c]->setAlignment(Qt::AlignRight);
    pos->addWidget(posHeads_[c], 0, c + 1);
  }
  const char* axes[2] = {"X", "Z"};
  for (int r = 0; r < 2; ++r) {
    pos->addWidget(new QLabel(QString::fromLatin1(axes[r])), r + 1, 0);
    for (int c = 0; c < 4; ++c) {
      pos_[r][c] = new QLabel;
      pos_[r][c]->setFont(mono);
      pos_[r][c]->setAlignment(Qt::AlignRight);
      pos_[r][c]->setObjectName(QStringLiteral("operatorPos%1%2").arg(QString::fromLatin1(axes[r])).arg(c));
      pos->addWidget(pos_[r][c], r + 1, c + 1);
    }
  }
  v->addLayout(pos);
  state_ = new QLabel;
  state_->setObjectName(QStringLiteral("operatorState"));
  state_->setFont(mono);
  v->addWidget(state_);
  message_ = new QLabel;
  message_->setObjectName(QStringLiteral("operatorMessage"));
  message_->setWordWrap(true);
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // Room for a three-line message kept (an alarm in words, or a message and the note under it):
  // the keys below do not jump under the mouse when one appears. Measured on three bold Thai
  // lines: a Thai line (its fallback font, vowels above and below) is taller than a Latin one.
  {
    // Ko kai with mai tho above and sara am: a tall Thai cluster (a probe, never shown).
    const QString line = QStringLiteral(u"\u0E01\u0E49\u0E33 Xg");
    QLabel probe(line + u'\n' + line + u'\n' + line);
    QFont bold = message_->font();
    bold.setBold(true);
    probe.setFont(bold);
    message_->setMinimumHeight(probe.sizeHint().height());
  }
  message_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  v->addWidget(message_);

  tabs_ = new QTabWidget;
  tabs_->setObjectName(QStringLiteral("operatorTabs"));
  v->addWidget(tabs_);

  // ---- the machine's keys
  auto* keys = new QWidget;
  auto* g = new QGridLayout(keys);
  g->setContentsMargins(2, 2, 2, 2);
  g->setSpacing(2);
  modes_ = new QButtonGroup(this);
  const char* modeNames[6] = {"operatorModeEdit", "operatorModeMem",    "operatorModeMdi",
                              "operatorModeJog",  "operatorModeHandle", "operatorModeZrn"};
  for (int i = 0; i < 6; ++i) {
    QToolButton* b = panelKey(QString::fromLatin1(modeNames[i]), true);
    modes_->addButton(b, i);
    g->addWidget(b, i / 3, (i % 3) * 2, 1, 2);
  }
  int row = 2;
  const char* jogNames[4] = {"operatorJogMinusX", "operatorJogPlusX", "operatorJogMinusZ", "operatorJogPlusZ"};
  for (int i = 0; i < 4; ++i) {
    jogKeys_[i] = panelKey(QString::fromLatin1(jogNames[i]));
    jogKeys_[i]->setAutoRepeat(true);
    jogKeys_[i]->setAutoRepeatDelay(250);
    jogKeys_[i]->setAutoRepeatInterval(100);
    g->addWidget(jogKeys_[i], row, i);
    const ctl::Axis axis = i < 2 ? ctl::Axis::X : ctl::Axis::Z;
    const int dir = i % 2 == 0 ? -1 : 1;
    connect(jogKeys_[i], &QToolButton::clicked, this, [this, axis, dir] { pressJog(axis, dir); });
  }
  rapid_ = panelKey(QStringLiteral("operatorRapid"), true);
  g->addWidget(rapid_, row, 4, 1, 2);
  ++row;
  handleAxis_ = new QButtonGroup(this);
  handleStep_ = new QButtonGroup(this);
  QToolButton* hx = panelKey(QStringLiteral("operatorHandleX"), true);
  QToolButton* hz = panelKey(QStringLiteral("operatorHandleZ"), true);
  hx->setText(QStringLiteral("X"));
  hz->setText(QStringLiteral("Z"));
  hz->setChecked(true);
  handleAxis_->addButton(hx, 0);
  handleAxis_->addButton(hz, 1);
  g->addWidget(hx, row, 0);
  g->addWidget(hz, row, 1);
  for (int i = 0; i < 3; ++i) {
    QToolButton* b = panelKey(QStringLiteral("operatorHandleStep%1").arg(i), true);
    handleStep_->addButton(b, i);
    g->addWidget(b, row, 2 + i);
  }
  handleStep_->button(0)->setChecked(true);
  dial_ = new QDial;
  dial_->setObjectName(QStringLiteral("operatorHandle"));
  dial_->setWrapping(true);
  dial_->setRange(0, 99);
  dial_->setNotchesVisible(true);
  dial_->setFixedSize(40, 40);
  g->addWidget(dial_, row - 1, 5, 2, 1, Qt::AlignCenter);
  // RAPID shares its row with the dial's upper half: one column for it.
  g->removeWidget(rapid_);
  g->addWidget(rapid_, row - 1, 4);
  connect(dial_, &QDial::valueChanged, this, [this](int value) {
    int d = value - dialValue_;
    if (d > 50) d -= 100;
    if (d < -50) d += 100;
    dialValue_ = value;
    if (d != 0) turnHandle(d);
  });
  connect(handleAxis_, &QButtonGroup::idClicked, this, [this](int id) {
    if (control_) control_->setHandleAxis(id == 0 ? ctl::Axis::X : ctl::Axis::Z);
  });
  connect(handleStep_, &QButtonGroup::idClicked, this, [this](int id) {
    if (control_) control_->setHandleStep(id == 0 ? 1 : id == 1 ? 10 : 100);
    refresh();
  });
  ++row;
  const char* spindleNames[3] = {"operatorSpindleCw", "operatorSpindleStop", "operatorSpindleCcw"};
  for (int i = 0; i < 3; ++i) {
    spindleKeys_[i] = panelKey(QString::fromLatin1(spindleNames[i]));
    g->addWidget(spindleKeys_[i], row, i * 2, 1, 2);
    const core::machine::SpindleDir dir = i == 0   ? core::machine::SpindleDir::Cw
                                          : i == 1 ? core::machine::SpindleDir::Stopped
                                                   : core::machine::SpindleDir::Ccw;
    connect(spindleKeys_[i], &QToolButton::clicked, this, [this, dir] {
      if (!control_) return;
      control_->setSpindle(dir);
      refresh();
    });
  }
  ++row;
  sWord_ = new QSpinBox;
  sWord_->setObjectName(QStringLiteral("operatorSpindleSpeed"));
  sWord_->setRange(0, 10000);
  sWord_->setSingleStep(50);
  sWord_->setPrefix(QStringLiteral("S"));
  g->addWidget(sWord_, row, 0, 1, 2);
  connect(sWord_, &QSpinBox::valueChanged, this, [this](int v) {
    if (control_ && control_->spindleSpeed() != v) {
      control_->setSpindleSpeed(v);
      refresh();
    }
  });
  coolant_ = panelKey(QStringLiteral("operatorCoolant"), true);
  g->addWidget(coolant_, row, 2, 1, 2);
  connect(coolant_, &QToolButton::toggled, this, [this](bool on) {
    if (control_) control_->coolant = on;
    refresh();
  });
  ++row;
  feedOv_ = new QComboBox;
  feedOv_->setObjectName(QStringLiteral("operatorFeedOverride"));
  for (int p = 0; p <= 150; p += 10) feedOv_->addItem(QStringLiteral("F %1%").arg(p), p);
  rapidOv_ = new QComboBox;
  rapidOv_->setObjectName(QStringLiteral("operatorRapidOverride"));
  for (int p : {0, 25, 50, 100}) rapidOv_->addItem(p == 0 ? QStringLiteral("R F0") : QStringLiteral("R %1%").arg(p), p);
  spindleOv_ = new QComboBox;
  spindleOv_->setObjectName(QStringLiteral("operatorSpindleOverride"));
  for (int p = 50; p <= 120; p += 10) spindleOv_->addItem(QStringLiteral("S %1%").arg(p), p);
  g->addWidget(feedOv_, row, 0, 1, 2);
  g->addWidget(rapidOv_, row, 2, 1, 2);
  g->addWidget(spindleOv_, row, 4, 1, 2);
  for (QComboBox* box : {feedOv_, rapidOv_, spindleOv_})
    connect(box, &QComboBox::currentIndexChanged, this, [this] {
      if (!control_) return;
      control_->overrides().feed = feedOv_->currentData().toInt();
      control_->overrides().rapid = rapidOv_->currentData().toInt();
      control_->overrides().spindle = spindleOv_->currentData().toInt();
      refresh();
      updateCycleTime();
      emitOverrides();
    });
  ++row;
  const char* switchNames[4] = {"operatorSingleBlock", "operatorOptStop", "operatorBlockDelete", "operatorDryRun"};
  for (int i = 0; i < 4; ++i) {
    switches_[i] = panelKey(QString::fromLatin1(switchNames[i]), true);
    g->addWidget(switches_[i], row + i / 2, (i % 2) * 3, 1, 3);
    connect(switches_[i], &QToolButton::toggled, this, [this, i](bool on) {
      if (!control_) return;
      bool* flags[4] = {&control_->singleBlock, &control_->optionalStop, &control_->blockDelete, &control_->dryRun};
      *flags[i] = on;
      refresh();
      updateCycleTime();
      if (i == 3) emitOverrides();
    });
    // Pressed by the user (not set at power-on): the Run menu's switches follow.
    if (i == 1 || i == 2)
      connect(switches_[i], &QToolButton::clicked, this,
              [this] { emit switchesChanged(switches_[1]->isChecked(), switches_[2]->isChecked()); });
  }
  row += 2;
  cycleStart_ = panelKey(QStringLiteral("operatorCycleStart"));
  cycleStart_->setStyleSheet(QStringLiteral("QToolButton { background: #2e8b3e; color: white; font-weight: bold; }"));
  feedHold_ = panelKey(QStringLiteral("operatorFeedHold"));
  reset_ = panelKey(QStringLiteral("operatorReset"));
  // Always in sight, above the pages (the keys page may scroll on a small screen).
  auto* cycle = new QHBoxLayout;
  cycle->setSpacing(2);
  cycle->addWidget(cycleStart_, 2);
  cycle->addWidget(feedHold_, 1);
  cycle->addWidget(reset_, 1);
  v->insertLayout(v->indexOf(tabs_), cycle);
  cycleTime_ = new QLabel;
  cycleTime_->setObjectName(QStringLiteral("operatorCycleTime"));
  cycleTime_->setWordWrap(true);
  g->addWidget(cycleTime_, row, 0, 1, 6);
  connect(modes_, &QButtonGroup::idClicked, this, [this](int id) { pressMode(static_cast<ctl::Mode>(id)); });
  connect(cycleStart_, &QToolButton::clicked, this, &OperatorPanel::pressCycleStart);
  connect(reset_, &QToolButton::clicked, this, &OperatorPanel::pressReset);
  connect(feedHold_, &QToolButton::clicked, this, &OperatorPanel::pressFeedHold);
  connect(powerOn_, &QToolButton::clicked, this, &OperatorPanel::powerOn);
  connect(zoom_, &QToolButton::clicked, this, [this] {
    view_->zoom = (view_->zoom + 1) % 3;
    zoom_->setText(view_->zoom == 0   ? QStringLiteral("ALL")
                   : view_->zoom == 1 ? QStringLiteral("40 mm")
                                      : QStringLiteral("8 mm"));
    view_->update();
  });
  tabs_->addTab(keys, QString());

  // ---- the offset page
  auto* page = new QWidget;
  auto* ov = new QVBoxLayout(page);
  ov->setContentsMargins(2, 2, 2, 2);
  ov->setSpacing(2);
  offsets_ = new QTableWidget(0, 4);
  offsets_->setObjectName(QStringLiteral("operatorOffsets"));
  offsets_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  offsets_->setSelectionBehavior(QAbstractItemView::SelectRows);
  offsets_->setSelectionMode(QAbstractItemView::SingleSelection);
  offsets_->verticalHeader()->setDefaultSectionSize(offsets_->fontMetrics().height() + 4);
  offsets_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  offsets_->setFont(mono);
  offsets_->setMinimumHeight(4 * offsets_->verticalHeader()->defaultSectionSize() +
                             offsets_->horizontalHeader()->sizeHint().height());
  ov->addWidget(offsets_, 1);
  auto* in = new QHBoxLayout;
  input_ = new QLineEdit;
  input_->setObjectName(QStringLiteral("operatorOffsetInput"));
  input_->setPlaceholderText(QStringLiteral("Z0 / X49.6"));
  measure_ = panelKey(QStringLiteral("operatorMeasure"));
  inputWear_ = panelKey(QStringLiteral("operatorPlusInput"));
  in->addWidget(input_, 2);
  in->addWidget(measure_, 1);
  in->addWidget(inputWear_, 1);
  ov->addLayout(in);
  auto* sh = new QHBoxLayout;
  shift_ = new QLabel;
  shift_->setObjectName(QStringLiteral("operatorWorkShift"));
  shift_->setFont(mono);
  measureShift_ = panelKey(QStringLiteral("operatorMeasureShift"));
  sh->addWidget(shift_, 2);
  sh->addWidget(measureShift_, 1);
  ov->addLayout(sh);
  auto* mic = new QHBoxLayout;
  labels_[0] = new QLabel;
  micZ_ = new QDoubleSpinBox;
  micZ_->setObjectName(QStringLiteral("operatorMicrometerZ"));
  micZ_->setRange(-2000.0, 0.0);
  micZ_->setDecimals(1);
  micZ_->setValue(-5.0);
  micZ_->setPrefix(QStringLiteral("Z"));
  micButton_ = panelKey(QStringLiteral("operatorMicrometer"));
  micReading_ = new QLabel;
  micReading_->setObjectName(QStringLiteral("operatorMicrometerReading"));
  micReading_->setFont(mono);
  mic->addWidget(labels_[0]);
  mic->addWidget(micZ_);
  mic->addWidget(micButton_);
  mic->addWidget(micReading_, 1);
  ov->addLayout(mic);
  exercise_ = new QCheckBox;
  exercise_->setObjectName(QStringLiteral("operatorExercise"));
  ov->addWidget(exercise_);
  connect(exercise_, &QCheckBox::toggled, this, [this](bool on) {
    if (!control_ || on == control_->exercise()) return;
    if (on) {
      control_->forgetGeometry();
      emitOffsets();
      refresh();
    } else {
      powerOn();
    }
  });
  connect(measure_, &QToolButton::clicked, this, &OperatorPanel::pressMeasure);
  connect(input_, &QLineEdit::returnPressed, this, &OperatorPanel::pressMeasure);
  connect(inputWear_, &QToolButton::clicked, this, [this] {
    if (!control_) return;
    const auto parsed = ctl::parseMeasureInput(input_->text().toStdString());
    if (!parsed) {
      showMessage(
          core::Diagnostic{core::Severity::Error, core::codes::kNotMeasureInput, {}, {input_->text().toStdString()}});
      return;
    }
    ctl::OffsetRow& r = control_->row(offsetRow());
    (parsed->axis == ctl::Axis::X ? r.wear.x : r.wear.z) += parsed->value;
    input_->clear();
    showMessage(std::nullopt);
    emitOffsets();
    refresh();
  });
  connect(measureShift_, &QToolButton::clicked, this, [this] {
    if (!control_) return;
    const auto parsed = ctl::parseMeasureInput(input_->text().toStdString());
    if (!parsed || parsed->axis != ctl::Axis::Z) {
      showMessage(
          core::Diagnostic{core::Severity::Error, core::codes::kNotMeasureInput, {}, {input_->text().toStdString()}});
      return;
    }
    showMessage(control_->measureWorkShift(parsed->value));
    input_->clear();
    emitOffsets();
    refresh();
  });
  connect(micButton_, &QToolButton::clicked, this, [this] {
    if (!control_) return;
    micReading_->setText(QStringLiteral("Ø%1").arg(panelMm(control_->micrometer(micZ_->value()))));
  });
  tabs_->addTab(page, QString());

  // ---- MDI
  auto* mdiPage = new QWidget;
  auto* mv = new QVBoxLayout(mdiPage);
  mv->setContentsMargins(2, 2, 2, 2);
  mdi_ = new QPlainTextEdit;
  mdi_->setObjectName(QStringLiteral("operatorMdi"));
  mdi_->setFont(mono);
  mdi_->setPlaceholderText(QStringLiteral("G00 X60 Z5"));
  // A few lines, as the control's MDI screen: the explanation stays in sight below.
  mdi_->setMaximumHeight(5 * mdi_->fontMetrics().lineSpacing() + 12);
  mdiHint_ = new QLabel;
  mdiHint_->setWordWrap(true);
  mdiHint_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  mv->addWidget(mdi_);
  mv->addWidget(mdiHint_, 1);
  tabs_->addTab(mdiPage, QString());

  // Keyboard: while the panel has the focus (the editor keeps its own keys).
  const auto shortcut = [this](const QKeySequence& keys, auto&& slot) {
    auto* s = new QShortcut(keys, this);
    s->setContext(Qt::WidgetWithChildrenShortcut);
    connect(s, &QShortcut::activated, this, std::forward<decltype(slot)>(slot));
  };
  for (int i = 0; i < 6; ++i)
    shortcut(QKeySequence(Qt::ALT | static_cast<Qt::Key>(Qt::Key_1 + i)),
             [this, i] { pressMode(static_cast<ctl::Mode>(i)); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Left), [this] { pressJog(ctl::Axis::Z, -1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Right), [this] { pressJog(ctl::Axis::Z, 1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Up), [this] { pressJog(ctl::Axis::X, 1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Down), [this] { pressJog(ctl::Axis::X, -1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_PageUp), [this] { turnHandle(1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_PageDown), [this] { turnHandle(-1); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Return), [this] { pressCycleStart(); });
  shortcut(QKeySequence(Qt::ALT | Qt::Key_Backspace), [this] { pressReset(); });

  auto* scroll = new QScrollArea;
  scroll->setWidget(body);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  setWidget(scroll);
  // Never narrower than its keys: a clipped panel hides the MACHINE column and the keys' ends.
  scroll->setMinimumWidth(body->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
}

void OperatorPanel::applyLayoutLabels() {
  const bool haas = control_ && control_->layout() == ctl::Layout::Haas;
  title_->setText(haas ? QStringLiteral("HAAS") : QStringLiteral("FANUC Series 0i-TF"));
  const char* fanucModes[6] = {"EDIT", "MEM", "MDI", "JOG", "HANDLE", "ZRN"};
  const char* haasModes[6] = {"EDIT", "MEM", "MDI/DNC", "HAND JOG", "HANDLE", "ZERO RET"};
  for (int i = 0; i < 6; ++i) modes_->button(i)->setText(QString::fromLatin1(haas ? haasModes[i] : fanucModes[i]));
  const char* heads[4] = {"ABSOLUTE", "RELATIVE", "MACHINE", "DIST TO GO"};
  const char* haasHeads[4] = {"WORK G54", "OPERATOR", "MACHINE", "DIST TO GO"};
  for (int c = 0; c < 4; ++c) posHeads_[c]->setText(QString::fromLatin1(haas ? haasHeads[c] : heads[c]));
  const char* jogs[4] = {"-X", "+X", "-Z", "+Z"};
  for (int i = 0; i < 4; ++i) jogKeys_[i]->setText(QString::fromLatin1(jogs[i]));
  rapid_->setText(haas ? QStringLiteral("RAPID") : QStringLiteral("RAPID"));
  // The rapid override keys: Fanuc F0 / 25 / 50 / 100 %, Haas 5 / 25 / 50 / 100 % (Haas NGC
  // operator's manual, T2.17 Override Keys). The value is kept when the machine changes.
  const int slowest = haas ? 5 : 0;
  if (rapidOv_->itemData(0).toInt() != slowest) {
    const QSignalBlocker quiet(rapidOv_);
    const int now = rapidOv_->currentData().toInt();
    rapidOv_->clear();
    for (int p : {slowest, 25, 50, 100})
      rapidOv_->addItem(p == 0 ? QStringLiteral("R F0") : QStringLiteral("R %1%").arg(p), p);
    const int at = rapidOv_->findData(now);
    rapidOv_->setCurrentIndex(at >= 0 ? at : 0);
    if (control_) control_->overrides().rapid = rapidOv_->currentData().toInt();
  }
  const char* steps[3] = {"×1", "×10", "×100"};
  const char* haasSteps[3] = {".001", ".01", ".1"};
  for (int i = 0; i < 3; ++i) handleStep_->button(i)->setText(QString::fromUtf8(haas ? haasSteps[i] : steps[i]));
  const char* spindle[3] = {"SPDL CW", "SPDL STOP", "SPDL CCW"};
  const char* haasSpindle[3] = {"FWD", "STOP", "REV"};
  for (int i = 0; i < 3; ++i) spindleKeys_[i]->setText(QString::fromLatin1(haas ? haasSpindle[i] : spindle[i]));
  coolant_->setText(haas ? QStringLiteral("COOLNT") : QStringLiteral("COOLANT"));
  const char* sw[4] = {"SINGLE BLOCK", "OPT STOP", "BLOCK SKIP", "DRY RUN"};
  const char* haasSw[4] = {"SINGLE BLOCK", "OPTION STOP", "BLOCK DELETE", "DRY RUN"};
  for (int i = 0; i < 4; ++i) switches_[i]->setText(QString::fromLatin1(haas ? haasSw[i] : sw[i]));
  cycleStart_->setText(QStringLiteral("CYCLE START"));
  feedHold_->setText(QStringLiteral("FEED HOLD"));
  reset_->setText(QStringLiteral("RESET"));
  powerOn_->setText(QStringLiteral("POWER ON"));
  zoom_->setText(view_->zoom == 0   ? QStringLiteral("ALL")
                 : view_->zoom == 1 ? QStringLiteral("40 mm")
                                    : QStringLiteral("8 mm"));
  measure_->setText(haas ? QStringLiteral("MESUR") : QStringLiteral("MEASURE"));
  inputWear_->setText(QStringLiteral("+INPUT"));
  measureShift_->setText(haas ? QStringLiteral("G54 Z MESUR") : QStringLiteral("SHIFT MEASURE"));
  micButton_->setText(QStringLiteral("Ø"));
  offsets_->setHorizontalHeaderLabels({haas ? QStringLiteral("X GEOM") : QStringLiteral("GEOM X"),
                                       haas ? QStringLiteral("Z GEOM") : QStringLiteral("GEOM Z"),
                                       haas ? QStringLiteral("X WEAR") : QStringLiteral("WEAR X"),
                                       haas ? QStringLiteral("Z WEAR") : QStringLiteral("WEAR Z")});
}

void OperatorPanel::retranslateUi() {
  setWindowTitle(tr("Operator panel"));
  tabs_->setTabText(0, tr("Keys"));
  tabs_->setTabText(1, tr("Offsets"));
  tabs_->setTabText(2, QStringLiteral("MDI"));
  const QString modeTips[6] = {
      tr("EDIT: the program is edited in the editor"),
      tr("MEMORY: cycle start runs the job's program"),
      tr("MDI: type blocks on the MDI page and press cycle start (Alt+Enter)"),
      tr("JOG: hold -X +X -Z +Z (Alt+arrows) to move at the jog feed, with RAPID at the rapid rate"),
      tr("HANDLE: the handwheel moves the chosen axis one step a click (Alt+Page Up/Down)"),
      tr("ZERO RETURN: +X and +Z bring each axis to the reference point; until then cycle start is refused")};
  for (int i = 0; i < 6; ++i) modes_->button(i)->setToolTip(modeTips[i] + QStringLiteral(" (Alt+%1)").arg(i + 1));
  for (int i = 0; i < 4; ++i)
    jogKeys_[i]->setToolTip(tr("Jog the turret; in ZERO RETURN mode +X / +Z return the axis"));
  rapid_->setToolTip(tr("Jog at the rapid rate (times the rapid override): a rapid into the bar is a crash"));
  handleStep_->button(0)->setToolTip(tr("0.001 mm a click (X in diameter)"));
  handleStep_->button(1)->setToolTip(tr("0.01 mm a click (X in diameter)"));
  handleStep_->button(2)->setToolTip(tr("0.1 mm a click (X in diameter)"));
  dial_->setToolTip(tr("The handwheel (manual pulse generator): turn it, or Alt+Page Up / Page Down"));
  spindleKeys_[0]->setToolTip(tr("Spindle forward (M03) at the S speed"));
  spindleKeys_[1]->setToolTip(tr("Spindle stop (M05): never touch the bar with the spindle stopped"));
  spindleKeys_[2]->setToolTip(tr("Spindle reverse (M04) at the S speed"));
  sWord_->setToolTip(tr("Spindle speed for the spindle keys, rpm"));
  coolant_->setToolTip(tr("Coolant on / off (M08 / M09)"));
  feedOv_->setToolTip(tr("Feed override: 0 to 150 % in steps of 10 %; it does not act while threading"));
  rapidOv_->setToolTip(tr("Rapid override: F0 (Haas: 5 %), 25, 50 or 100 % of the rapid rate"));
  spindleOv_->setToolTip(tr("Spindle override: 50 to 120 % of the programmed speed"));
  switches_[0]->setToolTip(tr("Single block: the program stops after each block"));
  switches_[1]->setToolTip(tr("Optional stop: M01 stops the program"));
  switches_[2]->setToolTip(tr("Block delete: blocks starting with / are skipped"));
  switches_[3]->setToolTip(tr("Dry run: feed moves at the jog feed, to try a program in the air"));
  cycleStart_->setToolTip(tr("Cycle start (Alt+Enter): MDI runs the typed blocks, MEMORY runs the program"));
  feedHold_->setToolTip(
      tr("Feed hold: a running program's axes decelerate and stop, the spindle keeps turning; CYCLE START resumes"));
  reset_->setToolTip(tr("Reset (Alt+Backspace): clears the alarm"));
  powerOn_->setToolTip(
      tr("Power on again: a new bar, the turret short of the reference point, the offsets as the job has them"));
  zoom_->setToolTip(tr("Zoom: the bar and the tool, 40 mm around the tool tip, or 8 mm to see each handwheel click"));
  measure_->setToolTip(
      tr("Type Z0 with the tool on the face, or X and the measured diameter after a cut, then MEASURE: "
         "the geometry offset of the selected row is computed from the machine position"));
  inputWear_->setToolTip(
      tr("Type X or Z and a correction (X-0.04), then +INPUT: it is added to the wear of the selected row"));
  measureShift_->setToolTip(
      tr("Type Z0 with the tool on the face: the work shift Z is set from the selected tool's geometry"));
  micButton_->setToolTip(tr("Measure the bar's diameter at this Z with the micrometer"));
  labels_[0]->setText(tr("Micrometer"));
  exercise_->setText(tr("Exercise: the offsets are unknown"));
  exercise_->setToolTip(
      tr("Every geometry offset starts at 0: each tool the program uses must be touched off "
         "before cycle start, and cycle start then says how far the entries are from the true tools "
         "and saves them beside the program for grading. A job file with (OFFSETS: UNKNOWN) at its head "
         "starts in the exercise."));
  offsets_->setToolTip(
      tr("Geometry and wear offsets, X as a diameter; the selected row takes MEASURE and +INPUT") +
      QStringLiteral("\n\n") +
      tr("Touch off: spindle on, touch the face, type Z0, MEASURE; skim a diameter, back off in Z only, "
         "stop the spindle, measure it, type X and the diameter, MEASURE. Row = the station (T0101)."));
  tabs_->setTabToolTip(1, offsets_->toolTip());
  mdiHint_->setText(
      tr("MDI mode: type one or more blocks, then CYCLE START. They run with the same check, "
         "interpreter and cut as a program; the modal state carries on to the next blocks."));
  // Long tips wrap (rich text) instead of running off the screen.
  for (QWidget* w : findChildren<QWidget*>()) {
    const QString t = w->toolTip();
    if (!t.isEmpty() && !t.startsWith(QLatin1Char('<')))
      w->setToolTip(QStringLiteral("<p>") + t.toHtmlEscaped().replace(QLatin1Char('\n'), QStringLiteral("<br>")) +
                    QStringLiteral("</p>"));
  }
  tabs_->setTabToolTip(1, offsets_->toolTip());
  applyLayoutLabels();
  refresh();
}

void OperatorPanel::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

void OperatorPanel::showEvent(QShowEvent* event) {
  QDockWidget::showEvent(event);
  if (!control_)
    powerOn();
  else
    updateCycleTime();
}

void OperatorPanel::powerOn() {
  Source s = source_();
  // The offsets the panel gave the run are not offset.cfg: power on starts from the file's again.
  if (emitted_ && panelSameOffsets(s.setup.offsets, lastEmitted_))
    s.setup.offsets = fileOffsets_;
  else
    fileOffsets_ = s.setup.offsets;
  control_ = std::make_unique<ctl::Control>(s.setup, s.stock, s.dialect);
  view_->setControl(control_.get());
  const int stations = std::min(s.setup.machine.turretStations, core::io::kMaxStations);
  offsets_->setRowCount(stations);
  QStringList rows;
  for (int n = 1; n <= stations; ++n) rows << QStringLiteral("%1").arg(n, 2, 10, QLatin1Char('0'));
  offsets_->setVerticalHeaderLabels(rows);
  setOffsetRow(1);
  modes_->button(static_cast<int>(control_->mode()))->setChecked(true);
  sWord_->setValue(static_cast<int>(control_->spindleSpeed()));
  feedOv_->setCurrentIndex(feedOv_->findData(100));
  rapidOv_->setCurrentIndex(rapidOv_->findData(100));
  spindleOv_->setCurrentIndex(spindleOv_->findData(100));
  for (QToolButton* sw : switches_) sw->setChecked(false);
  // The teacher's job file may ask for the setup exercise: (OFFSETS: UNKNOWN) at its head.
  if (core::io::offsetsUnknownIn(s.programFile.gcode) > 0) control_->forgetGeometry();
  {
    const QSignalBlocker quiet(exercise_);
    exercise_->setChecked(control_->exercise());
  }
  coolant_->setChecked(false);
  handleStep_->button(0)->setChecked(true);
  handleAxis_->button(1)->setChecked(true);
  shown_.reset();
  message_->clear();
  micReading_->clear();
  applyLayoutLabels();
  emitOffsets();
  emitOverrides();
  refresh();
  updateCycleTime();
}

int OperatorPanel::offsetRow() const { return std::max(0, offsets_->currentRow()) + 1; }

void OperatorPanel::setOffsetRow(int row) {
  if (row >= 1 && row <= offsets_->rowCount()) offsets_->selectRow(row - 1);
}

void OperatorPanel::pressMode(ctl::Mode mode) {
  if (!control_) return;
  control_->setMode(mode);
  chips_ = false;
  modes_->button(static_cast<int>(mode))->setChecked(true);
  if (mode == ctl::Mode::Mdi) tabs_->setCurrentIndex(2);
  refresh();
}

void OperatorPanel::pressJog(ctl::Axis axis, int direction) {
  if (!control_) return;
  if (control_->mode() == ctl::Mode::ZeroReturn) {
    if (direction > 0) afterMotion(control_->zeroReturn(axis));
    return;
  }
  // One tick of a held key: 0.1 s at the jog feed or the rapid rate (times the overrides).
  const core::io::MachineConfig& m = control_->setup().machine;
  const bool rapid = rapid_->isChecked();
  const int ro = control_->overrides().rapid;
  const double rate =
      rapid ? (ro <= 0 ? ctl::kRapidF0Rate : (axis == ctl::Axis::X ? 2.0 * m.rapidX : m.rapidZ) * ro / 100.0)
            : control_->jogFeed * control_->overrides().feed / 100.0 * (axis == ctl::Axis::X ? 2.0 : 1.0);
  afterMotion(control_->jog(axis, direction * rate / 600.0, rapid));
}

void OperatorPanel::turnHandle(int clicks) {
  if (!control_) return;
  afterMotion(control_->handle(clicks));
}

void OperatorPanel::afterMotion(const ctl::MotionResult& r) {
  chips_ = r.cut;
  showMessage(r.stop);
  view_->update();
  refresh();
}

void OperatorPanel::pressMeasure() {
  if (!control_) return;
  const auto parsed = ctl::parseMeasureInput(input_->text().toStdString());
  if (!parsed) {
    showMessage(
        core::Diagnostic{core::Severity::Error, core::codes::kNotMeasureInput, {}, {input_->text().toStdString()}});
    return;
  }
  showMessage(control_->measure(offsetRow(), parsed->axis, parsed->value));
  input_->clear();
  emitOffsets();
  refresh();
}

void OperatorPanel::pressCycleStart() {
  if (!control_) return;
  switch (control_->mode()) {
    case ctl::Mode::Mdi: {
      const double removed = control_->stock().removedVolume();
      const std::vector<core::Diagnostic> ds = control_->runMdi(mdi_->toPlainText().toStdString());
      chips_ = control_->stock().removedVolume() > removed;
      showAll(ds);
      if (!core::hasErrors(ds)) mdi_->clear();
      view_->update();
      refresh();
      return;
    }
    case ctl::Mode::Memory: {
      std::vector<int> used;
      if (control_->exercise()) {
        // The tools of the program as it is now (the last run may be of older text, or none yet).
        const Source s = source_();
        core::job::JobInput input;
        input.file = s.programFile;
        input.setup = control_->runSetup();
        input.inferTools = false;
        input.folder = std::string();
        input.run.dialect = s.dialect;
        const std::shared_ptr<const core::job::Job> job = core::job::makeJob(std::move(input));
        std::set<int> tools;
        if (const core::machine::Timeline* t = job->timeline())
          for (const core::machine::Move& m : t->moves)
            if (m.tool > 0) tools.insert(m.tool);
        used.assign(tools.begin(), tools.end());
      }
      const auto refusal = control_->cycleStartRefusal(used);
      // The exercise: how far the entered offsets are from the true ones.
      showMessage(refusal ? refusal : control_->exercise() ? control_->compareTouchOff(used) : std::nullopt);
      if (!refusal && control_->exercise()) saveTouchOff();
      if (!refusal) emit cycleStartRequested(control_->singleBlock);
      return;
    }
    default:
      showMessage(core::Diagnostic{core::Severity::Note, core::codes::kKeyNotInMode, {}, {"CYCLE START", "MEM / MDI"}});
  }
}

void OperatorPanel::saveTouchOff() {
  // The student's touch-off, beside the program, for klueng-cli class and Grade a class.
  const QString program = source_().programPath;
  if (program.isEmpty()) {
    touchOffSaved_.clear();
    return;
  }
  const std::string path = core::job::touchOffFilePath(program.toStdString());
  std::string error;
  const bool ok =
      core::io::writeTextFileAtomic(path, core::io::formatOffsetTable(control_->runSetup().offsets), &error);
  touchOffSaved_ = ok ? QString::fromStdString(path) : QString();
  const QString name = QString::fromStdString(std::filesystem::path(path).filename().string());
  note_ = ok ? tr("Touch-off saved for grading: %1").arg(name)
             : tr("Touch-off not saved (%1): %2").arg(name, QString::fromStdString(error));
  showMessage(shown_);
}

void OperatorPanel::pressFeedHold() {
  if (!control_) return;
  emit feedHoldRequested();
}

void OperatorPanel::showFeedHold(bool held) {
  showMessage(std::nullopt);
  note_ = held ? tr("FEED HOLD: the axes stop, the spindle keeps turning; CYCLE START in MEM resumes")
               : tr("FEED HOLD: no program is moving");
  showMessage(shown_);
}

void OperatorPanel::emitOverrides() {
  if (control_) emit overridesChanged(control_->overrides(), control_->dryRun, control_->jogFeed);
}

void OperatorPanel::pressReset() {
  if (!control_) return;
  control_->reset();
  showMessage(std::nullopt);
  refresh();
}

QString OperatorPanel::text(const core::Diagnostic& d) const {
  return QString::fromStdString(core::formatMessage(d, Language::coreLang(), core::Surface::Gui));
}

void OperatorPanel::showMessage(const std::optional<core::Diagnostic>& d) {
  if (&d != &shown_) {
    mdiPlace_ = {0, 0};  // a new message: not about an MDI line unless showAll says so
    note_.clear();
  }
  shown_ = d;
  if (!d) {
    message_->setStyleSheet(QString());
    message_->setText(note_);
    return;
  }
  const bool bad = core::isError(d->severity);
  const bool warn = d->severity == core::Severity::Warning;
  message_->setStyleSheet(bad    ? QStringLiteral("color: #b00000; font-weight: bold;")
                          : warn ? QStringLiteral("color: #8a5a00;")
                                 : QString());
  QString line = QString::fromStdString(d->code) + QStringLiteral(" ") + text(*d);
  if (mdiPlace_.first > 0) line += tr(" (MDI line %1, column %2)").arg(mdiPlace_.first).arg(mdiPlace_.second);
  if (!note_.isEmpty()) line += QLatin1Char('\n') + note_;
  message_->setText(line);
}

void OperatorPanel::showAll(const std::vector<core::Diagnostic>& ds) {
  if (ds.empty()) {
    showMessage(std::nullopt);
    return;
  }
  // The worst one first, with its line in the MDI text.
  const core::Diagnostic* worst = &ds.front();
  for (const core::Diagnostic& d : ds)
    if (core::isError(d.severity) && !core::isError(worst->severity)) worst = &d;
  showMessage(*worst);
  mdiPlace_ = worst->range.line > 0 ? std::make_pair(worst->range.line, worst->range.column) : std::make_pair(0, 0);
  showMessage(shown_);
}

void OperatorPanel::emitOffsets() {
  if (!control_) return;
  lastEmitted_ = control_->runSetup().offsets;
  emitted_ = true;
  emit offsetsChanged(lastEmitted_);
}

void OperatorPanel::refresh() {
  if (!control_) {
    for (auto& r : pos_)
      for (QLabel* l : r) l->setText(QStringLiteral("-"));
    return;
  }
  const ctl::Control& c = *control_;
  const ctl::AxisValues v[4] = {c.absolutePosition(), c.relativePosition(), c.machinePosition(), c.distanceToGo()};
  for (int k = 0; k < 4; ++k) {
    pos_[0][k]->setText(panelMm(v[k].x));
    pos_[1][k]->setText(panelMm(v[k].z));
  }
  // Not yet referenced: the machine column says so, as the lamps of a real panel do.
  for (int r = 0; r < 2; ++r) {
    const bool ref = c.referenced(r == 0 ? ctl::Axis::X : ctl::Axis::Z);
    pos_[r][2]->setStyleSheet(ref ? QString() : QStringLiteral("color: #b00000;"));
    pos_[r][2]->setToolTip(ref ? QString() : tr("Not returned to the reference point yet"));
  }
  const char* dir = c.spindle() == core::machine::SpindleDir::Cw    ? "CW"
                    : c.spindle() == core::machine::SpindleDir::Ccw ? "CCW"
                                                                    : "STOP";
  // The mode as its key says it (Fanuc JOG, Haas HAND JOG).
  state_->setText(QStringLiteral("%1  T%2  S%3 %4  %5%6")
                      .arg(modes_->button(static_cast<int>(c.mode()))->text())
                      .arg(c.station(), 2, 10, QLatin1Char('0'))
                      .arg(c.actualRpm(), 0, 'f', 0)
                      .arg(QString::fromLatin1(dir))
                      .arg(c.alarm() ? QStringLiteral("ALM ") : QString())
                      .arg(c.coolant ? QStringLiteral("COOL") : QString()));
  // Chips: the last key took material off, the sign a touch-off waits for.
  if (chips_) state_->setText(state_->text() + QStringLiteral("  ") + tr("CHIPS"));
  state_->setStyleSheet(c.alarm() ? QStringLiteral("color: #b00000; font-weight: bold;")
                        : chips_  ? QStringLiteral("color: #a05000; font-weight: bold;")
                                  : QString());
  if (shown_) showMessage(shown_);  // its words in the language now shown
  for (int n = 1; n <= offsets_->rowCount(); ++n) {
    const ctl::OffsetRow& r = c.row(n);
    const QString cells[4] = {panelMm(r.geometry.x), panelMm(r.geometry.z), panelMm(r.wear.x), panelMm(r.wear.z)};
    for (int k = 0; k < 4; ++k) {
      QTableWidgetItem* item = offsets_->item(n - 1, k);
      if (!item) {
        item = new QTableWidgetItem;
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        offsets_->setItem(n - 1, k, item);
      }
      item->setText(cells[k]);
    }
  }
  shift_->setText(QStringLiteral("SHIFT Z %1").arg(panelMm(c.workShift().z)));
}

void OperatorPanel::updateCycleTime() {
  if (!control_) return;
  const ctl::Control& c = *control_;
  // The program's cycle time as these overrides would make it.
  const Source s = source_();
  if (s.program && !s.program->moves.empty()) {
    const double base = s.program->cycleTime();
    const double now =
        ctl::withOverrides(*s.program, c.overrides(), c.setup().machine, c.dryRun, c.jogFeed).cycleTime();
    cycleTime_->setText(
        tr("Cycle time at these overrides: %1 (at 100 %: %2)").arg(panelMinSec(now), panelMinSec(base)));
  } else {
    cycleTime_->setText(tr("Run the program once to see its cycle time at these overrides."));
  }
}

}  // namespace klueng::gui
