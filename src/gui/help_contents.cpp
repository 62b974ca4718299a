#include "gui/help_contents.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QTextDocument>
#include <QUrl>
#include <QSet>

#include <algorithm>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "gui/help_pictures.h"
#include "gui/language.h"
#include "klueng/core/help/help.h"

namespace klueng::gui {

namespace {
QString fromStd(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }
QString esc(std::string_view s) { return fromStd(s).toHtmlEscaped(); }
}  // namespace

HelpContents::HelpContents(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("helpContents"));
  search_ = new QLineEdit(this);
  search_->setObjectName(QStringLiteral("helpSearch"));
  search_->setClearButtonEnabled(true);
  hits_ = new QListWidget(this);
  hits_->setObjectName(QStringLiteral("helpHits"));
  hits_->setMaximumHeight(140);
  hits_->hide();
  connect(search_, &QLineEdit::textChanged, this, &HelpContents::search);
  connect(search_, &QLineEdit::returnPressed, this, [this] {
    if (hits_->count() > 0) showHit(hits_->item(0));
  });
  connect(hits_, &QListWidget::itemActivated, this, &HelpContents::showHit);
  connect(hits_, &QListWidget::itemClicked, this, &HelpContents::showHit);
  browser_ = new QTextBrowser(this);
  browser_->setOpenLinks(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::hide);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(search_);
  layout->addWidget(hits_);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(820, 640);
  rebuild();
}

void HelpContents::setDialect(core::gcode::Dialect dialect) {
  dialect_ = dialect;
  rebuild();
}

QString HelpContents::anchorOf(char letter, int number) {
  return QStringLiteral("%1%2").arg(QLatin1Char(letter)).arg(number, 2, 10, QLatin1Char('0'));
}

void HelpContents::showCode(char letter, int number) {
  show();
  raise();
  activateWindow();
  if (number < 0) return;  // no code asked for: where the reader left off
  browser_->scrollToAnchor(anchorOf(letter, number));
  shownAnchor_ = anchorOf(letter, number);
}

void HelpContents::search(const QString& text) {
  hits_->clear();
  const std::vector<core::machine::HelpHit> hits = core::machine::searchHelp(text.toStdString(), dialect_);
  const bool thai = Language::coreLang() == core::Lang::Th;
  for (const core::machine::HelpHit& h : hits) {
    const auto row = core::gcode::lookupCode(h.letter, h.number, dialect_);
    if (!row) continue;
    auto* item = new QListWidgetItem(
        QStringLiteral("%1 \u2014 %2").arg(anchorOf(h.letter, h.number), fromStd(thai ? row->nameTh : row->nameEn)));
    item->setData(Qt::UserRole, anchorOf(h.letter, h.number));
    hits_->addItem(item);
  }
  hits_->setVisible(!text.trimmed().isEmpty());
  if (!text.trimmed().isEmpty() && hits.empty()) hits_->addItem(tr("Nothing found"));
}

void HelpContents::showHit(QListWidgetItem* item) {
  const QString anchor = item ? item->data(Qt::UserRole).toString() : QString();
  if (anchor.isEmpty()) return;
  browser_->scrollToAnchor(anchor);
  shownAnchor_ = anchor;
}

