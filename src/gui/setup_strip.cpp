#include "gui/setup_strip.h"

#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QMouseEvent>
#include <QStyle>
#include <QVBoxLayout>
#include <algorithm>

#include "gui/language.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/io/tool_config.h"
#include "klueng/core/io/tool_library.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

namespace machine = core::machine;

// ---------------------------------------------------------------- SetupLine

SetupLine::SetupLine(QWidget* parent) : QLabel(parent) {
  setTextFormat(Qt::PlainText);
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  setContentsMargins(6, 1, 6, 1);
}

void SetupLine::setFullText(const QString& text) {
  full_ = text;
  setToolTip(text);
  elide();
}

void SetupLine::setClickable(bool on) {
  clickable_ = on;
  setCursor(on ? Qt::PointingHandCursor : Qt::ArrowCursor);
  setProperty("clickable", on);
}

QSize SetupLine::minimumSizeHint() const { return {20, QLabel::minimumSizeHint().height()}; }

void SetupLine::resizeEvent(QResizeEvent* event) {
  QLabel::resizeEvent(event);
  elide();
}

void SetupLine::mouseReleaseEvent(QMouseEvent* event) {
  QLabel::mouseReleaseEvent(event);
  if (clickable_ && event->button() == Qt::LeftButton && rect().contains(event->position().toPoint())) emit clicked();
}

void SetupLine::elide() {
  const int width = contentsRect().width();
  setText(width > 0 ? fontMetrics().elidedText(full_, Qt::ElideRight, width) : full_);
}

// ---------------------------------------------------------------- SetupStrip

namespace {

QString note(const core::Diagnostic& d) {
  return QString::fromStdString(core::formatMessage(d, Language::coreLang(), core::Surface::Gui));
}

// A library tool's name in the UI language; the id when the library has no such tool.
QString libraryName(const std::string& id) {
  if (const core::io::LibraryTool* t = core::io::shippedToolLibrary().find(id))
    return QString::fromStdString(Language::instance()->isThai() && !t->nameTh.empty() ? t->nameTh : t->nameEn);
  return QString::fromStdString(id);
}

// "T02 = grooving-3mm (grooving cycle G75 on line 16)" -> "grooving cycle G75 on line 16":
// the line already names the station and the tool; the whole note is in the tooltip.
QString reasonOf(const QString& text, int station, const std::string& id) {
  const QString prefix =
      QStringLiteral("T%1 = %2 (").arg(station, 2, 10, QLatin1Char('0')).arg(QString::fromStdString(id));
  if (text.startsWith(prefix) && text.endsWith(QLatin1Char(')')))
    return text.mid(prefix.size(), text.size() - prefix.size() - 1);
  return text;
}

}  // namespace

SetupStrip::SetupStrip(QWidget* parent) : QFrame(parent) {
  setObjectName(QStringLiteral("setupStrip"));
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Maximum);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 2, 0, 2);
  layout->setSpacing(0);
  title_ = new QLabel(this);
  title_->setObjectName(QStringLiteral("setupTitle"));
  title_->setWordWrap(true);
  title_->setContentsMargins(6, 1, 6, 1);
  title_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  QFont bold = title_->font();
  bold.setBold(true);
  title_->setFont(bold);
  layout->addWidget(title_);
  // SPEC 2 (ext): the user is always told where the stock came from.
  stock_ = new SetupLine(this);
  stock_->setObjectName(QStringLiteral("stockSource"));
  stock_->setClickable(true);
  connect(stock_, &SetupLine::clicked, this, &SetupStrip::stockActivated);
  layout->addWidget(stock_);
  grid_ = new QGridLayout;
  grid_->setContentsMargins(0, 0, 0, 0);
  grid_->setHorizontalSpacing(0);
  grid_->setVerticalSpacing(0);
  layout->addLayout(grid_);
  side_ = new SetupLine(this);
  side_->setObjectName(QStringLiteral("setupToolSide"));
  side_->setClickable(true);
  connect(side_, &SetupLine::clicked, this, &SetupStrip::toolSideActivated);
  layout->addWidget(side_);
  point_ = new SetupLine(this);
  point_->setObjectName(QStringLiteral("setupDecimalPoint"));
  point_->setClickable(true);
  connect(point_, &SetupLine::clicked, this, &SetupStrip::pointReadingActivated);
  layout->addWidget(point_);
  setStyleSheet(QStringLiteral(
      "klueng--gui--SetupStrip[guessed=\"true\"] { background: #fff5d6; border-bottom: 1px solid #e2cf8f; }"
      "QLabel#setupTitle { color: #7a5a00; }"
      "klueng--gui--SetupLine[clickable=\"true\"] { color: #1d4f91; }"
      "klueng--gui--SetupLine[clickable=\"true\"]:hover { color: #0b2f66; background: rgba(0,0,0,18); }"));
  setVisible(false);
}

