#include "gui/job_tools.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QThreadPool>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <QStringList>

#include "klueng/core/io/tool_library.h"

namespace klueng::gui {

namespace machine = core::machine;

namespace {
QString overridesKey(const QString& filePath) {
  // One key per file; '/' would make QSettings groups, so the path is encoded.
  const QString abs = QFileInfo(filePath).absoluteFilePath();
  return QStringLiteral("toolOverrides/") + QString::fromLatin1(abs.toUtf8().toBase64(QByteArray::Base64UrlEncoding));
}
}  // namespace

std::vector<machine::StationOverride> loadToolOverrides(const QString& filePath) {
  std::vector<machine::StationOverride> out;
  if (filePath.isEmpty()) return out;
  const QSettings settings(QStringLiteral("Klueng"), QStringLiteral("klueng"));
  const QStringList items = settings.value(overridesKey(filePath)).toStringList();
  const auto& library = core::io::shippedToolLibrary();
  for (const QString& item : items) {
    machine::StationOverride o;
    std::string error;
    if (machine::parseStationOverride(item.toStdString(), core::io::kMaxStations, library, o, error)) out.push_back(o);
  }
  return out;
}

void saveToolOverrides(const QString& filePath, const std::vector<machine::StationOverride>& overrides) {
  if (filePath.isEmpty()) return;
  QSettings settings(QStringLiteral("Klueng"), QStringLiteral("klueng"));
  QStringList items;
  for (const auto& o : overrides)
    items << QStringLiteral("%1=%2").arg(o.station).arg(QString::fromStdString(o.libraryId));
  if (items.isEmpty())
    settings.remove(overridesKey(filePath));
  else
    settings.setValue(overridesKey(filePath), items);
}

bool sameTools(const machine::MachineSetup& a, const machine::MachineSetup& b) {
  if (a.tools.bitmap != b.tools.bitmap || a.tools.libraryPath != b.tools.libraryPath ||
      a.tools.material != b.tools.material)  // the cutting data judges by it (issue 39)
    return false;
  // How the program is read and where its tools sit change the run as much as a tool does.
  if (a.machine.calculatorInput != b.machine.calculatorInput ||
      a.machine.toolsBeyondCentre != b.machine.toolsBeyondCentre)
    return false;
  for (std::size_t i = 0; i < a.offsets.offsets.size(); ++i) {
    const auto& x = a.offsets.offsets[i];
    const auto& y = b.offsets.offsets[i];
    if (x.x != y.x || x.z != y.z || x.r != y.r || x.tip != y.tip) return false;
  }
  return true;
}

void releaseFreedMemory() {
#if defined(__GLIBC__)
  QThreadPool::globalInstance()->start([] { malloc_trim(0); });
#endif
}

}  // namespace klueng::gui
