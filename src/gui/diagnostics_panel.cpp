#include "gui/diagnostics_panel.h"

#include <QEvent>
#include <QHeaderView>
#include <QIcon>
#include <QTableView>

#include "gui/language.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

namespace {
QString fromStd(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }
}  // namespace

void DiagnosticsModel::setDiagnostics(std::vector<core::Diagnostic> diags) {
  beginResetModel();
  diags_ = std::move(diags);
  endResetModel();
}

void DiagnosticsModel::retranslate() {
  if (!diags_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

int DiagnosticsModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(diags_.size());
}
int DiagnosticsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant DiagnosticsModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const core::Diagnostic& d = diags_[static_cast<std::size_t>(index.row())];
  const core::Lang lang = Language::coreLang();
  if (role == Qt::DisplayRole) {
    switch (index.column()) {
      case SeverityColumn: return fromStd(core::severityName(d.severity, lang));
      case CodeColumn: return QString::fromStdString(d.code);
      case LineColumn: return d.range.line;
      case ColumnColumn: return d.range.column;
      case MessageColumn: return QString::fromStdString(core::formatMessage(d, lang, core::Surface::Gui));
      default: return {};
    }
  }
  if (role == Qt::DecorationRole && index.column() == SeverityColumn)
    return QIcon(core::isError(d.severity)            ? QStringLiteral(":/icons/error.svg")
                 : d.severity == core::Severity::Note ? QStringLiteral(":/icons/note.svg")
                                                      : QStringLiteral(":/icons/warning.svg"));
  if (role == Qt::ToolTipRole && index.column() == MessageColumn)
    return QString::fromStdString(core::formatMessage(d, lang, core::Surface::Gui));
  if (role == Qt::TextAlignmentRole && (index.column() == LineColumn || index.column() == ColumnColumn))
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  return {};
}

QVariant DiagnosticsModel::headerData(int section, Qt::Orientation o, int role) const {
  if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case SeverityColumn: return tr("Kind");
    case CodeColumn: return tr("Code");
    case LineColumn: return tr("Line");
    case ColumnColumn: return tr("Column");
    case MessageColumn: return tr("Message");
    default: return {};
  }
}

DiagnosticsPanel::DiagnosticsPanel(QWidget* parent) : QDockWidget(parent) {
  setObjectName(QStringLiteral("diagnosticsDock"));
  model_ = new DiagnosticsModel(this);
  view_ = new QTableView(this);
  view_->setObjectName(QStringLiteral("diagnosticsView"));
  view_->setModel(model_);
  view_->setSelectionBehavior(QAbstractItemView::SelectRows);
  view_->setSelectionMode(QAbstractItemView::SingleSelection);
  view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  view_->setAlternatingRowColors(true);
  view_->verticalHeader()->hide();
  view_->verticalHeader()->setDefaultSectionSize(view_->fontMetrics().height() + 6);
  view_->horizontalHeader()->setStretchLastSection(true);
  view_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  view_->setColumnWidth(DiagnosticsModel::SeverityColumn, 140);
  view_->setColumnWidth(DiagnosticsModel::CodeColumn, 70);
  view_->setColumnWidth(DiagnosticsModel::LineColumn, 70);
  view_->setColumnWidth(DiagnosticsModel::ColumnColumn, 70);
  setWidget(view_);
  auto jump = [this](const QModelIndex& i) {
    if (!i.isValid()) return;
    const auto& d = model_->diagnostics()[static_cast<std::size_t>(i.row())];
    emit diagnosticActivated(d.range.line, d.range.column);
  };
  connect(view_, &QTableView::clicked, this, jump);
  connect(view_, &QTableView::activated, this, jump);
  retranslateUi();
}

void DiagnosticsPanel::setDiagnostics(std::vector<core::Diagnostic> diags) {
  model_->setDiagnostics(std::move(diags));
  retranslateUi();
}

int DiagnosticsPanel::errorCount() const {
  int n = 0;
  for (const auto& d : model_->diagnostics()) n += core::isError(d.severity);
  return n;
}

int DiagnosticsPanel::warningCount() const {
  int n = 0;
  for (const auto& d : model_->diagnostics()) n += d.severity == core::Severity::Warning;
  return n;
}

void DiagnosticsPanel::retranslateUi() {
  const int errors = errorCount();
  const int warnings = warningCount();
  if (errors == 0 && warnings == 0)
    setWindowTitle(tr("Diagnostics: no errors"));
  else {
    // "1 error", never "1 errors" (Thai has one form for both).
    const QString e = errors == 1 ? tr("1 error") : tr("%1 errors").arg(errors);
    const QString w = warnings == 1 ? tr("1 warning") : tr("%1 warnings").arg(warnings);
    setWindowTitle(tr("Diagnostics: %1, %2").arg(e, w));
  }
  model_->retranslate();
}

void DiagnosticsPanel::changeEvent(QEvent* event) {
  QDockWidget::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

}  // namespace klueng::gui
