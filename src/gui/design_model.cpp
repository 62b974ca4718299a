#include "gui/design_model.h"

#include <QLocale>
#include <cmath>

#include "render/number_text.h"

namespace klueng::gui {

namespace {

using core::design::EdgeBreak;
using core::design::OutsideStep;
using core::design::StepKind;

QString mm(double v) { return render::trimmedNumber(v, 3); }

// A number typed in either locale's way ("12.5", "12,5").
std::optional<double> number(const QVariant& value) {
  QString t = value.toString().trimmed();
  t.replace(QLatin1Char(','), QLatin1Char('.'));
  bool ok = false;
  const double v = t.toDouble(&ok);
  if (!ok || !std::isfinite(v) || std::abs(v) > 10000.0) return std::nullopt;
  return v;
}

QString edgeText(const OutsideStep& s) {
  if (s.edge == EdgeBreak::Chamfer) return QStringLiteral("C") + mm(s.edgeSize);
  if (s.edge == EdgeBreak::Round) return QStringLiteral("R") + mm(s.edgeSize);
  return {};
}

}  // namespace

DesignTableModel::DesignTableModel(QObject* parent) : QAbstractTableModel(parent) {}

void DesignTableModel::setDesign(const core::design::PartDesign& design) {
  beginResetModel();
  design_ = design;
  rows_.clear();
  for (std::size_t k = 0; k < design_.outside.size(); ++k) {
    const StepKind s = design_.outside[k].kind;
    rows_.push_back({s == StepKind::Cylinder ? DesignRowKind::Cylinder
                     : s == StepKind::Taper  ? DesignRowKind::Taper
                                             : DesignRowKind::Arc,
                     static_cast<int>(k)});
  }
  for (std::size_t k = 0; k < design_.inside.size(); ++k)
    rows_.push_back({design_.inside[k].kind == StepKind::Cylinder ? DesignRowKind::Bore : DesignRowKind::BoreTaper,
                     static_cast<int>(k)});
  for (std::size_t k = 0; k < design_.grooves.size(); ++k)
    rows_.push_back({DesignRowKind::Groove, static_cast<int>(k)});
  for (std::size_t k = 0; k < design_.threads.size(); ++k)
    rows_.push_back({DesignRowKind::Thread, static_cast<int>(k)});
  endResetModel();
}

int DesignTableModel::rowOf(DesignRowKind kind, int index) const {
  const bool step = kind <= DesignRowKind::Arc, bore = kind == DesignRowKind::Bore || kind == DesignRowKind::BoreTaper;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const DesignRow& row = rows_[r];
    const bool same = step ? row.outsideStep() : bore ? row.boreStep() : row.kind == kind;
    if (same && row.index == index) return static_cast<int>(r);
  }
  return -1;
}

std::pair<double, double> DesignTableModel::zRange(int r) const {
  const DesignRow row = rowAt(r);
  const auto stepRange = [&](const std::vector<OutsideStep>& steps) {
    double z = 0.0;
    for (int k = 0; k < row.index; ++k) z -= steps[static_cast<std::size_t>(k)].length;
    return std::pair{z, z - steps[static_cast<std::size_t>(row.index)].length};
  };
  if (row.outsideStep()) return stepRange(design_.outside);
  if (row.boreStep()) return stepRange(design_.inside);
  if (row.kind == DesignRowKind::Groove) {
    const auto& g = design_.grooves[static_cast<std::size_t>(row.index)];
    return {g.z, g.z - g.width};
  }
  const auto& t = design_.threads[static_cast<std::size_t>(row.index)];
  return {t.z, t.z - t.length};
}

int DesignTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}

int DesignTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QString DesignTableModel::kindName(DesignRowKind kind) {
  switch (kind) {
    case DesignRowKind::Cylinder: return tr("Cylinder");
    case DesignRowKind::Taper: return tr("Taper");
    case DesignRowKind::Arc: return tr("Arc");
    case DesignRowKind::Bore: return tr("Bore");
    case DesignRowKind::BoreTaper: return tr("Bore taper");
    case DesignRowKind::Groove: return tr("Groove");
    case DesignRowKind::Thread: return tr("Thread");
  }
  return {};
}

bool DesignTableModel::editable(const DesignRow& row, int column) const {
  switch (column) {
    case Diameter: return row.kind != DesignRowKind::Thread;
    case Length: return true;
    case Z: return row.kind == DesignRowKind::Groove || row.kind == DesignRowKind::Thread;
    case Edge: return row.kind == DesignRowKind::Cylinder || row.kind == DesignRowKind::Bore;
    case Radius: return row.kind == DesignRowKind::Arc;
    case Pitch: return row.kind == DesignRowKind::Thread;
    default: return false;
  }
}