void SetupStrip::showSetup(const std::vector<core::Diagnostic>& stockNotes, bool stockGuessed, bool plainGcode,
                           const machine::ToolInference& inference, const PointReadingShown& points) {
  stockNotes_ = stockNotes;
  stockGuessed_ = stockGuessed;
  plain_ = plainGcode;
  inference_ = inference;
  points_ = points;
  retranslateUi();
}

QString SetupStrip::stockText() const { return stock_->isHidden() ? QString() : stock_->fullText(); }

QList<int> SetupStrip::stations() const {
  QList<int> out;
  for (const Row& r : rows_) out << r.station;
  return out;
}

SetupLine* SetupStrip::stationLine(int station) const {
  for (const Row& r : rows_)
    if (r.station == station) return r.line;
  return nullptr;
}

QString SetupStrip::stationText(int station) const {
  const SetupLine* line = stationLine(station);
  return line ? line->fullText() : QString();
}

QString SetupStrip::titleText() const { return title_->isHidden() ? QString() : title_->text(); }

QString SetupStrip::sideText() const { return side_->isHidden() ? QString() : side_->fullText(); }

QString SetupStrip::pointText() const { return point_->isHidden() ? QString() : point_->fullText(); }

QString SetupStrip::pointReadingText(QString* tip) const {
  // The user's choice wins over a check still running with the old one.
  const bool whole = points_.chosen.value_or(inference_.setup.machine.calculatorInput);
  const core::Diagnostic* decided = nullptr;
  if (!points_.chosen && points_.note && points_.note->args.size() >= 3) decided = &*points_.note;
  QString text;
  if (decided) {
    const auto arg = [decided](std::size_t i) { return QString::fromStdString(decided->args[i]); };
    text = whole ? tr("Lengths without a decimal point: whole millimetres/inches — %1 on line %2 = %3 "
                      "(calculator-type input)")
                       .arg(arg(0), arg(1), arg(2))
                 : tr("Lengths without a decimal point: least input increments — %1 on line %2 = %3 "
                      "(as a standard Fanuc/Haas)")
                       .arg(arg(0), arg(1), arg(2));
  } else if (points_.chosen) {
    text = whole ? tr("Lengths without a decimal point: whole millimetres/inches, as chosen in Job details "
                      "(X30 = 30 mm)")
                 : tr("Lengths without a decimal point: least input increments, as chosen in Job details "
                      "(X30 = 0.030 mm)");
  } else if (!whole) {
    // Whole units are the usual school setting: only the other one is worth a line.
    text =
        tr("Lengths without a decimal point: least input increments, as the machine is set (machine.cfg; "
           "X30 = 0.030 mm)");
  }
  if (tip) {
    QString first = decided ? note(*decided) : QString();
    if (!first.isEmpty()) first[0] = first[0].toUpper();
    *tip = (first.isEmpty() ? QString() : first + QLatin1Char('\n')) +
           tr("A length written without a decimal point is read whole (X30 = 30 mm, calculator-type input) or in "
              "least input increments (X30 = 0.030 mm, 0.0030 in under G20), as a standard Fanuc or Haas reads it.") +
           QLatin1Char('\n') + tr("Click to change it for this file (Job details).");
  }
  return text;
}

