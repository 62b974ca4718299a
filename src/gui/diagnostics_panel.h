#pragma once
// A dock listing every diagnostic of the program (severity, code, line,
// column, message in the UI language). Clicking a row asks to jump there.
#include <QAbstractTableModel>
#include <QDockWidget>
#include <vector>

#include "klueng/core/diagnostic.h"

class QTableView;

namespace klueng::gui {

class DiagnosticsModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { SeverityColumn, CodeColumn, LineColumn, ColumnColumn, MessageColumn, ColumnCount };
  using QAbstractTableModel::QAbstractTableModel;

  void setDiagnostics(std::vector<core::Diagnostic> diags);
  const std::vector<core::Diagnostic>& diagnostics() const { return diags_; }
  // Texts follow the UI language; call after a language change.
  void retranslate();

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  QVariant headerData(int section, Qt::Orientation o, int role) const override;

 private:
  std::vector<core::Diagnostic> diags_;
};

class DiagnosticsPanel : public QDockWidget {
  Q_OBJECT
 public:
  explicit DiagnosticsPanel(QWidget* parent = nullptr);

  void setDiagnostics(std::vector<core::Diagnostic> diags);
  const std::vector<core::Diagnostic>& diagnostics() const { return model_->diagnostics(); }
  DiagnosticsModel* model() const { return model_; }
  QTableView* view() const { return view_; }
  int errorCount() const;
  int warningCount() const;

 signals:
  // File line and 1-based code-point column of the clicked diagnostic.
  void diagnosticActivated(int fileLine, int column);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  DiagnosticsModel* model_;
  QTableView* view_;
};

}  // namespace klueng::gui