QString HelpContents::buildHtml(bool thai, core::gcode::Dialect dialect) {
  QString html;
  html += QStringLiteral("<html><body style='font-size:11pt'>");
  html += QStringLiteral("<h2>%1</h2>").arg(tr("Klueng help: the G and M codes"));
  html += QStringLiteral("<p>%1</p>")
              .arg(tr("A program file starts with six lines: project name, part name, material, stock diameter, "
                      "stock length and programmer. Diameter and length begin with a unit digit (0 = inch, 1 = mm): "
                      "<tt>150</tt> is 50 mm. From line 7 on comes the G-code, one block per line."));
  html +=
      QStringLiteral("<p>%1</p>")
          .arg(tr("A word is a letter followed at once by a number: <tt>X25.4</tt>, <tt>G1</tt>, <tt>Z-3</tt>. "
                  "X is a diameter. Comments are written in ( ) or after ;. A / at the start of a block skips it "
                  "when the Block Skip switch is on. A length without a decimal point is whole millimetres "
                  "(<tt>X30</tt> = 30 mm) in Klueng's own programs; a program from the shop may be read in least "
                  "input increments (<tt>X30</tt> = 0.030 mm) as a standard Fanuc or Haas reads it: the setup strip "
                  "says which, and Job details changes it."));
  const core::gcode::MachineProfile& machine = core::gcode::machineProfile(dialect);
  html += QStringLiteral("<p>%1 <b>%2</b></p>")
              .arg(tr("Dialect:"), dialect == core::gcode::Dialect::Fanuc  ? tr("Fanuc 0i-TF")
                                   : dialect == core::gcode::Dialect::Haas ? tr("Haas ST (NGC)")
                                   : dialect == core::gcode::Dialect::Classic
                                       ? tr("Rook classic")
                                       : fromStd(thai ? machine.nameTh : machine.nameEn));
  QSet<QString> anchored;
  QString examples;
  for (const char letter : {'G', 'M'}) {
    html += QStringLiteral("<h3><a name='%1'></a>%2</h3>")
                .arg(QString(QLatin1Char(letter)),
                     letter == 'G' ? tr("G codes (preparatory functions)") : tr("M codes (miscellaneous functions)"));
    html += QStringLiteral("<table border='1' cellspacing='0' cellpadding='4' width='100%'>");
    html += QStringLiteral("<tr style='background:#e8eef6'><th>%1</th><th>%2</th><th>%3</th></tr>")
                .arg(tr("Code"), tr("Meaning"), tr("Example"));
    // The table's rows, then the rows only G-code systems B and C have (G90/G91 absolute/incremental).
    std::vector<std::pair<const core::gcode::CodeInfo*, bool>> rows;  // the row, a system-only row
    for (const auto& a : core::gcode::codeTable()) rows.emplace_back(&a, false);
    for (const auto& a : core::gcode::systemOnlyRows())
      if (machine.system != core::gcode::GcodeSystem::A) rows.emplace_back(&a, true);
    // In the order of the numbers this machine uses (system B's G33 among the G3x, its
    // G98/G99 return levels beside each other), as a control's manual lists them.
    const auto shownNumber = [&](const std::pair<const core::gcode::CodeInfo*, bool>& r) {
      const core::gcode::CodeInfo& a = *r.first;
      if (!a.in(dialect) || r.second) return a.number;
      const int n = core::gcode::numberInSystem(a.letter, a.number, dialect);
      const core::gcode::CodeInfo* own = core::gcode::findCode(a.letter, n, dialect);
      return own && own->action == a.action ? n : a.number;
    };
    std::stable_sort(rows.begin(), rows.end(),
                     [&](const auto& x, const auto& y) { return shownNumber(x) < shownNumber(y); });
    for (const auto& [row, systemOnly] : rows) {
      const core::gcode::CodeInfo& a = *row;
      if (a.letter != letter) continue;
      // The machine's own row, under its G-code system's number (G33 for G32 in system B).
      const core::gcode::CodeInfo* own =
          !a.in(dialect) ? nullptr
          : systemOnly
              ? core::gcode::findCode(a.letter, a.number, dialect)
              : core::gcode::findCode(a.letter, core::gcode::numberInSystem(a.letter, a.number, dialect), dialect);
      const bool known = own && own->action == a.action;
      const auto& c = known ? *own : a;
      const QString code = QStringLiteral("%1%2").arg(QLatin1Char(c.letter)).arg(c.number, 2, 10, QLatin1Char('0'));
      const auto name = thai ? c.nameTh : c.nameEn;
      const auto other = thai ? c.nameEn : c.nameTh;
      const auto ex = thai ? c.exampleTh : c.exampleEn;
      const auto exOther = thai ? c.exampleEn : c.exampleTh;
      QString note;
      if (!known) note = QStringLiteral(" <i>(%1)</i>").arg(tr("not in this dialect"));
      // The dialect's own row carries the anchor F1 and the search jump to, and its worked example.
      QString anchor, exampleLink;
      if (known && !anchored.contains(code)) {
        anchored.insert(code);
        anchor = QStringLiteral("<a name='%1'></a>").arg(code);
        exampleLink = QStringLiteral("<br><a href='#ex-%1'>%2</a>").arg(code, tr("Worked example"));
        examples +=
            QStringLiteral("<h4><a name='ex-%1'></a>%1 \u2014 %2</h4><pre>%3</pre>")
                .arg(code, esc(name),
                     QString::fromStdString(core::machine::workedExample(c.letter, c.number, dialect)).toHtmlEscaped());
        if (pictured(c))  // the path the example really makes (rebuild() draws it)
          examples += QStringLiteral("<p><img src='help-path-%1.png'><br><i>%2</i></p>")
                          .arg(code, tr("Red: cutting moves; blue dashes: rapids; grey: the bar."));
      }
      html += QStringLiteral(
                  "<tr><td>%7<b>%1</b></td><td>%2%3<br><span style='color:#666'>%4</span></td>"
                  "<td><tt>%5</tt><br><span style='color:#666'>%6</span>%8</td></tr>")
                  .arg(code, esc(name), note, esc(other), esc(ex), esc(exOther), anchor, exampleLink);
    }
    html += QStringLiteral("</table>");
  }
  html += QStringLiteral("<h3>%1</h3><p>%2</p>")
              .arg(tr("Running a program"),
                   tr("F5 Go runs the program, F10 Step runs one block, Pause waits after the current "
                      "step, Stop resets. F9 sets a breakpoint on the cursor's line; Run to cursor stops "
                      "at the cursor's block. Every error is underlined in the editor and listed below it; "
                      "click one to jump to it."));
  html += QStringLiteral("<h3><a name='tips'></a>%1</h3><p>%2</p><p><img src='help-tips.png'></p>")
              .arg(tr("Imaginary tool tip numbers 0-9"),
                   tr("Offset define gives each tool nose its tip number T: where the imaginary tip lies from the "
                      "nose centre. Nose radius compensation (G41/G42) needs it: an outside turning tool is 3, a "
                      "boring bar 2."));
  html += QStringLiteral("<h3><a name='examples'></a>%1</h3><p>%2</p>")
              .arg(tr("Worked examples"),
                   tr("Each program runs as it is on a bar of 50 x 100 mm with the shipped tools: copy it into "
                      "the editor and press Go."));
  html += examples;
  html += QStringLiteral("</body></html>");
  return html;
}

