#include "gui/settings.h"

#include <algorithm>

#include <QCryptographicHash>
#include <QFileInfo>

namespace klueng::gui {

namespace {
QString key(const char* k) { return QString::fromLatin1(k); }

// One group per file: "jobs/<sha1 of the absolute path>" (a path's slashes would be groups).
QString jobKey(const QString& path) {
  const QByteArray abs = QFileInfo(path).absoluteFilePath().toUtf8();
  return key("jobs/") + QString::fromLatin1(QCryptographicHash::hash(abs, QCryptographicHash::Sha1).toHex());
}

core::io::JobHeader readJob(QSettings& s, core::io::JobHeader h) {
  h.project = s.value(key("project"), QString::fromStdString(h.project)).toString().toStdString();
  h.part = s.value(key("part"), QString::fromStdString(h.part)).toString().toStdString();
  h.material = s.value(key("material"), QString::fromStdString(h.material)).toString().toStdString();
  h.programmer = s.value(key("programmer"), QString::fromStdString(h.programmer)).toString().toStdString();
  const double dia = s.value(key("diameter"), h.diameter).toDouble();
  const double len = s.value(key("length"), h.length).toDouble();
  const double bore = s.value(key("bore"), 0.0).toDouble();
  if (dia > 0) h.diameter = dia;
  if (len > 0) h.length = len;
  h.bore = bore > 0 && bore < h.diameter ? bore : 0.0;
  h.diameterUnit =
      s.value(key("diameterInch"), false).toBool() ? core::io::LengthUnit::Inch : core::io::LengthUnit::Millimetre;
  h.lengthUnit =
      s.value(key("lengthInch"), false).toBool() ? core::io::LengthUnit::Inch : core::io::LengthUnit::Millimetre;
  return h;
}

void writeJob(QSettings& s, const core::io::JobHeader& h) {
  s.setValue(key("project"), QString::fromStdString(h.project));
  s.setValue(key("part"), QString::fromStdString(h.part));
  s.setValue(key("material"), QString::fromStdString(h.material));
  s.setValue(key("programmer"), QString::fromStdString(h.programmer));
  s.setValue(key("diameter"), h.diameter);
  s.setValue(key("length"), h.length);
  s.setValue(key("bore"), h.bore);
  s.setValue(key("diameterInch"), h.diameterUnit == core::io::LengthUnit::Inch);
  s.setValue(key("lengthInch"), h.lengthUnit == core::io::LengthUnit::Inch);
}
}  // namespace

Settings::Settings() : settings_(QStringLiteral("Klueng"), QStringLiteral("klueng")) {}

QString Settings::language() const {
  const QString code = settings_.value(key("ui/language"), QStringLiteral("en")).toString();
  return code == QStringLiteral("th") ? code : QStringLiteral("en");
}
void Settings::setLanguage(const QString& code) { settings_.setValue(key("ui/language"), code); }

core::gcode::Dialect Settings::dialect() const {
  const QByteArray id = settings_.value(key("gcode/dialect")).toString().toUtf8();
  core::gcode::Dialect d = core::gcode::Dialect::Fanuc;
  if (!core::gcode::parseDialectId(std::string_view(id.constData(), static_cast<std::size_t>(id.size())), d))
    d = core::gcode::Dialect::Fanuc;
  return d;
}
void Settings::setDialect(core::gcode::Dialect d) {
  const std::string_view id = core::gcode::machineProfile(d).id;
  settings_.setValue(key("gcode/dialect"), QString::fromUtf8(id.data(), static_cast<qsizetype>(id.size())));
}

std::optional<core::gcode::InputUnits> Settings::powerOnUnits() const {
  const QString v = settings_.value(key("gcode/units")).toString();
  if (v == QStringLiteral("mm")) return core::gcode::InputUnits::Millimetre;
  if (v == QStringLiteral("inch")) return core::gcode::InputUnits::Inch;
  return std::nullopt;
}
void Settings::setPowerOnUnits(std::optional<core::gcode::InputUnits> units) {
  settings_.setValue(key("gcode/units"), !units                                    ? QStringLiteral("machine")
                                         : *units == core::gcode::InputUnits::Inch ? QStringLiteral("inch")
                                                                                   : QStringLiteral("mm"));
}

std::optional<core::DisplayUnits> Settings::shownUnits() const {
  const QString v = settings_.value(key("view/units")).toString();
  if (v == QStringLiteral("mm")) return core::DisplayUnits::Mm;
  if (v == QStringLiteral("inch")) return core::DisplayUnits::Inch;
  return std::nullopt;
}
void Settings::setShownUnits(std::optional<core::DisplayUnits> units) {
  settings_.setValue(key("view/units"), !units                               ? QStringLiteral("auto")
                                        : *units == core::DisplayUnits::Inch ? QStringLiteral("inch")
                                                                             : QStringLiteral("mm"));
}

QStringList Settings::recentFiles() const { return settings_.value(key("files/recent")).toStringList(); }

void Settings::addRecentFile(const QString& path) {
  const QString abs = QFileInfo(path).absoluteFilePath();
  QStringList list = recentFiles();
  list.removeAll(abs);
  list.prepend(abs);
  while (list.size() > kMaxRecentFiles) list.removeLast();
  settings_.setValue(key("files/recent"), list);
}

void Settings::removeRecentFile(const QString& path) {
  QStringList list = recentFiles();
  list.removeAll(QFileInfo(path).absoluteFilePath());
  settings_.setValue(key("files/recent"), list);
}

QByteArray Settings::windowGeometry() const { return settings_.value(key("window/geometry")).toByteArray(); }
void Settings::setWindowGeometry(const QByteArray& g) { settings_.setValue(key("window/geometry"), g); }
QByteArray Settings::windowState() const { return settings_.value(key("window/state")).toByteArray(); }
void Settings::setWindowState(const QByteArray& s) { settings_.setValue(key("window/state"), s); }
QByteArray Settings::splitterState() const { return settings_.value(key("window/splitter")).toByteArray(); }
void Settings::setSplitterState(const QByteArray& s) { settings_.setValue(key("window/splitter"), s); }

core::io::JobHeader Settings::lastJobHeader() const {
  settings_.beginGroup(key("job"));
  const core::io::JobHeader h = readJob(settings_, {});
  settings_.endGroup();
  return h;
}

void Settings::setLastJobHeader(const core::io::JobHeader& h) {
  settings_.beginGroup(key("job"));
  writeJob(settings_, h);
  settings_.endGroup();
}

std::optional<core::io::JobHeader> Settings::jobDetailsFor(const QString& path) const {
  settings_.beginGroup(jobKey(path));
  std::optional<core::io::JobHeader> h;
  if (settings_.contains(key("diameter"))) {
    h = readJob(settings_, {});
    h->stockSource = core::io::StockSource::JobDetails;
    // Lengths without a decimal point, when chosen for this file (never for other files).
    const QString reading = settings_.value(key("decimalPoint")).toString();
    if (reading == QStringLiteral("whole")) h->calculatorInput = true;
    if (reading == QStringLiteral("increments")) h->calculatorInput = false;
    const QString side = settings_.value(key("toolSide")).toString();
    if (side == QStringLiteral("front")) h->toolsBeyondCentre = false;
    if (side == QStringLiteral("beyond")) h->toolsBeyondCentre = true;
  }
  settings_.endGroup();
  return h;
}

void Settings::setJobDetailsFor(const QString& path, const core::io::JobHeader& h) {
  settings_.beginGroup(jobKey(path));
  settings_.setValue(key("path"), QFileInfo(path).absoluteFilePath());
  writeJob(settings_, h);
  if (h.calculatorInput)
    settings_.setValue(key("decimalPoint"),
                       *h.calculatorInput ? QStringLiteral("whole") : QStringLiteral("increments"));
  else
    settings_.remove(key("decimalPoint"));
  if (h.toolsBeyondCentre)
    settings_.setValue(key("toolSide"), *h.toolsBeyondCentre ? QStringLiteral("beyond") : QStringLiteral("front"));
  else
    settings_.remove(key("toolSide"));
  settings_.endGroup();
}

void Settings::removeJobDetailsFor(const QString& path) { settings_.remove(jobKey(path)); }

bool Settings::optionalStop() const { return settings_.value(key("run/optionalStop"), false).toBool(); }
void Settings::setOptionalStop(bool on) { settings_.setValue(key("run/optionalStop"), on); }
bool Settings::blockSkip() const { return settings_.value(key("run/blockSkip"), false).toBool(); }
void Settings::setBlockSkip(bool on) { settings_.setValue(key("run/blockSkip"), on); }

QString Settings::lastDirectory() const { return settings_.value(key("files/lastDirectory")).toString(); }
void Settings::setLastDirectory(const QString& dir) { settings_.setValue(key("files/lastDirectory"), dir); }

int Settings::autosaveSeconds() const {
  bool ok = false;
  const int s = settings_.value(key("files/autosaveSeconds"), 30).toInt(&ok);
  return ok ? std::clamp(s, 1, 3600) : 30;
}
void Settings::setAutosaveSeconds(int seconds) { settings_.setValue(key("files/autosaveSeconds"), seconds); }

}  // namespace klueng::gui
