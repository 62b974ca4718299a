// The operator panel's face: its widgets laid out as the control's (title, bar view,
// position page, message line, cycle keys, and the keys, offset and MDI pages), each wired to
// the key it is, and their words (the control's own labels, tooltips via tr()). What the keys
// do is in operator_panel.cpp.
#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDial>
#include <QDoubleSpinBox>
#include <QFontDatabase>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
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

#include "gui/operator_panel.h"
#include "gui/operator_touch_view.h"

namespace klueng::gui {

namespace ctl = core::control;

namespace {

QToolButton* panelKey(const QString& objectName, bool checkable = false) {
  auto* b = new QToolButton;
  b->setObjectName(objectName);
  b->setCheckable(checkable);
  b->setToolButtonStyle(Qt::ToolButtonTextOnly);
  b->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  return b;
}

QFont panelMono() { return QFontDatabase::systemFont(QFontDatabase::FixedFont); }

}  // namespace

void OperatorPanel::build() {
  auto* body = new QWidget;
  auto* v = new QVBoxLayout(body);
  v->setContentsMargins(4, 4, 4, 4);
  v->setSpacing(4);
  addTitleRow(v);
  view_ = new TouchView(body);
  v->addWidget(view_, 1);
  addPositionPage(v);
  addMessageLine(v);
  tabs_ = new QTabWidget;
  tabs_->setObjectName(QStringLiteral("operatorTabs"));
  v->addWidget(tabs_);
  QWidget* keys = buildKeysPage();
  // Always in sight, above the pages (the keys page may scroll on a small screen).
  v->insertLayout(v->indexOf(tabs_), buildCycleKeys());
  tabs_->addTab(keys, QString());
  tabs_->addTab(buildOffsetPage(), QString());
  tabs_->addTab(buildMdiPage(), QString());
  addShortcuts();
  putInScrollArea(body);
}

// The control's name, the zoom of the bar view and POWER ON.
void OperatorPanel::addTitleRow(QVBoxLayout* v) {
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
  connect(powerOn_, &QToolButton::clicked, this, &OperatorPanel::powerOn);
  connect(zoom_, &QToolButton::clicked, this, [this] {
    view_->zoom = (view_->zoom + 1) % 3;
    zoom_->setText(view_->zoom == 0   ? QStringLiteral("ALL")
                   : view_->zoom == 1 ? QStringLiteral("40 mm")
                                      : QStringLiteral("8 mm"));
    view_->update();
  });
}

// The position page: X as a diameter, as the control shows it; the mode, tool and spindle under it.
void OperatorPanel::addPositionPage(QVBoxLayout* v) {
  auto* pos = new QGridLayout;
  pos->setHorizontalSpacing(6);
  pos->setVerticalSpacing(0);
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
      pos_[r][c]->setFont(panelMono());
      pos_[r][c]->setAlignment(Qt::AlignRight);
      pos_[r][c]->setObjectName(QStringLiteral("operatorPos%1%2").arg(QString::fromLatin1(axes[r])).arg(c));
      pos->addWidget(pos_[r][c], r + 1, c + 1);
    }
  }
  v->addLayout(pos);
  state_ = new QLabel;
  state_->setObjectName(QStringLiteral("operatorState"));
  state_->setFont(panelMono());
  v->addWidget(state_);
}

void OperatorPanel::addMessageLine(QVBoxLayout* v) {
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
}

// The keys page, row by row as on the control.
QWidget* OperatorPanel::buildKeysPage() {
  auto* keys = new QWidget;
  auto* g = new QGridLayout(keys);
  g->setContentsMargins(2, 2, 2, 2);
  g->setSpacing(2);
  addModeKeys(g);      // rows 0 and 1
  addJogKeys(g, 2);    // and RAPID
  addHandwheel(g, 3);  // its dial across rows 2 and 3
  addSpindleKeys(g, 4);
  addSpindleSpeedAndCoolant(g, 5);
  addOverrideKnobs(g, 6);
  addSwitches(g, 7);  // rows 7 and 8
  cycleTime_ = new QLabel;
  cycleTime_->setObjectName(QStringLiteral("operatorCycleTime"));
  cycleTime_->setWordWrap(true);
  g->addWidget(cycleTime_, 9, 0, 1, 6);
  return keys;
}

void OperatorPanel::addModeKeys(QGridLayout* g) {
  modes_ = new QButtonGroup(this);
  const char* modeNames[6] = {"operatorModeEdit", "operatorModeMem",    "operatorModeMdi",
                              "operatorModeJog",  "operatorModeHandle", "operatorModeZrn"};
  for (int i = 0; i < 6; ++i) {
    QToolButton* b = panelKey(QString::fromLatin1(modeNames[i]), true);
    modes_->addButton(b, i);
    g->addWidget(b, i / 3, (i % 3) * 2, 1, 2);
  }
  connect(modes_, &QButtonGroup::idClicked, this, [this](int id) { pressMode(static_cast<ctl::Mode>(id)); });
}

