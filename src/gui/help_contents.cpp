#include "gui/help_contents.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

#include "gui/language.h"

namespace klueng::gui {

namespace {
QString fromStd(std::string_view s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }
QString esc(std::string_view s) { return fromStd(s).toHtmlEscaped(); }
}  // namespace

HelpContents::HelpContents(QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("helpContents"));
  browser_ = new QTextBrowser(this);
  browser_->setOpenLinks(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::hide);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(browser_);
  layout->addWidget(buttons);
  resize(820, 640);
  rebuild();
}

void HelpContents::setDialect(core::gcode::Dialect dialect) {
  dialect_ = dialect;
  rebuild();
}

QString HelpContents::buildHtml(bool thai, core::gcode::Dialect dialect) {
  QString html;
  html += QStringLiteral("<html><body style='font-size:11pt'>");
  html += QStringLiteral("<h2>%1</h2>").arg(tr("Klueng help: the G and M codes"));
  html += QStringLiteral("<p>%1</p>").arg(
      tr("A program file starts with six lines: project name, part name, material, stock diameter, "
         "stock length and programmer. Diameter and length begin with a unit digit (0 = inch, 1 = mm): "
         "<tt>150</tt> is 50 mm. From line 7 on comes the G-code, one block per line."));
  html += QStringLiteral("<p>%1</p>").arg(
      tr("A word is a letter followed at once by a number: <tt>X25.4</tt>, <tt>G1</tt>, <tt>Z-3</tt>. "
         "X is a diameter. Comments are written in ( ) or after ;. A / at the start of a block skips it "
         "when the Block Skip switch is on. Numbers without a decimal point are millimetres."));
  html += QStringLiteral("<p>%1 <b>%2</b></p>")
              .arg(tr("Dialect:"), dialect == core::gcode::Dialect::Fanuc ? tr("Fanuc 0i-TF")
                                  : dialect == core::gcode::Dialect::Haas ? tr("Haas ST (NGC)")
                                                                          : tr("Rook classic"));
  for (const char letter : {'G', 'M'}) {
    html += QStringLiteral("<h3><a name='%1'></a>%2</h3>")
                .arg(QString(QLatin1Char(letter)), letter == 'G' ? tr("G codes (preparatory functions)")
                                                        : tr("M codes (miscellaneous functions)"));
    html += QStringLiteral("<table border='1' cellspacing='0' cellpadding='4' width='100%'>");
    html += QStringLiteral("<tr style='background:#e8eef6'><th>%1</th><th>%2</th><th>%3</th></tr>")
                .arg(tr("Code"), tr("Meaning"), tr("Example"));
    for (const auto& c : core::gcode::codeTable()) {
      if (c.letter != letter) continue;
      const bool known = c.in(dialect);
      const QString code = QStringLiteral("%1%2").arg(QLatin1Char(c.letter)).arg(c.number, 2, 10, QLatin1Char('0'));
      const auto name = thai ? c.nameTh : c.nameEn;
      const auto other = thai ? c.nameEn : c.nameTh;
      const auto ex = thai ? c.exampleTh : c.exampleEn;
      const auto exOther = thai ? c.exampleEn : c.exampleTh;
      QString note;
      if (!known) note = QStringLiteral(" <i>(%1)</i>").arg(tr("not in this dialect"));
      html += QStringLiteral(
                  "<tr><td><b>%1</b></td><td>%2%3<br><span style='color:#666'>%4</span></td>"
                  "<td><tt>%5</tt><br><span style='color:#666'>%6</span></td></tr>")
                  .arg(code, esc(name), note, esc(other), esc(ex), esc(exOther));
    }
    html += QStringLiteral("</table>");
  }
  html += QStringLiteral("<h3>%1</h3><p>%2</p>")
              .arg(tr("Running a program"),
                   tr("F5 Go runs the program, F10 Step runs one block, Pause waits after the current "
                      "step, Stop resets. F9 sets a breakpoint on the cursor's line; Run to cursor stops "
                      "at the cursor's block. Every error is underlined in the editor and listed below it; "
                      "click one to jump to it."));
  html += QStringLiteral("</body></html>");
  return html;
}

void HelpContents::rebuild() {
  setWindowTitle(tr("Help Contents"));
  browser_->setHtml(buildHtml(Language::coreLang() == core::Lang::Th, dialect_));
}

void HelpContents::changeEvent(QEvent* event) {
  QDialog::changeEvent(event);
  if (event->type() == QEvent::LanguageChange) rebuild();
}

}  // namespace klueng::gui
