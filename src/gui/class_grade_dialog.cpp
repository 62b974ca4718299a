#include "gui/class_grade_dialog.h"

#include "klueng/core/messages.h"

#include <algorithm>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtConcurrent/QtConcurrentRun>
#include <cstdlib>
#include <memory>
#include <optional>

#include "gui/file_save.h"
#include "gui/language.h"
#include "klueng/core/design/dxf_import.h"
#include "klueng/core/design/part_design.h"
#include "klueng/core/io/program_file.h"
#include "render/class_pdf_cells.h"

// The class report's painter (render/class_report.cpp, also in the CLI's klueng-png.so).
extern "C" int klueng_class_pdf(const KluengClassPdf* in, char** bytes, std::size_t* size, char* error,
                                std::size_t errorSize);

namespace klueng::gui {

namespace {

enum Column {
  kProgram,
  kResult,
  kErrors,
  kAlarm,
  kCycleTime,
  kLeftover,
  kGouge,
  kDrawing,
  kCutting,
  kTouchOff,
  kColumns
};

// The drawing's toleranced dimensions, or nullopt with the reasons in the UI language.
std::optional<std::vector<core::cut::DrawnDimension>> readDrawing(const QString& path, const std::string& general,
                                                                  double chuckGrip, const QString& layer,
                                                                  QString* why) {
  const std::string file = path.toStdString();
  const core::Lang lang = Language::coreLang();
  const auto fail = [&](const std::vector<core::Diagnostic>& diagnostics) {
    QStringList lines;
    for (const core::Diagnostic& d : diagnostics)
      if (core::isError(d.severity)) lines << QString::fromStdString(core::formatMessage(d, lang));
    *why = lines.join(QLatin1Char('\n'));
    return std::nullopt;
  };
  const auto read = core::design::readPartFile(file);
  if (!read.ok()) return fail(read.diagnostics);
  core::design::DxfImportOptions dxf;
  dxf.chuckGrip = chuckGrip;
  dxf.layer = layer.toStdString();
  const auto part = path.endsWith(QStringLiteral(".dxf"), Qt::CaseInsensitive)
                        ? core::design::importDxf(*read.value, file, dxf)
                        : core::design::readPartDesign(*read.value, file);
  if (!part.ok()) return fail(part.diagnostics);
  auto dims = core::design::drawnDimensions(*part.value, general);
  if (dims.empty()) {
    *why = ClassGradeDialog::tr(
               "The drawing %1 has no toleranced dimension. Give tolerances in a part file (JSON; a "
               "DXF drawing's dimension texts are not read) or choose a general tolerance.")
               .arg(QFileInfo(path).fileName());
    return std::nullopt;
  }
  return dims;
}

}  // namespace

ClassGradeDialog::ClassGradeDialog(const core::machine::MachineSetup& setup, core::gcode::Dialect dialect,
                                   const QString& reference, QWidget* parent)
    : QDialog(parent), setup_(setup), dialect_(dialect) {
  setObjectName(QStringLiteral("classGradeDialog"));
  folder_ = new QLineEdit(this);
  reference_ = new QLineEdit(reference, this);
  drawing_ = new QLineEdit(this);
  drawing_->setObjectName(QStringLiteral("drawingEdit"));
  browseFolder_ = new QPushButton(this);
  browseReference_ = new QPushButton(this);
  browseDrawing_ = new QPushButton(this);
  general_ = new QComboBox(this);
  general_->setObjectName(QStringLiteral("generalTolerance"));
  for (const char* c : {"", "f", "m", "c", "v"}) general_->addItem(QString(), QString::fromLatin1(c));
  tolerance_ = new QDoubleSpinBox(this);
  tolerance_->setRange(0.0, 10.0);
  tolerance_->setDecimals(3);
  tolerance_->setSingleStep(0.01);
  tolerance_->setValue(0.05);
  gradeButton_ = new QPushButton(this);
  gradeButton_->setObjectName(QStringLiteral("gradeButton"));
  saveButton_ = new QPushButton(this);
  saveButton_->setEnabled(false);
  pdfButton_ = new QPushButton(this);
  pdfButton_->setObjectName(QStringLiteral("pdfButton"));
  pdfButton_->setEnabled(false);
  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  table_ = new QTableWidget(0, kColumns, this);
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->setSelectionMode(QAbstractItemView::SingleSelection);
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setColumnHidden(kTouchOff, true);  // until a graded program asks for the setup exercise
  table_->setWordWrap(true);                 // the touch-off lines wrap in the room left (showRows)
  details_ = new QTableWidget(0, 5, this);
  details_->setObjectName(QStringLiteral("dimensionTable"));
  details_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  details_->horizontalHeader()->setStretchLastSection(true);
  details_->verticalHeader()->hide();
  details_->hide();

  const auto row = [this](QLineEdit* edit, QPushButton* browse) {
    auto* layout = new QHBoxLayout;
    layout->addWidget(edit, 1);
    layout->addWidget(browse);
    return layout;
  };
  form_ = new QFormLayout;
  // Labels texted in retranslate(), row by row.
  form_->addRow(new QLabel(this), row(folder_, browseFolder_));
  form_->addRow(new QLabel(this), row(reference_, browseReference_));
  form_->addRow(new QLabel(this), tolerance_);
  form_->addRow(new QLabel(this), row(drawing_, browseDrawing_));
  form_->addRow(new QLabel(this), general_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  buttons->addButton(gradeButton_, QDialogButtonBox::ActionRole);
  buttons->addButton(saveButton_, QDialogButtonBox::ActionRole);
  buttons->addButton(pdfButton_, QDialogButtonBox::ActionRole);
  auto* split = new QSplitter(Qt::Vertical, this);
  split->addWidget(table_);
  split->addWidget(details_);
  split->setChildrenCollapsible(false);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form_);
  layout->addWidget(split, 1);
  layout->addWidget(summary_);
  layout->addWidget(buttons);

  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(gradeButton_, &QPushButton::clicked, this, &ClassGradeDialog::grade);
  connect(browseFolder_, &QPushButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Students' programs"), folder_->text());
    if (!dir.isEmpty()) folder_->setText(dir);
  });
  connect(browseReference_, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("Reference program"), reference_->text());
    if (!file.isEmpty()) reference_->setText(file);
  });
  connect(browseDrawing_, &QPushButton::clicked, this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, tr("The teacher's drawing"),
                                                      drawing_->text().isEmpty() ? folder_->text() : drawing_->text(),
                                                      tr("Parts and drawings (*.json *.dxf);;All files (*)"));
    if (!file.isEmpty()) drawing_->setText(file);
  });
  connect(saveButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save the grades"), folder_->text() + QStringLiteral("/grades.csv"), tr("CSV files (*.csv)"));
    QString why;
    if (!path.isEmpty() && !saveCsv(path, &why))
      QMessageBox::warning(this, windowTitle(),
                           tr("\"%1\" could not be written.").arg(path) + QStringLiteral("\n\n") + why);
  });
  connect(pdfButton_, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save the grades as PDF"), folder_->text() + QStringLiteral("/grades.pdf"), tr("PDF files (*.pdf)"));
    QString why;
    if (!path.isEmpty() && !savePdf(path, &why))
      QMessageBox::warning(this, windowTitle(),
                           tr("\"%1\" could not be written.").arg(path) + QStringLiteral("\n\n") + why);
  });
  connect(table_, &QTableWidget::cellDoubleClicked, this, [this](int row, int) {
    if (row >= 0 && row < static_cast<int>(rows_.size()))
      emit openProgram(QString::fromStdString(rows_[static_cast<std::size_t>(row)].path));
  });
  connect(table_, &QTableWidget::currentCellChanged, this, [this](int row) { showDetails(row); });
  connect(&watcher_, &QFutureWatcher<std::vector<core::job::ClassRow>>::finished, this, [this] {
    rows_ = watcher_.result();
    noteShown_ = false;
    showRows();
    gradeButton_->setEnabled(true);
    setCursor(Qt::ArrowCursor);
    emit finished();
  });
  retranslate();
  resize(1000, 640);
}