QVariant DesignTableModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= rowCount()) return {};
  const DesignRow row = rowAt(index.row());
  const int c = index.column();
  if (role == Qt::TextAlignmentRole && c != Feature) return int(Qt::AlignRight | Qt::AlignVCenter);
  if (role == Qt::ToolTipRole && c == Radius && row.kind == DesignRowKind::Arc)
    return tr("The arc's radius; negative for a hollow arc");
  if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
  if (c == Feature) return kindName(row.kind);
  if (row.outsideStep() || row.boreStep()) {
    const OutsideStep& s = (row.outsideStep() ? design_.outside : design_.inside)[static_cast<std::size_t>(row.index)];
    const auto [zr, zl] = zRange(index.row());
    switch (c) {
      case Diameter: return mm(s.diameter);
      case Length: return mm(s.length);
      case Z: return role == Qt::DisplayRole ? QStringLiteral("%1 … %2").arg(mm(zr), mm(zl)) : QVariant();
      case Edge: return edgeText(s);
      case Radius: return s.kind == StepKind::Arc ? mm(s.concave ? -s.radius : s.radius) : QString();
      default: return {};
    }
  }
  if (row.kind == DesignRowKind::Groove) {
    const auto& g = design_.grooves[static_cast<std::size_t>(row.index)];
    if (c == Diameter) return mm(g.diameter);
    if (c == Length) return mm(g.width);
    if (c == Z) return mm(g.z);
    return {};
  }
  const auto& t = design_.threads[static_cast<std::size_t>(row.index)];
  if (c == Diameter) {
    // M size: the cylinder under the thread (none: longer than its cylinder, E510).
    const OutsideStep* s = core::design::cylinderUnder(design_, t.z, t.z - t.length);
    return s ? QStringLiteral("M") + mm(s->diameter) : QStringLiteral("—");
  }
  if (c == Length) return mm(t.length);
  if (c == Z) return mm(t.z);
  if (c == Pitch) return mm(t.pitch);
  return {};
}

bool DesignTableModel::setData(const QModelIndex& index, const QVariant& value, int role) {
  if (role != Qt::EditRole || !index.isValid()) return false;
  const DesignRow row = rowAt(index.row());
  const int c = index.column();
  if (!editable(row, c)) return false;
  core::design::PartDesign after = design_;
  const QString text = value.toString().trimmed();
  if (c == Edge) {
    OutsideStep& s = (row.outsideStep() ? after.outside : after.inside)[static_cast<std::size_t>(row.index)];
    if (text.isEmpty() || text == QStringLiteral("0") || text == QStringLiteral("-")) {
      s.edge = EdgeBreak::None;
      s.edgeSize = 0.0;
    } else {
      const QChar letter = text.at(0).toUpper();
      const auto size = number(text.mid(1));
      if ((letter != QLatin1Char('C') && letter != QLatin1Char('R')) || !size || *size <= 0.0) return false;
      s.edge = letter == QLatin1Char('C') ? EdgeBreak::Chamfer : EdgeBreak::Round;
      s.edgeSize = *size;
    }
  } else {
    const auto v = number(value);
    if (!v) return false;
    const bool mayBeNegative = c == Z || c == Radius;
    if (!mayBeNegative && *v <= 0.0) return false;
    if (c == Z && *v > 0.0) return false;
    if (row.outsideStep() || row.boreStep()) {
      OutsideStep& s = (row.outsideStep() ? after.outside : after.inside)[static_cast<std::size_t>(row.index)];
      if (c == Diameter) s.diameter = *v;
      if (c == Length) s.length = *v;
      if (c == Radius) {
        if (*v == 0.0) return false;
        s.radius = std::abs(*v);
        s.concave = *v < 0.0;
      }
    } else if (row.kind == DesignRowKind::Groove) {
      auto& g = after.grooves[static_cast<std::size_t>(row.index)];
      if (c == Diameter) g.diameter = *v;
      if (c == Length) g.width = *v;
      if (c == Z) g.z = *v;
    } else {
      auto& t = after.threads[static_cast<std::size_t>(row.index)];
      if (c == Length) t.length = *v;
      if (c == Z) t.z = *v;
      if (c == Pitch) t.pitch = *v;
    }
  }
  emit editRequested(
      after, tr("Edit %1 %2").arg(kindName(row.kind), headerData(c, Qt::Horizontal, Qt::DisplayRole).toString()));
  return true;
}

Qt::ItemFlags DesignTableModel::flags(const QModelIndex& index) const {
  if (!index.isValid()) return Qt::NoItemFlags;
  Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
  if (editable(rowAt(index.row()), index.column())) f |= Qt::ItemIsEditable;
  return f;
}

QVariant DesignTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal) return {};
  if (role == Qt::ToolTipRole) {
    switch (section) {
      case Diameter: return tr("Diameter, mm (a taper's or arc's at its left end; a groove's at its bottom)");
      case Length: return tr("Length along Z, mm (a groove's width)");
      case Z: return tr("Z of a groove's right wall or a thread's right end; the steps' Z are worked out");
      case Edge:
        return tr("The right-hand corner: C3 is a 45° chamfer of 3 mm, R2 a round of 2 mm; empty for a sharp corner");
      case Radius: return tr("An arc's radius, mm: positive bulges out of the part, negative is hollow");
      case Pitch: return tr("A thread's pitch, mm (ISO metric)");
      default: return {};
    }
  }
  if (role != Qt::DisplayRole) return {};
  switch (section) {
    case Feature: return tr("Feature");
    case Diameter: return tr("Ø mm");
    case Length: return tr("Length");
    case Z: return tr("Z");
    case Edge: return tr("Corner");
    case Radius: return tr("Arc R");
    case Pitch: return tr("Pitch");
    default: return {};
  }
}

void DesignTableModel::retranslate() {
  emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
  if (!rows_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

}  // namespace klueng::gui