namespace {
// The cycles whose worked example gets a picture of its path, by action: the
// machine's own numbers (G73 roughs in G-code system C) follow from its rows.
constexpr core::gcode::CodeAction kPicturedCycles[] = {
    core::gcode::CodeAction::TurnRoughing, core::gcode::CodeAction::FaceRoughing,
    core::gcode::CodeAction::PatternRepeating, core::gcode::CodeAction::ThreadCutting};
}  // namespace

bool HelpContents::pictured(const core::gcode::CodeInfo& row) {
  return std::find(std::begin(kPicturedCycles), std::end(kPicturedCycles), row.action) != std::end(kPicturedCycles);
}

void HelpContents::rebuild() {
  setWindowTitle(tr("Help Contents"));
  const bool thai = Language::coreLang() == core::Lang::Th;
  QTextDocument* doc = browser_->document();
  doc->addResource(QTextDocument::ImageResource, QUrl(QStringLiteral("help-tips.png")), tipNumbersPicture());
  for (const core::gcode::CodeAction action : kPicturedCycles)
    if (const core::gcode::CodeInfo* row = core::gcode::findAction('G', action, dialect_))
      doc->addResource(
          QTextDocument::ImageResource,
          QUrl(QStringLiteral("help-path-%1.png").arg(QString::fromStdString(core::gcode::codeWord(*row)))),
          examplePathPicture('G', row->number, dialect_));
  search_->setPlaceholderText(tr("Search: G71, roughing, กลึงปอกหยาบ ..."));
  browser_->setHtml(buildHtml(thai, dialect_));
  if (!search_->text().isEmpty()) search(search_->text());
  if (!shownAnchor_.isEmpty()) browser_->scrollToAnchor(shownAnchor_);
}

void HelpContents::changeEvent(QEvent* event) {
  QDialog::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) rebuild();
}

}  // namespace klueng::gui