void ClassGradeDialog::setFolder(const QString& folder) { folder_->setText(folder); }
void ClassGradeDialog::setReference(const QString& path) { reference_->setText(path); }
void ClassGradeDialog::setDrawing(const QString& path) { drawing_->setText(path); }
void ClassGradeDialog::setGeneralTolerance(const QString& isoClass) {
  general_->setCurrentIndex(std::max(0, general_->findData(isoClass)));
}
void ClassGradeDialog::setTolerance(double mm) { tolerance_->setValue(mm); }

void ClassGradeDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

void ClassGradeDialog::retranslate() {
  setWindowTitle(tr("Grade a class"));
  for (QPushButton* b : {browseFolder_, browseReference_, browseDrawing_}) b->setText(tr("Browse..."));
  // The form's rows in order: folder, reference, tolerance, drawing, general tolerance.
  const QStringList texts = {tr("Students' programs (folder):"), tr("Reference program (optional):"),
                             tr("Tolerance on the diameter:"), tr("Drawing with tolerances (JSON/DXF, optional):"),
                             tr("General tolerance (ISO 2768-1):")};
  for (int i = 0; i < form_->rowCount() && i < texts.size(); ++i)
    if (auto* item = form_->itemAt(i, QFormLayout::LabelRole))
      if (auto* l = qobject_cast<QLabel*>(item->widget())) l->setText(texts[i]);
  tolerance_->setSuffix(tr(" mm"));
  general_->setItemText(0, tr("none: only the drawing's own tolerances"));
  general_->setItemText(1, tr("f (fine)"));
  general_->setItemText(2, tr("m (medium)"));
  general_->setItemText(3, tr("c (coarse)"));
  general_->setItemText(4, tr("v (very coarse)"));
  gradeButton_->setText(tr("Grade"));
  saveButton_->setText(tr("Save CSV..."));
  pdfButton_->setText(tr("Save PDF..."));
  table_->setHorizontalHeaderLabels({tr("Program"), tr("Result"), tr("Errors"), tr("Alarm"), tr("Cycle time (s)"),
                                     tr("Leftover (mm)"), tr("Gouge (mm)"), tr("Drawing"), tr("Cutting data"),
                                     tr("Touch-off")});
  details_->setHorizontalHeaderLabels(
      {tr("Dimension"), tr("Tolerance"), tr("Limits (mm)"), tr("Measured (mm)"), tr("Result")});
  // Every header whole in both languages ("เวลาทำงาน (วินาที)" is wider than a default column).
  table_->resizeColumnsToContents();
  details_->resizeColumnsToContents();
  if (!rows_.empty() && !noteShown_) showRows();  // the verdicts and the summary in the new language
}

