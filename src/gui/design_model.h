#pragma once
// The part designer's table (issue 14): a part design's features one a row —
// outside cylinders, tapers and arcs, bore steps, grooves, threads — with
// the columns a drawing gives them. Edits do not change the model: they ask
// for the changed design (editRequested), which the designer pushes on its
// undo stack and sets back here.
#include <QAbstractTableModel>

#include "klueng/core/design/part_design.h"

namespace klueng::gui {

enum class DesignRowKind { Cylinder, Taper, Arc, Bore, BoreTaper, Groove, Thread };

struct DesignRow {
  DesignRowKind kind = DesignRowKind::Cylinder;
  int index = 0;  // in its list: outside, inside, grooves or threads
  bool outsideStep() const { return kind <= DesignRowKind::Arc; }
  bool boreStep() const { return kind == DesignRowKind::Bore || kind == DesignRowKind::BoreTaper; }
};

class DesignTableModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Feature, Diameter, Length, Z, Edge, Radius, Pitch, ColumnCount };

  explicit DesignTableModel(QObject* parent = nullptr);
  const core::design::PartDesign& design() const { return design_; }
  void setDesign(const core::design::PartDesign& design);

  DesignRow rowAt(int row) const { return rows_.at(static_cast<std::size_t>(row)); }
  int rowOf(DesignRowKind kind, int index) const;  // -1 when none
  // Z from the right end to the left end of a row's feature (for the preview's highlight).
  std::pair<double, double> zRange(int row) const;

  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;
  bool setData(const QModelIndex& index, const QVariant& value, int role) override;
  Qt::ItemFlags flags(const QModelIndex& index) const override;
  QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

  static QString kindName(DesignRowKind kind);
  void retranslate();

 signals:
  void editRequested(const core::design::PartDesign& after, const QString& what);

 private:
  bool editable(const DesignRow& row, int column) const;
  core::design::PartDesign design_;
  std::vector<DesignRow> rows_;
};

}  // namespace klueng::gui
