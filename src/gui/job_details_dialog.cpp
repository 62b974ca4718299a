#include "gui/job_details_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <optional>

#include "gui/language.h"
#include "klueng/core/gcode/machine_profile.h"

namespace klueng::gui {

namespace io = core::io;

namespace {
QDoubleSpinBox* makeSize(QWidget* parent, double value) {
  auto* box = new QDoubleSpinBox(parent);
  box->setDecimals(3);
  box->setRange(0.001, 9999.999);  // SPEC 2: diameter and length must be > 0
  box->setValue(value);
  return box;
}
// A choice the file may leave to the program and the machine: item data -1
// (unset), then `first` and `second`, the texts set by retranslate().
QComboBox* makeChoice(QWidget* parent, const char* objectName, const std::optional<bool>& chosen, bool first) {
  auto* box = new QComboBox(parent);
  box->setObjectName(QLatin1String(objectName));
  box->addItem(QString(), -1);
  box->addItem(QString(), first ? 1 : 0);
  box->addItem(QString(), first ? 0 : 1);
  box->setCurrentIndex(!chosen ? 0 : *chosen == first ? 1 : 2);
  return box;
}
std::optional<bool> choiceOf(const QComboBox* box) {
  const int value = box->currentData().toInt();
  return value < 0 ? std::nullopt : std::optional<bool>(value == 1);
}
QComboBox* makeUnit(QWidget* parent, io::LengthUnit unit) {
  auto* box = new QComboBox(parent);
  box->addItem(QString(), static_cast<int>(io::LengthUnit::Millimetre));
  box->addItem(QString(), static_cast<int>(io::LengthUnit::Inch));
  box->setCurrentIndex(unit == io::LengthUnit::Millimetre ? 0 : 1);
  return box;
}
QWidget* pair(QWidget* parent, QWidget* a, QWidget* b) {
  auto* w = new QWidget(parent);
  auto* l = new QHBoxLayout(w);
  l->setContentsMargins(0, 0, 0, 0);
  l->addWidget(a, 1);
  l->addWidget(b);
  return w;
}
}  // namespace

JobDetailsDialog::JobDetailsDialog(const io::JobHeader& h, QWidget* parent) : QDialog(parent) {
  project_ = new QLineEdit(QString::fromStdString(h.project), this);
  part_ = new QLineEdit(QString::fromStdString(h.part), this);
  material_ = new QLineEdit(QString::fromStdString(h.material), this);
  diameter_ = makeSize(this, h.diameter);
  diameter_->setObjectName(QStringLiteral("diameter"));
  diameterUnit_ = makeUnit(this, h.diameterUnit);
  length_ = makeSize(this, h.length);
  length_->setObjectName(QStringLiteral("length"));
  lengthUnit_ = makeUnit(this, h.lengthUnit);
  bore_ = makeSize(this, h.bore);
  bore_->setObjectName(QStringLiteral("bore"));
  bore_->setMinimum(0.0);  // 0 = a solid bar
  bore_->setValue(h.bore);
  boreUnit_ = new QLabel(this);
  problem_ = new QLabel(this);
  problem_->setObjectName(QStringLiteral("jobDetailsProblem"));
  problem_->setWordWrap(true);
  problem_->setStyleSheet(QStringLiteral("color: #b00020;"));
  programmer_ = new QLineEdit(QString::fromStdString(h.programmer), this);
  for (QLineEdit* e : {project_, part_, material_, programmer_}) e->setMinimumWidth(280);
  // Unset (the program's numbers, else the machine), whole, increments.
  decimalPoint_ = makeChoice(this, "decimalPoint", h.calculatorInput, true);
  // Unset (what the program's moves show, else the machine), in front, beyond.
  toolSide_ = makeChoice(this, "toolSide", h.toolsBeyondCentre, false);
  // Not named, then every loaded machine (names in the UI language: retranslate).
  machine_ = new QComboBox(this);
  machine_->setObjectName(QStringLiteral("machine"));
  machine_->addItem(QString(), QString());
  for (const core::gcode::MachineProfile* p : core::gcode::machineProfiles())
    machine_->addItem(QString(), QString::fromUtf8(p->id.data(), static_cast<qsizetype>(p->id.size())));
  const int named = machine_->findData(QString::fromStdString(h.machine));
  machine_->setCurrentIndex(named > 0 ? named : 0);
  form_ = new QFormLayout;
  form_->addRow(new QLabel(this), project_);
  form_->addRow(new QLabel(this), part_);
  form_->addRow(new QLabel(this), material_);
  form_->addRow(new QLabel(this), pair(this, diameter_, diameterUnit_));
  form_->addRow(new QLabel(this), pair(this, length_, lengthUnit_));
  form_->addRow(new QLabel(this), pair(this, bore_, boreUnit_));
  form_->addRow(new QLabel(this), programmer_);
  form_->addRow(new QLabel(this), decimalPoint_);
  form_->addRow(new QLabel(this), toolSide_);
  form_->addRow(new QLabel(this), machine_);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form_);
  layout->addWidget(problem_);
  layout->addWidget(buttons_);
  connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(diameter_, &QDoubleSpinBox::valueChanged, this, &JobDetailsDialog::validate);
  connect(bore_, &QDoubleSpinBox::valueChanged, this, &JobDetailsDialog::validate);
  connect(diameterUnit_, &QComboBox::currentIndexChanged, this, &JobDetailsDialog::retranslate);
  retranslate();
}