void ClassGradeDialog::grade() {
  if (watcher_.isRunning()) return;
  const std::string folder = folder_->text().toStdString();
  const std::string reference = reference_->text().trimmed().toStdString();
  const double tolerance = tolerance_->value();
  core::job::GradeAgainst against;
  against.tolerance = tolerance;
  const QString drawing = drawing_->text().trimmed();
  if (reference.empty() && drawing.isEmpty()) {
    noteShown_ = true;
    summary_->setText(tr("Choose a reference program or a drawing with tolerances to grade against."));
    return;
  }
  if (!drawing.isEmpty()) {
    // A DXF with lines on several layers: ask which holds the outline, as the Part Designer does.
    if (drawing.endsWith(QStringLiteral(".dxf"), Qt::CaseInsensitive) && drawing != layerOf_ && isVisible()) {
      layer_.clear();
      const auto text = core::design::readPartFile(drawing.toStdString());
      const std::vector<std::string> layers =
          text.ok() ? core::design::dxfOutlineLayers(*text.value) : std::vector<std::string>{};
      if (layers.size() > 1) {
        QStringList names;
        for (const std::string& l : layers) names << QString::fromStdString(l);
        bool ok = false;
        layer_ =
            QInputDialog::getItem(this, windowTitle(), tr("The layer of the part's outline:"), names, 0, false, &ok);
        if (!ok) return;
        layerOf_ = drawing;
      }
    }
    QString why;
    auto dims = readDrawing(drawing, general_->currentData().toString().toStdString(), setup_.machine.chuckGrip,
                            drawing == layerOf_ ? layer_ : QString(), &why);
    if (!dims) {
      noteShown_ = true;
      summary_->setText(why);
      return;
    }
    against.drawingPath = drawing.toStdString();
    against.drawing = std::move(*dims);
    against.hasDrawing = true;
  }
  gradedReference_ = QString::fromStdString(reference);
  gradedDrawing_ = drawing;
  gradedTolerance_ = tolerance;
  core::job::JobInput request;  // each student's path is set by the grading
  request.run.dialect = dialect_;
  request.stations = setup_.tools.stations;
  request.setup = setup_;
  request.programMachine = true;  // a program that names its machine is graded on it (issue 27)
  gradeButton_->setEnabled(false);
  setCursor(Qt::BusyCursor);
  summary_->setText(tr("Grading..."));
  watcher_.setFuture(
      QtConcurrent::run([folder, reference, against, request]() mutable -> std::vector<core::job::ClassRow> {
        core::job::GradedProgram ref;
        if (!reference.empty()) {
          ref = core::job::gradeProgram(reference, request);
          if (!ref.part) return {};
          against.referencePath = reference;
          against.reference = &*ref.part;
        }
        return core::job::gradeClass(folder, against, request);
      }));
}

