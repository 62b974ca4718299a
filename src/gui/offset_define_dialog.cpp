#include "gui/offset_define_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <algorithm>
#include <QTableWidget>
#include <QVBoxLayout>

#include "gui/file_save.h"
#include "gui/language.h"
#include "gui/tool_select_dialog.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/messages.h"
#include "render/tool_sprite.h"

namespace klueng::gui {

namespace io = core::io;

namespace {
enum Column { ColX, ColZ, ColR, ColT, ColPicture, ColumnCount };
constexpr double kMaxValue = 9999.999;
const QRegularExpression& numberPattern() {
  static const QRegularExpression re(QStringLiteral(R"(^[+-]?(\d+\.?\d*|\.\d+)$)"));
  return re;
}
QString formatValue(double v) {
  QString s = QString::number(v, 'f', 3);
  return s == QStringLiteral("-0.000") ? QStringLiteral("0.000") : s;
}
}  // namespace

OffsetDefineDialog::OffsetDefineDialog(const QString& configDir, QWidget* parent) : QDialog(parent) {
  const auto read = io::readOffsetTable(configDir.toStdString() + "/offset.cfg");
  build(read.value.value_or(io::OffsetTable{}));
  QStringList loadProblems;
  for (const auto& d : read.diagnostics)
    loadProblems << QString::fromStdString(core::formatMessage(d, Language::coreLang(), core::Surface::Gui));
  if (!loadProblems.isEmpty()) intro_->setToolTip(loadProblems.join(QLatin1Char('\n')));
}

OffsetDefineDialog::OffsetDefineDialog(const io::OffsetTable& offsets, QWidget* parent) : QDialog(parent) {
  build(offsets);
}

void OffsetDefineDialog::build(const io::OffsetTable& table) {
  intro_ = new QLabel(this);
  intro_->setWordWrap(true);
  table_ = new QTableWidget(io::kOffsetCount, ColumnCount, this);
  table_->verticalHeader()->setDefaultSectionSize(28);
  table_->setIconSize(QSize(24, 24));
  table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
  table_->horizontalHeader()->setSectionResizeMode(ColPicture, QHeaderView::ResizeToContents);
  status_ = new QLabel(this);
  status_->setWordWrap(true);
  buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(intro_);
  layout->addWidget(table_, 1);
  layout->addWidget(status_);
  layout->addWidget(buttons_);

  filling_ = true;
  for (int row = 0; row < io::kOffsetCount; ++row) {
    const io::Offset& o = table.offsets[static_cast<std::size_t>(row)];
    table_->setItem(row, ColX, new QTableWidgetItem(formatValue(o.x)));
    table_->setItem(row, ColZ, new QTableWidgetItem(formatValue(o.z)));
    table_->setItem(row, ColR, new QTableWidgetItem(formatValue(o.r)));
    table_->setItem(row, ColT, new QTableWidgetItem(QString::number(o.tip)));
    auto* picture = new QTableWidgetItem;
    picture->setFlags(Qt::ItemIsEnabled);
    table_->setItem(row, ColPicture, picture);
    for (int c = ColX; c <= ColT; ++c) table_->item(row, c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
  }
  filling_ = false;

  connect(table_, &QTableWidget::itemChanged, this, [this] {
    if (!filling_) validate();
  });
  connect(buttons_, &QDialogButtonBox::accepted, this, &OffsetDefineDialog::accept);
  connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
  retranslate();
  resize(560, 640);
}

void OffsetDefineDialog::setCell(int row, int column, const QString& text) { table_->item(row, column)->setText(text); }

QString OffsetDefineDialog::cellText(int row, int column) const { return table_->item(row, column)->text(); }

QString OffsetDefineDialog::cellError(int row, int column) const {
  const QString text = cellText(row, column).trimmed();
  if (column == ColT) {
    bool ok = false;
    const int tip = text.toInt(&ok);
    if (!ok || tip < 0 || tip > 9) return tr("the tip number must be a whole number from 0 to 9");
    return {};
  }
  if (!numberPattern().match(text).hasMatch()) return tr("'%1' is not a number").arg(text);
  const double v = text.toDouble();
  const int dot = text.indexOf(QLatin1Char('.'));
  if (dot >= 0 && text.size() - dot - 1 > 3) return tr("at most 3 decimals");
  if (std::abs(v) > kMaxValue) return tr("must lie between -9999.999 and 9999.999");
  if (column == ColR && v < 0) return tr("the nose radius must not be negative");
  return {};
}

bool OffsetDefineDialog::isValid() const { return errorText().isEmpty(); }

QString OffsetDefineDialog::errorText() const {
  const QString columns[] = {QStringLiteral("X"), QStringLiteral("Z"), QStringLiteral("R"), QStringLiteral("T")};
  for (int row = 0; row < io::kOffsetCount; ++row)
    for (int c = ColX; c <= ColT; ++c)
      if (const QString e = cellError(row, c); !e.isEmpty())
        return tr("Offset %1, %2: %3").arg(row + 1, 2, 10, QLatin1Char('0')).arg(columns[c], e);
  return {};
}

void OffsetDefineDialog::validate() {
  filling_ = true;
  for (int row = 0; row < io::kOffsetCount; ++row) {
    for (int c = ColX; c <= ColT; ++c) {
      const QString e = cellError(row, c);
      table_->item(row, c)->setBackground(e.isEmpty() ? QBrush() : QBrush(QColor(255, 205, 205)));
      table_->item(row, c)->setToolTip(e);
    }
    bool ok = false;
    const int tip = cellText(row, ColT).trimmed().toInt(&ok);
    auto* picture = table_->item(row, ColPicture);
    if (ok && tip >= 0 && tip <= 9) {
      picture->setIcon(QIcon(QPixmap::fromImage(render::tipPicture(tip, 24))));
      picture->setText(QString());
    } else {
      picture->setIcon(QIcon());
      picture->setText(QStringLiteral("?"));
    }
  }
  filling_ = false;
  const QString e = errorText();
  status_->setText(e.isEmpty() ? tr("All offsets are valid.") : e);
  status_->setStyleSheet(e.isEmpty() ? QString() : QStringLiteral("color: #b00000"));
  buttons_->button(QDialogButtonBox::Ok)->setEnabled(e.isEmpty());
}

io::OffsetTable OffsetDefineDialog::offsetTable() const {
  io::OffsetTable t;
  for (int row = 0; row < io::kOffsetCount; ++row) {
    io::Offset& o = t.offsets[static_cast<std::size_t>(row)];
    o.x = cellText(row, ColX).trimmed().toDouble();
    o.z = cellText(row, ColZ).trimmed().toDouble();
    o.r = cellText(row, ColR).trimmed().toDouble();
    o.tip = cellText(row, ColT).trimmed().toInt();
  }
  return t;
}

void OffsetDefineDialog::accept() {
  if (!isValid()) {
    QMessageBox::warning(this, windowTitle(), errorText());
    return;
  }
  const std::string text = io::formatOffsetTable(offsetTable());
  // Never write a file the loader would refuse.
  const auto check = io::parseOffsetTable(text, "offset.cfg");
  if (!check.ok()) {
    QMessageBox::warning(this, windowTitle(),
                         QString::fromStdString(
                             core::formatMessage(check.diagnostics.front(), Language::coreLang(), core::Surface::Gui)));
    return;
  }
  // Nothing is written here (issue 30 item 2): the window makes the table an undo step on
  // the setup it holds, and File ▸ Save writes offset.cfg.
  QDialog::accept();
}

void OffsetDefineDialog::retranslate() {
  setWindowTitle(tr("Offset Define"));
  intro_->setText(
      tr("Offsets 01–64: X offset (diameter, mm), Z offset (mm), nose radius R (mm) and the imaginary "
         "tool tip number T (0–9). Use offset nn with T..nn, e.g. T0101. Rows 17–64 that stay 0 0 0 0 "
         "are not written; a tool chosen from the program fills an empty row with its own R and tip."));
  table_->setHorizontalHeaderLabels({tr("X (dia.)"), tr("Z"), tr("R"), tr("Tip T"), tr("Tip")});
  // The picture column is as wide as its header ("ปลายมีด" in Thai) with room to spare, never clipped.
  QHeaderView* header = table_->horizontalHeader();
  header->setSectionResizeMode(ColPicture, QHeaderView::Fixed);
  header->resizeSection(ColPicture, std::max(48, header->fontMetrics().horizontalAdvance(tr("Tip")) + 28));
  QStringList rows;
  for (int row = 1; row <= io::kOffsetCount; ++row) rows << QStringLiteral("%1").arg(row, 2, 10, QLatin1Char('0'));
  table_->setVerticalHeaderLabels(rows);
  validate();
}

void OffsetDefineDialog::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDialog::changeEvent(event);
}

}  // namespace klueng::gui
