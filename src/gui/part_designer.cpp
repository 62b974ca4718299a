#include "gui/part_designer.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSignalBlocker>
#include <QDir>
#include <QFile>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableView>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/design_model.h"
#include "gui/design_preview.h"
#include "gui/file_save.h"
#include "gui/language.h"
#include "gui/part3d_view.h"
#include "klueng/core/design/dxf_import.h"

namespace klueng::gui {

namespace {

using core::design::PartDesign;

// One change of the design: the whole design before and after (small, and undo is exact).
class DesignCommand : public QUndoCommand {
 public:
  DesignCommand(PartDesign before, PartDesign after, const QString& text, std::function<void(const PartDesign&)> apply)
      : QUndoCommand(text), before_(std::move(before)), after_(std::move(after)), apply_(std::move(apply)) {}
  void undo() override { apply_(before_); }
  void redo() override { apply_(after_); }

 private:
  PartDesign before_, after_;
  std::function<void(const PartDesign&)> apply_;
};

QString message(const core::Diagnostic& d) {
  return QString::fromStdString(core::formatMessage(d, Language::coreLang(), core::Surface::Gui));
}

// What a new part looks like before anything is drawn: a plain bar turned down 5 mm over half its length.
PartDesign starter(const core::io::JobHeader& job) {
  PartDesign p;
  const double d = job.diameterMm() > 12.0 ? job.diameterMm() - 6.0 : job.diameterMm();
  p.outside = {{core::design::StepKind::Cylinder, d, std::max(5.0, std::round(job.lengthMm() / 3.0)),
                core::design::EdgeBreak::Chamfer, 1.0}};
  return p;
}

}  // namespace

PartDesignerDialog::PartDesignerDialog(const core::machine::MachineSetup& setup, core::gcode::Dialect dialect,
                                       const core::io::JobHeader& job, QWidget* parent)
    : QDialog(parent), setup_(setup), job_(job), model_(new DesignTableModel(this)), undo_(new QUndoStack(this)) {
  setObjectName(QStringLiteral("partDesigner"));
  speeds_ = core::design::readCuttingSpeeds().value.value_or(std::vector<core::design::CuttingSpeed>{});
  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(150);
  connect(debounce_, &QTimer::timeout, this, &PartDesignerDialog::startLoop);
  connect(&watcher_, &QFutureWatcher<std::shared_ptr<const core::design::DesignLoop>>::finished, this, [this] {
    running_ = false;
    loop_ = watcher_.result();
    cut_ = loop_ && loop_->cut ? std::shared_ptr<const core::cut::Stock>(loop_, loop_->cut.get()) : nullptr;
    showLoop();
    if (pending_) {
      pending_ = false;
      startLoop();
      return;
    }
    emit loopFinished();
  });
  buildUi();
  setDialect(dialect);
  connect(model_, &DesignTableModel::editRequested, this,
          [this](const PartDesign& after, const QString& what) { setDesign(after, what); });
  PartDesign first = starter(job_);
  first.name = job_.part.empty() ? "Part" : job_.part;
  apply(first);
  setJobHeader(job_);
}

PartDesignerDialog::~PartDesignerDialog() { watcher_.waitForFinished(); }

const PartDesign& PartDesignerDialog::design() const { return model_->design(); }

bool PartDesignerDialog::isRunning() const { return running_ || pending_ || debounce_->isActive(); }

core::gcode::Dialect PartDesignerDialog::dialect() const {
  return static_cast<core::gcode::Dialect>(dialect_->currentData().toInt());
}

void PartDesignerDialog::setDialect(core::gcode::Dialect dialect) {
  dialect_->setCurrentIndex(dialect_->findData(static_cast<int>(dialect)));
}

void PartDesignerDialog::setMachineSetup(const core::machine::MachineSetup& setup) {
  setup_ = setup;
  scheduleLoop();
}

void PartDesignerDialog::setJobHeader(const core::io::JobHeader& job) {
  job_ = job;
  const std::string row = core::design::cuttingSpeedRow(job.material, speeds_);
  if (!row.empty()) material_->setCurrentIndex(material_->findData(QString::fromStdString(row)));
  PartDesign d = design();
  d.stockDiameter = job.diameterMm();
  d.stockLength = job.lengthMm();
  d.stockBore = job.boreMm();
  if (!job.part.empty()) d.name = job.part;
  model_->setDesign(d);  // the bar is not part of the drawing's undo history
  barLabel_->setText(tr("Bar from Job details: %1, %2")
                         .arg(QString::fromStdString(core::io::stockSizeText(job)),
                              job.material.empty() ? tr("no material given") : QString::fromStdString(job.material)));
  scheduleLoop();
}

void PartDesignerDialog::setDesign(const PartDesign& design, const QString& what) {
  PartDesign after = design;
  after.stockDiameter = job_.diameterMm();
  after.stockLength = job_.lengthMm();
  after.stockBore = job_.boreMm();
  undo_->push(new DesignCommand(this->design(), after, what, [this](const PartDesign& d) { apply(d); }));
}

void PartDesignerDialog::apply(const PartDesign& design) {
  const int row = table_ && table_->currentIndex().isValid() ? table_->currentIndex().row() : -1;
  const int column = row >= 0 ? table_->currentIndex().column() : 0;
  model_->setDesign(design);
  if (partOff_ && partOff_->isChecked() != design.partOff) {
    const QSignalBlocker quiet(partOff_);
    partOff_->setChecked(design.partOff);
  }
  if (row >= 0 && model_->rowCount() > 0)
    table_->setCurrentIndex(model_->index(std::min(row, model_->rowCount() - 1), column));
  scheduleLoop();
}

core::design::GenerateOptions PartDesignerDialog::options() const {
  core::design::GenerateOptions o;
  o.dialect = dialect();
  o.lang = Language::coreLang();
  o.machine = setup_.machine;
  o.speeds = speeds_;
  return o;
}

void PartDesignerDialog::scheduleLoop() {
  if (debounce_) debounce_->start();
}

void PartDesignerDialog::startLoop() {
  if (running_) {
    pending_ = true;  // once this run is shown, run the latest design
    return;
  }
  running_ = true;
  PartDesign d = design();
  d.material = material_->currentData().toString().toStdString();
  d.toolMaterial = toolMaterial_->currentData().toString().toStdString();
  const core::design::GenerateOptions o = options();
  const core::machine::MachineSetup setup = setup_;
  watcher_.setFuture(QtConcurrent::run([d, o, setup]() -> std::shared_ptr<const core::design::DesignLoop> {
    return std::make_shared<core::design::DesignLoop>(core::design::runDesignLoop(d, o, setup));
  }));
}

QString PartDesignerDialog::verdict() const {
  if (!loop_) return {};
  if (!loop_->program) return tr("This part cannot be turned this way:");
  if (!loop_->problems.empty()) return tr("The generated program does not run:");
  if (loop_->matches()) return tr("The cut part matches the drawing within 0.01 mm.");
  return tr("The cut part differs from the drawing:");
}

void PartDesignerDialog::showLoop() {
  findings_->clear();
  const QString head = verdict();
  auto* first = new QListWidgetItem(head, findings_);
  QFont bold = first->font();
  bold.setBold(true);
  first->setFont(bold);
  first->setForeground(loop_ && loop_->matches() ? QColor(0, 120, 40) : QColor(170, 30, 30));
  if (loop_) {
    for (const auto* list : {&loop_->refused, &loop_->problems, &loop_->findings})
      for (const core::Diagnostic& d : *list)
        new QListWidgetItem(QStringLiteral("%1  %2").arg(QString::fromStdString(d.code), message(d)), findings_);
  }
  createButton_->setEnabled(loop_ && loop_->program.has_value());
  preview_->show(design(), cut_);
  preview_->setMessage(loop_ && !loop_->program ? head : QString());
  view3d_->setStock(cut_);
  updateSelection();
}

void PartDesignerDialog::updateSelection() {
  const QModelIndex at = table_->currentIndex();
  if (at.isValid() && at.row() < model_->rowCount()) {
    const auto [zr, zl] = model_->zRange(at.row());
    preview_->setHighlight(zr, zl);
  } else {
    preview_->setHighlight(0.0, 1.0);
  }
  removeButton_->setEnabled(at.isValid());
  upButton_->setEnabled(at.isValid());
  downButton_->setEnabled(at.isValid());
}

void PartDesignerDialog::addRow(int kind) {
  PartDesign d = design();
  const auto k = static_cast<DesignRowKind>(kind);
  const double bar = d.stockDiameter;
  const double lastOutside = d.outside.empty() ? bar - 6.0 : d.outside.back().diameter;
  int index = 0;
  switch (k) {
    case DesignRowKind::Cylinder:
    case DesignRowKind::Taper:
    case DesignRowKind::Arc: {
      core::design::OutsideStep s{k == DesignRowKind::Cylinder ? core::design::StepKind::Cylinder
                                  : k == DesignRowKind::Taper  ? core::design::StepKind::Taper
                                                               : core::design::StepKind::Arc,
                                  std::min(bar, lastOutside + 4.0), 10.0};
      if (k == DesignRowKind::Arc) s.length = 2.0, s.radius = 2.0;
      d.outside.push_back(s);
      index = static_cast<int>(d.outside.size()) - 1;
      break;
    }
    case DesignRowKind::Bore:
    case DesignRowKind::BoreTaper: {
      const double hole = d.stockBore > 0.0 ? d.stockBore : 10.0;
      const double last = d.inside.empty() ? hole + 6.0 : std::max(hole, d.inside.back().diameter - 2.0);
      d.inside.push_back(
          {k == DesignRowKind::Bore ? core::design::StepKind::Cylinder : core::design::StepKind::Taper, last, 10.0});
      index = static_cast<int>(d.inside.size()) - 1;
      break;
    }
    case DesignRowKind::Groove: {
      const double z = d.outside.empty() ? -10.0 : -std::min(d.outside[0].length - 4.0, 10.0);
      d.grooves.push_back(
          {std::min(0.0, z), 3.0, std::max(1.0, (d.outside.empty() ? bar : d.outside[0].diameter) - 4.0)});
      index = static_cast<int>(d.grooves.size()) - 1;
      break;
    }
    case DesignRowKind::Thread:
      d.threads.push_back({0.0, d.outside.empty() ? 10.0 : std::max(3.0, d.outside[0].length - 5.0), 1.5});
      index = static_cast<int>(d.threads.size()) - 1;
      break;
  }
  setDesign(d, tr("Add %1").arg(DesignTableModel::kindName(k)));
  const int row = model_->rowOf(k, index);
  if (row >= 0) table_->setCurrentIndex(model_->index(row, DesignTableModel::Diameter));
}

void PartDesignerDialog::removeRow() {
  const QModelIndex at = table_->currentIndex();
  if (!at.isValid()) return;
  const DesignRow row = model_->rowAt(at.row());
  PartDesign d = design();
  const auto drop = [&](auto& list) { list.erase(list.begin() + row.index); };
  if (row.outsideStep())
    drop(d.outside);
  else if (row.boreStep())
    drop(d.inside);
  else if (row.kind == DesignRowKind::Groove)
    drop(d.grooves);
  else
    drop(d.threads);
  setDesign(d, tr("Remove %1").arg(DesignTableModel::kindName(row.kind)));
}

void PartDesignerDialog::moveRow(int by) {
  const QModelIndex at = table_->currentIndex();
  if (!at.isValid()) return;
  const DesignRow row = model_->rowAt(at.row());
  PartDesign d = design();
  const auto swap = [&](auto& list) {
    const int to = row.index + by;
    if (to < 0 || to >= static_cast<int>(list.size())) return false;
    std::swap(list[static_cast<std::size_t>(row.index)], list[static_cast<std::size_t>(to)]);
    return true;
  };
  const bool moved = row.outsideStep()                   ? swap(d.outside)
                     : row.boreStep()                    ? swap(d.inside)
                     : row.kind == DesignRowKind::Groove ? swap(d.grooves)
                                                         : swap(d.threads);
  if (!moved) return;
  setDesign(d, by < 0 ? tr("Move up") : tr("Move down"));
  table_->setCurrentIndex(model_->index(at.row() + by, at.column()));
}

bool PartDesignerDialog::openFile(const QString& path, const QString& layer) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly) || f.size() > 64 * 1024 * 1024) {
    QMessageBox::warning(this, tr("Part designer"), tr("Cannot read %1").arg(QDir::toNativeSeparators(path)));
    return false;
  }
  const std::string text = f.readAll().toStdString();
  const std::string name = QFileInfo(path).fileName().toStdString();
  core::io::ReadResult<PartDesign> read;
  if (path.endsWith(QStringLiteral(".dxf"), Qt::CaseInsensitive)) {
    core::design::DxfImportOptions o;
    o.layer = layer.toStdString();
    o.chuckGrip = setup_.machine.chuckGrip;
    const std::vector<std::string> layers = core::design::dxfOutlineLayers(text);
    if (o.layer.empty() && layers.size() > 1 && isVisible()) {
      QStringList names;
      for (const std::string& l : layers) names << QString::fromStdString(l);
      bool ok = false;
      const QString picked =
          QInputDialog::getItem(this, tr("Import DXF"), tr("The layer of the part's outline:"), names, 0, false, &ok);
      if (!ok) return false;
      o.layer = picked.toStdString();
    }
    read = core::design::importDxf(text, name, o);
  } else {
    read = core::design::readPartDesign(text, name);
  }
  if (!read.ok()) {
    findings_->clear();
    auto* head = new QListWidgetItem(tr("%1 cannot be used:").arg(QString::fromStdString(name)), findings_);
    head->setForeground(QColor(170, 30, 30));
    for (const core::Diagnostic& d : read.diagnostics)
      new QListWidgetItem(QStringLiteral("%1  %2").arg(QString::fromStdString(d.code), message(d)), findings_);
    return false;
  }
  const PartDesign& got = *read.value;
  fileStock_[0] = got.stockDiameter;
  fileStock_[1] = got.stockLength;
  fileStock_[2] = got.stockBore;
  const bool sameBar = std::abs(got.stockDiameter - job_.diameterMm()) < 1e-6 &&
                       std::abs(got.stockLength - job_.lengthMm()) < 1e-6 &&
                       std::abs(got.stockBore - job_.boreMm()) < 1e-6;
  fileBar_->setVisible(!sameBar);
  useFileBar_->setVisible(!sameBar);
  if (!sameBar) {
    core::io::JobHeader fileJob;
    fileJob.diameter = got.stockDiameter;
    fileJob.length = got.stockLength;
    fileJob.bore = got.stockBore;
    fileBar_->setText(tr("%1 is drawn for a bar %2.")
                          .arg(QString::fromStdString(name), QString::fromStdString(core::io::stockSizeText(fileJob))));
  }
  if (material_->findData(QString::fromStdString(got.material)) >= 0)
    material_->setCurrentIndex(material_->findData(QString::fromStdString(got.material)));
  toolMaterial_->setCurrentIndex(toolMaterial_->findData(QString::fromStdString(got.toolMaterial)));
  setDesign(got, tr("Open %1").arg(QString::fromStdString(name)));
  return true;
}