void ClassGradeDialog::showRows() {
  const bool drawing = !gradedDrawing_.isEmpty(), reference = !gradedReference_.isEmpty();
  table_->setColumnHidden(kLeftover, !reference);
  table_->setColumnHidden(kGouge, !reference);
  table_->setColumnHidden(kDrawing, !drawing);
  // The setup exercise (issue 31): shown when a program or the reference says the offsets are unknown.
  table_->setColumnHidden(kTouchOff, std::none_of(rows_.begin(), rows_.end(),
                                                  [](const core::job::ClassRow& r) { return r.touchOff.asked; }));
  details_->setVisible(drawing);
  table_->setRowCount(static_cast<int>(rows_.size()));
  int passed = 0;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const core::job::ClassRow& r = rows_[i];
    const int row = static_cast<int>(i);
    passed += r.pass ? 1 : 0;
    auto set = [this, row](int column, const QString& text) {
      table_->setItem(row, column, new QTableWidgetItem(text));
    };
    set(kProgram, QString::fromStdString(r.file));
    set(kResult, r.pass ? tr("pass") : tr("fail"));
    table_->item(row, kResult)->setForeground(r.pass ? QColor(0, 120, 0) : QColor(190, 0, 0));
    set(kErrors, r.graded.errors > 0
                     ? QStringLiteral("%1 (%2)").arg(r.graded.errors).arg(QString::fromStdString(r.graded.firstError))
                     : QStringLiteral("0"));
    set(kAlarm, QString::fromStdString(r.graded.alarm));
    set(kCycleTime, r.graded.errors == 0 ? QString::number(r.graded.cycleTime, 'f', 1) : QString());
    // The size, and where when there is any.
    auto where = [](double mm, double z) {
      return mm > 0.0 ? QStringLiteral("%1 (Z%2)").arg(mm, 0, 'f', 3).arg(z, 0, 'f', 2) : QString::number(mm, 'f', 3);
    };
    set(kLeftover, r.compared ? where(r.deviation.leftover, r.deviation.leftoverZ) : QString());
    set(kGouge, r.compared ? where(r.deviation.gouge, r.deviation.gougeZ) : QString());
    int in = 0;
    for (const core::cut::InspectedDimension& d : r.inspection) in += d.in() ? 1 : 0;
    set(kDrawing, drawing ? tr("%1 of %2 in tolerance").arg(in).arg(r.inspection.size()) : QString());
    // The teacher's cutting-data warnings (issue 39): their codes and lines; the messages in the tooltip.
    QString cutting, cuttingTip;
    for (const core::Diagnostic& w : r.graded.cuttingWarnings) {
      cutting += (cutting.isEmpty() ? QString() : QStringLiteral(", ")) +
                 tr("%1 line %2").arg(QString::fromStdString(w.code)).arg(w.range.line);
      cuttingTip += (cuttingTip.isEmpty() ? QString() : QStringLiteral("\n")) +
                    tr("line %1: %2")
                        .arg(w.range.line)
                        .arg(QString::fromStdString(core::formatMessage(w, Language::coreLang(), core::Surface::Gui)));
    }
    set(kCutting, r.graded.errors == 0 && r.graded.alarm.empty() && cutting.isEmpty() ? tr("none") : cutting);
    table_->item(row, kCutting)->setToolTip(cuttingTip);
    if (!cutting.isEmpty()) table_->item(row, kCutting)->setForeground(QColor(160, 100, 0));
    // Each tool's entered offsets against the true ones, one tool a line in the tooltip.
    const QString touch =
        QString::fromStdString(core::job::touchOffText(r.touchOff, gradedTolerance_, Language::coreLang()));
    set(kTouchOff, touch);
    table_->item(row, kTouchOff)->setToolTip(QString(touch).replace(QStringLiteral("; "), QStringLiteral("\n")));
    if (r.touchOff.asked)
      table_->item(row, kTouchOff)->setForeground(r.touchOff.pass() ? QColor(0, 120, 0) : QColor(190, 0, 0));
  }
  table_->resizeColumnsToContents();
  if (!table_->isColumnHidden(kTouchOff)) {
    // The touch-off lines take the room the other columns leave and wrap there (a line per tool
    // can be long, in Thai more so), instead of running off the dialog.
    int used = 0;
    for (int c = 0; c < kTouchOff; ++c)
      if (!table_->isColumnHidden(c)) used += table_->columnWidth(c);
    table_->setColumnWidth(kTouchOff, std::max(240, table_->viewport()->width() - used));
    table_->resizeRowsToContents();
  }
  saveButton_->setEnabled(!rows_.empty());
  pdfButton_->setEnabled(!rows_.empty());
  summary_->setText(rows_.empty()
                        ? (reference ? tr("No programs graded: is the reference a program that runs to its end?")
                                     : tr("No programs graded: the folder has no program files."))
                        : tr("%1 programs: %2 pass, %3 fail")
                              .arg(rows_.size())
                              .arg(passed)
                              .arg(static_cast<int>(rows_.size()) - passed));
  const int current = table_->currentRow();
  if (drawing && !rows_.empty() && current < 0)
    table_->selectRow(0);
  else
    showDetails(current);
}

