#include "gui/part_panel.h"

#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <cmath>

#include "gui/language.h"
#include "klueng/core/cut/comp_compare.h"
#include "klueng/core/cut/part_check.h"
#include "klueng/core/cut/part_features.h"
#include "gui/off_gui_thread.h"
#include "klueng/core/job/job.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/messages.h"
#include "render/lathe_painters.h"

namespace klueng::gui {

namespace {

using namespace klueng::core;

enum Role { kLineRole = Qt::UserRole + 1, kZLeftRole, kZRightRole, kPathRole };

QString qs(const std::string& s) { return QString::fromStdString(s); }

// The feature's profile, upper half, in scene units (y = -radius).
QPainterPath profileOf(const cut::PartFeature& f) {
  QPainterPath path;
  const int steps = f.kind == cut::FeatureKind::Arc ? 24 : 1;
  for (int k = 0; k <= steps; ++k) {
    const double z = f.zLeft + (f.zRight - f.zLeft) * k / steps;
    const QPointF p(z, -f.radiusAt(z));
    k == 0 ? path.moveTo(p) : path.lineTo(p);
  }
  return path;
}

QTreeWidgetItem* row(QTreeWidgetItem* parent, const QString& what, const QString& where, int line, double zLeft,
                     double zRight) {
  auto* item = new QTreeWidgetItem(parent, {what, where, line > 0 ? QString::number(line) : QString()});
  item->setData(0, kLineRole, line);
  item->setData(0, kZLeftRole, zLeft);
  item->setData(0, kZRightRole, zRight);
  return item;
}

}  // namespace

PartPanel::PartPanel(QWidget* parent, std::function<Source()> source)
    : QDockWidget(parent), source_(std::move(source)) {
  setObjectName(QStringLiteral("partPanel"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* bar = new QHBoxLayout;
  check_ = new QPushButton(body);
  check_->setObjectName(QStringLiteral("checkPart"));
  compare_ = new QComboBox(body);
  compare_->setObjectName(QStringLiteral("compareCompensation"));
  compare_->addItems({QString(), QString(), QString()});
  compare_->setSizeAdjustPolicy(QComboBox::AdjustToContents);  // the Thai choices are longer: never cut
  measure_ = new QPushButton(body);
  measure_->setObjectName(QStringLiteral("measure"));
  measure_->setCheckable(true);
  summary_ = new QLabel(body);
  summary_->setObjectName(QStringLiteral("partSummary"));
  summary_->setWordWrap(true);
  bar->addWidget(check_);
  bar->addWidget(compare_);
  bar->addWidget(measure_);
  bar->addWidget(summary_, 1);
  layout->addLayout(bar);
  list_ = new QTreeWidget(body);
  list_->setObjectName(QStringLiteral("partList"));
  list_->setColumnCount(4);
  list_->setAlternatingRowColors(true);
  list_->header()->setSectionResizeMode(0, QHeaderView::Stretch);
  list_->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
  list_->header()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
  list_->header()->setSectionResizeMode(3, QHeaderView::ResizeToContents);
  layout->addWidget(list_);
  setWidget(body);
  connect(check_, &QPushButton::clicked, this, &PartPanel::analyse);
  connect(measure_, &QPushButton::toggled, this, &PartPanel::measuringToggled);
  connect(compare_, &QComboBox::activated, this, [this] { analyse(); });
  connect(list_, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) { select(item); });
  connect(list_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
    const int line = item ? item->data(0, kLineRole).toInt() : 0;
    if (line > 0) emit lineActivated(line);
  });
  retranslateUi();
}

void PartPanel::invalidate() {
  if (list_->topLevelItemCount() == 0) return;
  list_->clear();
  features_ = defects_ = differences_ = nullptr;
  base_ = PartOverlay{};
  summaryMaker_ = [] { return tr("The program changed: check the part again."); };
  summary_->setText(summaryMaker_());
  emit overlayChanged(base_);
}

void PartPanel::setUnits(const core::UnitFormat& units) {
  if (units_ == units) return;
  units_ = units;
  if (features_) analyse();  // the same part, said in the new unit
}

void PartPanel::setComparison(int compare) { compare_->setCurrentIndex(std::clamp(compare, 0, 2)); }

void PartPanel::retranslateUi() {
  setWindowTitle(tr("Part"));
  check_->setText(tr("Check part"));
  check_->setToolTip(tr("Cut the program and list the finished part's features, gouges and leftovers"));
  measure_->setText(tr("Measure"));
  measure_->setToolTip(tr("Click two points on the output screen: ΔZ, ΔØ, distance and angle"));
  compare_->setItemText(0, tr("No comparison"));
  compare_->setItemText(1, tr("Compare: without G41/G42"));
  compare_->setItemText(2, tr("Compare: sharp nose (R 0)"));
  list_->setHeaderLabels({tr("Feature / finding"), tr("Where"), tr("Line"), tr("Ra (µm)")});
  if (features_) features_->setText(0, tr("Features"));
  if (defects_) defects_->setText(0, tr("Part check"));
  if (differences_) differences_->setText(0, tr("Compensation"));
}

void PartPanel::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() != QEvent::LanguageChange) return;
  retranslateUi();
  // The list and the summary are the core's sentences in the language of the
  // last check: say them again in the new one (the same program, cut again).
  if (features_)
    analyse();
  else if (summaryMaker_)
    summary_->setText(summaryMaker_());
}