void OperatorPanel::addJogKeys(QGridLayout* g, int row) {
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
  // RAPID shares its row with the handwheel's upper half: one column for it.
  g->addWidget(rapid_, row, 4);
}

void OperatorPanel::addHandwheel(QGridLayout* g, int row) {
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
}

void OperatorPanel::addSpindleKeys(QGridLayout* g, int row) {
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
}

void OperatorPanel::addSpindleSpeedAndCoolant(QGridLayout* g, int row) {
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
}

void OperatorPanel::addOverrideKnobs(QGridLayout* g, int row) {
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
}

void OperatorPanel::addSwitches(QGridLayout* g, int row) {
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
      if (i == 0) emit singleBlockChanged(on);
    });
    // Pressed by the user (not set at power-on): the Run menu's switches follow.
    if (i == 1 || i == 2)
      connect(switches_[i], &QToolButton::clicked, this,
              [this] { emit switchesChanged(switches_[1]->isChecked(), switches_[2]->isChecked()); });
  }
}

// CYCLE START, FEED HOLD, RESET.
QHBoxLayout* OperatorPanel::buildCycleKeys() {
  cycleStart_ = panelKey(QStringLiteral("operatorCycleStart"));
  cycleStart_->setStyleSheet(QStringLiteral("QToolButton { background: #2e8b3e; color: white; font-weight: bold; }"));
  feedHold_ = panelKey(QStringLiteral("operatorFeedHold"));
  reset_ = panelKey(QStringLiteral("operatorReset"));
  auto* cycle = new QHBoxLayout;
  cycle->setSpacing(2);
  cycle->addWidget(cycleStart_, 2);
  cycle->addWidget(feedHold_, 1);
  cycle->addWidget(reset_, 1);
  connect(cycleStart_, &QToolButton::clicked, this, &OperatorPanel::pressCycleStart);
  connect(reset_, &QToolButton::clicked, this, &OperatorPanel::pressReset);
  connect(feedHold_, &QToolButton::clicked, this, &OperatorPanel::pressFeedHold);
  return cycle;
}

// The offset page: the geometry and wear rows, MEASURE / +INPUT, the work shift, the micrometer, the exercise.
QWidget* OperatorPanel::buildOffsetPage() {
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
  offsets_->setFont(panelMono());
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
  shift_->setFont(panelMono());
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
  micReading_->setFont(panelMono());
  mic->addWidget(labels_[0]);
  mic->addWidget(micZ_);
  mic->addWidget(micButton_);
  mic->addWidget(micReading_, 1);
  ov->addLayout(mic);
  exercise_ = new QCheckBox;
  exercise_->setObjectName(QStringLiteral("operatorExercise"));
  ov->addWidget(exercise_);
  connect(exercise_, &QCheckBox::toggled, this, &OperatorPanel::setExercise);
  connect(measure_, &QToolButton::clicked, this, &OperatorPanel::pressMeasure);
  connect(input_, &QLineEdit::returnPressed, this, &OperatorPanel::pressMeasure);
  connect(inputWear_, &QToolButton::clicked, this, &OperatorPanel::pressInputWear);
  connect(measureShift_, &QToolButton::clicked, this, &OperatorPanel::pressMeasureShift);
  connect(micButton_, &QToolButton::clicked, this, &OperatorPanel::pressMicrometer);
  return page;
}

QWidget* OperatorPanel::buildMdiPage() {
  auto* mdiPage = new QWidget;
  auto* mv = new QVBoxLayout(mdiPage);
  mv->setContentsMargins(2, 2, 2, 2);
  mdi_ = new QPlainTextEdit;
  mdi_->setObjectName(QStringLiteral("operatorMdi"));
  mdi_->setFont(panelMono());
  mdi_->setPlaceholderText(QStringLiteral("G00 X60 Z5"));
  // A few lines, as the control's MDI screen: the explanation stays in sight below.
  mdi_->setMaximumHeight(5 * mdi_->fontMetrics().lineSpacing() + 12);
  mdiHint_ = new QLabel;
  mdiHint_->setWordWrap(true);
  mdiHint_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  mv->addWidget(mdi_);
  mv->addWidget(mdiHint_, 1);
  return mdiPage;
}

// Keyboard: while the panel has the focus (the editor keeps its own keys).
void OperatorPanel::addShortcuts() {
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
}

void OperatorPanel::putInScrollArea(QWidget* body) {
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

}  // namespace klueng::gui