void ClassGradeDialog::showDetails(int row) {
  if (row < 0 || row >= static_cast<int>(rows_.size())) {
    details_->setRowCount(0);
    return;
  }
  const core::Lang lang = Language::coreLang();
  const auto& inspection = rows_[static_cast<std::size_t>(row)].inspection;
  details_->setRowCount(static_cast<int>(inspection.size()));
  for (std::size_t i = 0; i < inspection.size(); ++i) {
    const core::cut::InspectedDimension& d = inspection[i];
    const int at = static_cast<int>(i);
    auto set = [this, at](int column, const QString& text) {
      details_->setItem(at, column, new QTableWidgetItem(text));
    };
    set(0, QString::fromStdString(core::cut::dimensionLabel(d.drawn, lang)));
    set(1, QString::fromStdString(core::cut::toleranceLabel(d.drawn.tolerance)));
    set(2, QStringLiteral("%1 – %2").arg(d.lowerLimit(), 0, 'f', 3).arg(d.upperLimit(), 0, 'f', 3));
    set(3, d.measured ? QString::number(*d.measured, 'f', 3) : QStringLiteral("–"));
    set(4, d.verdict == core::cut::Verdict::In    ? tr("in tolerance")
           : d.verdict == core::cut::Verdict::Out ? tr("out of tolerance")
                                                  : tr("not on the part"));
    details_->item(at, 4)->setForeground(d.in() ? QColor(0, 120, 0) : QColor(190, 0, 0));
  }
  details_->resizeColumnsToContents();
}

bool ClassGradeDialog::saveCsv(const QString& path, QString* why) {
  // A graded program, the reference or the drawing is never the CSV's name (issue 29).
  QString refused = outputIsInput(path, reference_->text());
  if (refused.isEmpty() && !gradedDrawing_.isEmpty()) refused = outputIsInput(path, gradedDrawing_);
  for (const core::job::ClassRow& row : rows_)
    if (refused.isEmpty()) refused = outputIsInput(path, QString::fromStdString(row.path));
  if (refused.isEmpty()) refused = outputIsAnyInput(path, setupInputs(setup_));  // the setup too (issue 42)
  if (refused.isEmpty()) refused = writeFileChecked(path, core::job::classCsv(rows_, !gradedDrawing_.isEmpty()));
  if (why) *why = refused;
  return refused.isEmpty();
}

bool ClassGradeDialog::savePdf(const QString& path, QString* why) {
  QString refused = outputIsInput(path, reference_->text());
  if (refused.isEmpty() && !gradedDrawing_.isEmpty()) refused = outputIsInput(path, gradedDrawing_);
  for (const core::job::ClassRow& row : rows_)
    if (refused.isEmpty()) refused = outputIsInput(path, QString::fromStdString(row.path));
  if (refused.isEmpty()) refused = outputIsAnyInput(path, setupInputs(setup_));  // the setup too (issue 42)
  if (refused.isEmpty()) {
    const core::Lang lang = Language::coreLang();
    const render::ClassPdfCells cells(rows_, lang, !gradedReference_.isEmpty());
    const std::string reference = QFileInfo(gradedReference_).fileName().toStdString();
    const std::string drawing = QFileInfo(gradedDrawing_).fileName().toStdString();
    KluengClassPdf in{};
    in.thai = lang == core::Lang::Th ? 1 : 0;
    in.reference = reference.c_str();
    in.tolerance = gradedTolerance_;
    cells.into(in);
    in.dialect = static_cast<int>(dialect_);
    in.drawing = gradedDrawing_.isEmpty() ? nullptr : drawing.c_str();
    in.hasReference = gradedReference_.isEmpty() ? 0 : 1;
    char* bytes = nullptr;
    std::size_t size = 0;
    char reason[512] = {0};
    if (!klueng_class_pdf(&in, &bytes, &size, reason, sizeof reason)) {
      refused = QString::fromUtf8(reason);
    } else {
      const std::unique_ptr<char, decltype(&std::free)> owned(bytes, &std::free);
      refused = writeFileChecked(path, std::string_view(bytes, size));
    }
  }
  if (why) *why = refused;
  return refused.isEmpty();
}

}  // namespace klueng::gui