void PartPanel::analyse() {
  const Source src = source_();
  const Lang lang = Language::coreLang();
  QApplication::setOverrideCursor(Qt::WaitCursor);
  list_->clear();
  features_ = defects_ = differences_ = nullptr;
  base_ = PartOverlay{};
  core::job::JobInput input;
  input.file = src.program;
  input.setup = src.setup;  // the job's tools, as the last check decided them
  input.inferTools = false;
  input.run = src.run;
  input.run.persistentVariables = nullptr;  // a look at the part must not change #500-#999
  input.folder = src.folder;
  const int comparison = compare_->currentIndex();
  // The job, its run, the part check and the comparison: on a worker thread (issue 30).
  struct Analysis {
    std::shared_ptr<const core::job::Job> job;
    cut::PartCheck check;
    cut::PartFeatures part;
    cut::CuttingData measured;  // the run's cuts: the roughness each surface got (issue 39)
    std::optional<cut::CompComparison> comparison;
  };
  const auto done = offGuiThread([input = std::move(input), comparison]() {
    auto a = std::make_shared<Analysis>();
    a->job = core::job::makeJob(input);
    const machine::Timeline* timeline = a->job->timeline();
    if (!timeline) return a;
    const core::job::Job& job = *a->job;
    const cut::CutSetup setup = cut::CutSetup::from(job.file()->header, job.setup());
    const machine::Timeline programmed = cut::programmedPath(*job.program(), job.setup(), job.input().run, *timeline);
    a->check = cut::checkPart(*timeline, programmed, setup);
    a->part = cut::partFeatures(a->check.cut);  // the part the check cut, not a second cut
    a->measured = cut::measureRun(*timeline, job.file()->header, job.setup(), job.units(), job.input().finishMarks);
    if (comparison > 0) {
      const auto with = comparison == 1 ? cut::CompareWith::NoCompensation : cut::CompareWith::SharpNose;
      a->comparison = cut::compareCompensation(*job.program(), job.setup(), job.input().run, setup, with);
    }
    return a;
  });
  if (!done->job->timeline()) {
    summaryMaker_ = [] { return tr("The program has errors: correct them, then check the part."); };
    summary_->setText(summaryMaker_());
    QApplication::restoreOverrideCursor();
    emit overlayChanged(base_);
    return;
  }
  const cut::PartCheck& check = done->check;
  const cut::PartFeatures& part = done->part;

  features_ = new QTreeWidgetItem(list_);
  for (const auto* side : {&part.outside, &part.inside})
    for (const cut::PartFeature& f : *side) {
      // The roughness its surface got from the cut that left it (theoretical, Ra = f²/32r): the
      // block in the Line column (activating the row goes there), the numbers in the tooltip.
      const std::optional<cut::SurfaceFinish> got = cut::surfaceFinishOf(done->measured, check.cut, f);
      QTreeWidgetItem* item = row(features_, qs(cut::describeFeature(f, lang, units_)),
                                  qs(cut::featureLabel(f, lang, units_)), got ? got->line : 0, f.zLeft, f.zRight);
      item->setData(0, kPathRole, QVariant::fromValue(profileOf(f)));
      if (got) {
        item->setText(3, QString::number(got->ra, 'f', 2));
        item->setToolTip(3,
                         tr("Ra %1 µm, Rz %2 µm: the theoretical roughness of line %3's cut (feed %4, nose R%5)")
                             .arg(got->ra, 0, 'f', 2)
                             .arg(got->rz, 0, 'f', 1)
                             .arg(got->line)
                             .arg(qs(units_.feed(got->feed, true)) + QLatin1Char(' ') + qs(units_.feedUnit(true, lang)),
                                  qs(units_.size(got->noseRadius, 3))));
      }
    }
  defects_ = new QTreeWidgetItem(list_);
  for (const Diagnostic& d : cut::partCheckDiagnostics(check, units_)) {
    QTreeWidgetItem* item =
        row(defects_, qs(formatMessage(d, lang, core::Surface::Gui)), QString(), d.range.line, 0.0, 0.0);
    if (d.code == codes::kPartGouge || d.code == codes::kBoreGouge) item->setForeground(0, QColor(190, 0, 0));
    if (d.code == codes::kPartLeftover || d.code == codes::kBoreLeftover) item->setForeground(0, QColor(150, 110, 0));
  }
  for (const cut::PartDefect& d : check.defects) {
    const bool gouge = d.kind == cut::DefectKind::Gouge;
    const double r = d.diameter / 2.0;
    base_.bands.push_back({d.zLeft, d.zRight, gouge ? r - d.depth : r, gouge ? r : r + d.depth,
                           gouge ? QColor(220, 0, 0) : QColor(240, 200, 0)});
  }
  QString summary = check.defects.empty() && !check.nothingCut
                        ? tr("The cut part is the part the program describes: no gouge, no leftover.")
                        : tr("%n finding(s): see Part check.", nullptr, static_cast<int>(check.defects.size()));
  if (done->comparison) {
    const auto with = comparison == 1 ? cut::CompareWith::NoCompensation : cut::CompareWith::SharpNose;
    const cut::CompComparison& c = *done->comparison;
    differences_ = new QTreeWidgetItem(list_);
    if (c.other) base_.otherOutline = render::stockShapeFromStock(*c.other).outline;
    for (const cut::CompDifference& d : c.differences) {
      row(differences_, qs(cut::describeDifference(d, *done->job->program(), with, lang, units_)),
          QStringLiteral("Z%1").arg(qs(units_.position(d.z))), d.line, d.zLeft, d.zRight);
      const double r = d.diameter / 2.0;
      base_.bands.push_back({d.zLeft, d.zRight, r, r + d.radial, QColor(255, 140, 0)});
    }
    if (!c.usesCompensation) summary += QLatin1Char(' ') + tr("The program has no G41/G42 moves.");
  }
  summaryMaker_ = nullptr;
  summary_->setText(summary);
  retranslateUi();
  list_->expandAll();
  QApplication::restoreOverrideCursor();
  emit overlayChanged(base_);
}

void PartPanel::select(QTreeWidgetItem* item) {
  PartOverlay overlay = base_;
  if (item && item->data(0, kPathRole).isValid()) overlay.highlight = item->data(0, kPathRole).value<QPainterPath>();
  emit overlayChanged(overlay);
}

}  // namespace klueng::gui