bool PartDesignerDialog::saveFile(const QString& path) {
  PartDesign d = design();
  d.material = material_->currentData().toString().toStdString();
  d.toolMaterial = toolMaterial_->currentData().toString().toStdString();
  // A file the designer or a run reads (the cutting speeds, the library, tools.cfg, a tool
  // picture) is never replaced by a part: F126 (issue 42 item 2).
  if (const QString why = outputIsAnyInput(path, setupInputs(setup_)); !why.isEmpty()) {
    QMessageBox::warning(this, tr("Part designer"), tr("Cannot save %1: %2").arg(QDir::toNativeSeparators(path), why));
    return false;
  }
  // The same checked writer as programs: a read-only part file is refused, root too (issue 29).
  if (const QString why = writeFileChecked(path, core::design::writePartDesign(d)); !why.isEmpty()) {
    QMessageBox::warning(this, tr("Part designer"), tr("Cannot save %1: %2").arg(QDir::toNativeSeparators(path), why));
    return false;
  }
  undo_->setClean();
  return true;
}

void PartDesignerDialog::openDialog() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Open a part"), QString(),
                                                    tr("Parts and drawings (*.json *.dxf);;All files (*)"));
  if (!path.isEmpty()) openFile(path);
}

void PartDesignerDialog::saveDialog() {
  QString path = QFileDialog::getSaveFileName(this, tr("Save the part"),
                                              QString::fromStdString(design().name) + QStringLiteral(".json"),
                                              tr("Part files (*.json)"));
  if (path.isEmpty()) return;
  if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) path += QStringLiteral(".json");
  saveFile(path);
}

void PartDesignerDialog::changeEvent(QEvent* event) {
  QDialog::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslate();
}

}  // namespace klueng::gui