io::JobHeader JobDetailsDialog::header() const {
  io::JobHeader h;
  // A header line holds one line of text: line breaks would shift the G-code.
  auto line = [](const QLineEdit* e) { return e->text().simplified().toStdString(); };
  h.project = line(project_);
  h.part = line(part_);
  h.material = line(material_);
  h.programmer = line(programmer_);
  h.diameter = diameter_->value();
  h.diameterUnit = static_cast<io::LengthUnit>(diameterUnit_->currentData().toInt());
  h.length = length_->value();
  h.lengthUnit = static_cast<io::LengthUnit>(lengthUnit_->currentData().toInt());
  h.bore = bore_->value() < h.diameter ? bore_->value() : 0.0;
  h.calculatorInput = choiceOf(decimalPoint_);
  h.toolsBeyondCentre = choiceOf(toolSide_);
  h.machine = machine_->currentData().toString().toStdString();
  return h;
}

void JobDetailsDialog::validate() {
  const bool boreOk = bore_->value() < diameter_->value();
  problem_->setText(boreOk ? QString()
                           : tr("The bore (%1) must be smaller than the stock diameter (%2).")
                                 .arg(bore_->value())
                                 .arg(diameter_->value()));
  problem_->setVisible(!boreOk);
  if (QPushButton* ok = buttons_->button(QDialogButtonBox::Ok)) ok->setEnabled(boreOk);
}

void JobDetailsDialog::retranslate() {
  setWindowTitle(tr("Job Details"));
  const QString labels[] = {tr("Project:"),      tr("Part:"),
                            tr("Material:"),     tr("Stock diameter:"),
                            tr("Stock length:"), tr("Bore diameter (tube; 0 = solid bar):"),
                            tr("Programmer:"),   tr("Lengths without a decimal point:"),
                            tr("Tool side:"),    tr("Machine:")};
  for (int i = 0; i < 10; ++i)
    if (auto* label = qobject_cast<QLabel*>(form_->itemAt(i, QFormLayout::LabelRole)->widget()))
      label->setText(labels[i]);
  for (QComboBox* unit : {diameterUnit_, lengthUnit_}) {
    unit->setItemText(0, tr("mm"));
    unit->setItemText(1, tr("inch"));
  }
  boreUnit_->setText(diameterUnit_->currentText());  // the bore is in the diameter's unit
  bore_->setToolTip(tr("Tube stock: the diameter of the hole through it. 0 = a solid bar."));
  decimalPoint_->setItemText(0, tr("As the program's numbers show"));
  decimalPoint_->setItemText(1, tr("Whole (X30 = 30 mm)"));
  decimalPoint_->setItemText(2, tr("Least input increments (X30 = 0.030 mm)"));
  decimalPoint_->setToolTip(
      tr("How X30 or G71 U1250 is read. Whole: X30 = 30 mm (calculator-type input). Least input increments: "
         "X30 = 0.030 mm, 0.0030 in under G20, as a standard Fanuc or Haas reads it. As the program's numbers "
         "show: a plain program's own numbers decide (G71 U1250 only makes sense in increments), else the "
         "machine setting (machine.cfg calculator_input)."));
  toolSide_->setItemText(0, tr("As the program's moves show"));
  toolSide_->setItemText(1, tr("In front of the centre line"));
  toolSide_->setItemText(2, tr("Beyond the centre line (rear tool post, X < 0)"));
  toolSide_->setToolTip(
      tr("Where the tools work. Beyond the centre line: a rear tool post or a lathe programmed in negative X; the "
         "tools are drawn and cut mirrored onto the front. As the program's moves show: a plain program that cuts "
         "at X < 0 has its tools there, else the machine setting (machine.cfg tools_beyond_centre)."));
  const bool thai = Language::coreLang() == core::Lang::Th;
  machine_->setItemText(0, tr("Not named (the window's machine)"));
  for (int i = 1; i < machine_->count(); ++i) {
    core::gcode::Dialect d{};
    if (!core::gcode::parseDialectId(machine_->itemData(i).toString().toStdString(), d)) continue;
    const core::gcode::MachineProfile& p = core::gcode::machineProfile(d);
    const std::string_view name = thai ? p.nameTh : p.nameEn;
    machine_->setItemText(i, QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size())));
  }
  machine_->setToolTip(
      tr("The machine this program is written for. The program names it in a comment at its head, "
         "(MACHINE: romi-gl240m): opening the file selects that machine, and klueng-cli checks it on that "
         "machine unless --machine or --dialect is given."));
  validate();
}

void JobDetailsDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

}  // namespace klueng::gui