void SetupStrip::retranslateUi() {
  // The stock: its first note in short, every note in the tooltip.
  QStringList notes;
  for (const core::Diagnostic& d : stockNotes_) notes << note(d);
  QString first = notes.isEmpty() ? QString() : notes.front();
  if (!first.isEmpty()) first[0] = first[0].toUpper();  // "Stock Ø50 x 80 mm inferred from ..."
  stock_->setFullText(first);
  stock_->setToolTip(notes.isEmpty() ? QString()
                                     : notes.join(QLatin1Char('\n')) + QLatin1Char('\n') +
                                           tr("Click to change the stock (Job details)."));
  stock_->setVisible(!notes.isEmpty());

  // The stations: what the core chose, and the stations it left on the tool table's tool as guesses.
  struct Item {
    int station;
    QString text;
    QString tip;
  };
  std::vector<Item> items;
  bool toolGuessed = false;
  for (const machine::ToolChoice& c : inference_.choices) {
    const QString full = note(c.note());
    const bool guess = c.reason != machine::ToolReason::Override;
    toolGuessed = toolGuessed || guess;
    items.push_back({c.station,
                     tr("T%1  %2 — %3")
                         .arg(c.station, 2, 10, QLatin1Char('0'))
                         .arg(libraryName(c.libraryId), reasonOf(full, c.station, c.libraryId)),
                     full + QLatin1Char('\n') + tr("Click to choose another tool for this station (Tool Select).")});
  }
  const auto& tools = inference_.setup.tools;
  for (int station = 1; station <= core::io::kMaxStations; ++station) {
    if (!tools.isGuess(station) || inference_.choiceFor(station)) continue;
    toolGuessed = true;
    const QString entry = QString::fromStdString(tools.bitmap[static_cast<std::size_t>(station - 1)]);
    const QString prefix = QString::fromLatin1(core::io::kLibraryPrefix.data(), int(core::io::kLibraryPrefix.size()));
    const QString name = entry.isEmpty()            ? tr("no tool")
                         : entry.startsWith(prefix) ? libraryName(entry.mid(prefix.size()).trimmed().toStdString())
                                                    : QFileInfo(entry).fileName();
    items.push_back({station,
                     tr("T%1  %2 — kept from the tool table (tools.cfg): nothing in the program asks for another tool")
                         .arg(station, 2, 10, QLatin1Char('0'))
                         .arg(name),
                     tr("Click to choose another tool for this station (Tool Select).")});
  }
  std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.station < b.station; });

  // Lines are re-made for a new set of stations (deleted later: one may be the line just clicked).
  const bool sameStations = std::equal(items.begin(), items.end(), rows_.begin(), rows_.end(),
                                       [](const Item& a, const Row& b) { return a.station == b.station; });
  if (!sameStations) {
    for (Row& r : rows_) {
      r.line->hide();
      grid_->removeWidget(r.line);
      r.line->deleteLater();
    }
    rows_.clear();
    // Two columns from four stations on, so a big turret does not eat the output screen.
    const int columns = items.size() >= 4 ? 2 : 1;
    const int perColumn = (static_cast<int>(items.size()) + columns - 1) / columns;
    for (std::size_t i = 0; i < items.size(); ++i) {
      auto* line = new SetupLine(this);
      line->setObjectName(QStringLiteral("setupStation%1").arg(items[i].station, 2, 10, QLatin1Char('0')));
      line->setClickable(true);
      const int station = items[i].station;
      connect(line, &SetupLine::clicked, this, [this, station] { emit stationActivated(station); });
      grid_->addWidget(line, static_cast<int>(i) % perColumn, static_cast<int>(i) / perColumn);
      rows_.push_back({station, line});
    }
  }
  for (std::size_t i = 0; i < items.size(); ++i) {
    rows_[i].line->setFullText(items[i].text);
    rows_[i].line->setToolTip(items[i].tip);
  }

  // The tool side: a program that cuts beyond the centre line has its tools there (I412),
  // unless the user said where they are for this file; in front, the usual side, needs no line.
  QString side;
  const bool beyond = points_.sideChosen.value_or(inference_.setup.machine.toolsBeyondCentre);
  if (points_.sideChosen) {
    side = beyond ? tr("Tools beyond the centre line (a rear tool post), drawn mirrored, as chosen in Job details")
                  : tr("Tools in front of the centre line, as chosen in Job details");
  } else if (beyond) {
    side = tr("Tools beyond the centre line (a rear tool post), drawn mirrored, as the machine is set (machine.cfg)");
    for (const core::Diagnostic& d : inference_.offsetNotes)
      if (d.code == core::codes::kToolsBeyondCentre)
        side = tr("Tools beyond the centre line, drawn mirrored: %1").arg(note(d));
  }
  side_->setFullText(side);
  side_->setToolTip(side.isEmpty()
                        ? QString()
                        : side + QLatin1Char('\n') + tr("Click to change the tool side for this file (Job details)."));
  side_->setVisible(!side.isEmpty());

  // Lengths without a decimal point: said when the program's numbers decided it or the reading is not the usual.
  QString pointTip;
  const QString point = pointReadingText(&pointTip);
  point_->setFullText(point);
  point_->setToolTip(pointTip);
  point_->setVisible(!point.isEmpty());
  const bool pointGuessed = !point.isEmpty() && !points_.chosen && points_.note.has_value();

  const bool guessed = plain_ && (stockGuessed_ || toolGuessed || !side.isEmpty() || pointGuessed);
  if (plain_ && (guessed || !rows_.empty()))
    title_->setText(guessed ? tr("Setup guessed from the program — check it before you run; click a line to change it")
                            : tr("Setup for this program — click a line to change it"));
  title_->setVisible(plain_ && (guessed || !rows_.empty()));
  setProperty("guessed", guessed);
  style()->unpolish(this);
  style()->polish(this);
  setVisible(!notes.isEmpty() || !rows_.empty() || !side.isEmpty() || !point.isEmpty());
}

void SetupStrip::changeEvent(QEvent* event) {
  QFrame::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
}

}  // namespace klueng::gui
