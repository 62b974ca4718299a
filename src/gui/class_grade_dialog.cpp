#include "gui/class_grade_dialog.h"

#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>

#include "gui/file_save.h"
#include "klueng/core/io/program_file.h"

namespace klueng::gui {

ClassGradeDialog::ClassGradeDialog(const core::machine::MachineSetup& setup, core::gcode::Dialect dialect,
                                   const QString& reference, QWidget* parent)
    : QDialog(parent), setup_(setup), dialect_(dialect) {
  setObjectName(QStringLiteral("classGradeDialog"));
  folder_ = new QLineEdit(this);
  reference_ = new QLineEdit(reference, this);
  auto* browseFolder = new QPushButton(tr("Browse..."), this);
  auto* browseReference = new QPushButton(tr("Browse..."), this);
  tolerance_ = new QDoubleSpinBox(this);
  tolerance_->setRange(0.0, 10.0);
  tolerance_->setDecimals(3);
  tolerance_->setSingleStep(0.01);
  tolerance_->setValue(0.05);
  tolerance_->setSuffix(tr(" mm"));
  gradeButton_ = new QPushButton(tr("Grade"), this);
  gradeButton_->setObjectName(QStringLiteral("gradeButton"));
  saveButton_ = new QPushButton(tr("Save CSV..."), this);
  saveButton_->setEnabled(false);
  summary_ = new QLabel(this);
  table_ = new QTableWidget(0, 7, this);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();

  auto* folderRow = new QHBoxLayout;
  folderRow->addWidget(folder_, 1);
  folderRow->addWidget(browseFolder);
  auto* referenceRow = new QHBoxLayout;
  referenceRow->addWidget(reference_, 1);
  referenceRow->addWidget(browseReference);
  auto* form = new QFormLayout;
  form->addRow(tr("Students' programs (folder):"), folderRow);
  form->addRow(tr("Reference program:"), referenceRow);
  form->addRow(tr("Tolerance on the diameter:"), tolerance_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  buttons->addButton(gradeButton_, QDialogButtonBox::ActionRole);
  buttons->addButton(saveButton_, QDialogButtonBox::ActionRole);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(table_, 1);
  layout->addWidget(summary_);
  layout->addWidget(buttons);

  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(gradeButton_, &QPushButton::clicked, this, &ClassGradeDialog::grade);
  connect(browseFolder, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Students' programs"), folder_->text());
    if (!dir.isEmpty()) folder_->setText(dir);
  });
  connect(browseReference, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Reference program"), reference_->text());
    if (!file.isEmpty()) reference_->setText(file);
  });
  connect(saveButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save the grades"), folder_->text() + QStringLiteral("/grades.csv"),
                                                      tr("CSV files (*.csv)"));
    QString why;
    if (!path.isEmpty() && !saveCsv(path, &why))
      QMessageBox::warning(this, windowTitle(), tr("\"%1\" could not be written.").arg(path) + QStringLiteral("\n\n") + why);
  });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    if (row >= 0 && row < static_cast<int>(rows_.size())) emit openProgram(QString::fromStdString(rows_[static_cast<std::size_t>(row)].path));
  });
  connect(&watcher_, &QFutureWatcher<std::vector<core::cut::ClassRow>>::finished, this, [this] {
    rows_ = watcher_.result();
    showRows();
    gradeButton_->setEnabled(true);
    setCursor(Qt::ArrowCursor);
    emit finished();
  });
  retranslate();
  resize(900, 560);
}

void ClassGradeDialog::setFolder(const QString& folder) { folder_->setText(folder); }
void ClassGradeDialog::setReference(const QString& path) { reference_->setText(path); }
void ClassGradeDialog::setTolerance(double mm) { tolerance_->setValue(mm); }

void ClassGradeDialog::retranslate() {
  setWindowTitle(tr("Grade a class"));
  table_->setHorizontalHeaderLabels({tr("Program"), tr("Result"), tr("Errors"), tr("Alarm"), tr("Cycle time (s)"),
                                     tr("Leftover (mm)"), tr("Gouge (mm)")});
}

void ClassGradeDialog::grade() {
  if (watcher_.isRunning()) return;
  const std::string folder = folder_->text().toStdString();
  const std::string reference = reference_->text().toStdString();
  const double tolerance = tolerance_->value();
  core::machine::JobFileRequest request;
  request.run.dialect = dialect_;
  request.stations = setup_.tools.stations;
  const core::machine::MachineSetup setup = setup_;
  gradeButton_->setEnabled(false);
  setCursor(Qt::BusyCursor);
  summary_->setText(tr("Grading..."));
  watcher_.setFuture(QtConcurrent::run([folder, reference, tolerance, request, setup]() -> std::vector<core::cut::ClassRow> {
    const core::cut::GradedProgram ref = core::cut::gradeProgram(reference, setup, request);
    if (!ref.part) return {};
    return core::cut::gradeClass(folder, reference, *ref.part, setup, request, tolerance);
  }));
}

void ClassGradeDialog::showRows() {
  table_->setRowCount(static_cast<int>(rows_.size()));
  int passed = 0;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const core::cut::ClassRow& r = rows_[i];
    const int row = static_cast<int>(i);
    passed += r.pass ? 1 : 0;
    auto set = [this, row](int column, const QString& text) { table_->setItem(row, column, new QTableWidgetItem(text)); };
    set(0, QString::fromStdString(r.file));
    set(1, r.pass ? tr("pass") : tr("fail"));
    table_->item(row, 1)->setForeground(r.pass ? QColor(0, 120, 0) : QColor(190, 0, 0));
    set(2, r.graded.errors > 0 ? QStringLiteral("%1 (%2)").arg(r.graded.errors).arg(QString::fromStdString(r.graded.firstError))
                               : QStringLiteral("0"));
    set(3, QString::fromStdString(r.graded.alarm));
    set(4, r.graded.errors == 0 ? QString::number(r.graded.cycleTime, 'f', 1) : QString());
    // The size, and where when there is any.
    auto where = [](double mm, double z) {
      return mm > 0.0 ? QStringLiteral("%1 (Z%2)").arg(mm, 0, 'f', 3).arg(z, 0, 'f', 2) : QString::number(mm, 'f', 3);
    };
    set(5, r.compared ? where(r.deviation.leftover, r.deviation.leftoverZ) : QString());
    set(6, r.compared ? where(r.deviation.gouge, r.deviation.gougeZ) : QString());
  }
  table_->resizeColumnsToContents();
  saveButton_->setEnabled(!rows_.empty());
  summary_->setText(rows_.empty() ? tr("No programs graded: is the reference a program that runs to its end?")
                                  : tr("%1 programs: %2 pass, %3 fail").arg(rows_.size()).arg(passed).arg(static_cast<int>(rows_.size()) - passed));
}

bool ClassGradeDialog::saveCsv(const QString& path, QString* why) {
  // A graded program or the reference is never the CSV's name (issue 29).
  QString refused = outputIsInput(path, reference_->text());
  for (const core::cut::ClassRow& row : rows_)
    if (refused.isEmpty()) refused = outputIsInput(path, QString::fromStdString(row.path));
  if (refused.isEmpty()) refused = writeFileChecked(path, core::cut::classCsv(rows_));
  if (why) *why = refused;
  return refused.isEmpty();
}

}  // namespace klueng::gui
