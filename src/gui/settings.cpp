#include "gui/settings.h"

#include <QFileInfo>

namespace klueng::gui {

namespace {
QString key(const char* k) { return QString::fromLatin1(k); }
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
  core::io::JobHeader h;
  settings_.beginGroup(key("job"));
  h.project = settings_.value(key("project")).toString().toStdString();
  h.part = settings_.value(key("part")).toString().toStdString();
  h.material = settings_.value(key("material")).toString().toStdString();
  h.programmer = settings_.value(key("programmer")).toString().toStdString();
  const double dia = settings_.value(key("diameter"), h.diameter).toDouble();
  const double len = settings_.value(key("length"), h.length).toDouble();
  if (dia > 0) h.diameter = dia;
  if (len > 0) h.length = len;
  h.diameterUnit = settings_.value(key("diameterInch"), false).toBool() ? core::io::LengthUnit::Inch
                                                                       : core::io::LengthUnit::Millimetre;
  h.lengthUnit = settings_.value(key("lengthInch"), false).toBool() ? core::io::LengthUnit::Inch
                                                                   : core::io::LengthUnit::Millimetre;
  settings_.endGroup();
  return h;
}

void Settings::setLastJobHeader(const core::io::JobHeader& h) {
  settings_.beginGroup(key("job"));
  settings_.setValue(key("project"), QString::fromStdString(h.project));
  settings_.setValue(key("part"), QString::fromStdString(h.part));
  settings_.setValue(key("material"), QString::fromStdString(h.material));
  settings_.setValue(key("programmer"), QString::fromStdString(h.programmer));
  settings_.setValue(key("diameter"), h.diameter);
  settings_.setValue(key("length"), h.length);
  settings_.setValue(key("diameterInch"), h.diameterUnit == core::io::LengthUnit::Inch);
  settings_.setValue(key("lengthInch"), h.lengthUnit == core::io::LengthUnit::Inch);
  settings_.endGroup();
}

bool Settings::optionalStop() const { return settings_.value(key("run/optionalStop"), false).toBool(); }
void Settings::setOptionalStop(bool on) { settings_.setValue(key("run/optionalStop"), on); }
bool Settings::blockSkip() const { return settings_.value(key("run/blockSkip"), false).toBool(); }
void Settings::setBlockSkip(bool on) { settings_.setValue(key("run/blockSkip"), on); }

QString Settings::lastDirectory() const { return settings_.value(key("files/lastDirectory")).toString(); }
void Settings::setLastDirectory(const QString& dir) { settings_.setValue(key("files/lastDirectory"), dir); }

}  // namespace klueng::gui
