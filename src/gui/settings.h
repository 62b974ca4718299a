#pragma once
// The GUI's remembered choices (QSettings, organisation "Klueng"): window
// layout, recent files, UI language, dialect, last job header. One typed
// accessor per key so no string key is spelled twice.
#include <QByteArray>
#include <QSettings>
#include <QString>
#include <QStringList>
#include <optional>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/units.h"

namespace klueng::gui {

class Settings {
 public:
  static constexpr int kMaxRecentFiles = 8;

  Settings();

  QString language() const;  // "en" or "th"
  void setLanguage(const QString& code);

  core::gcode::Dialect dialect() const;
  void setDialect(core::gcode::Dialect d);
  // Power-on units: nullopt = as the dialect's machine powers on.
  std::optional<core::gcode::InputUnits> powerOnUnits() const;
  void setPowerOnUnits(std::optional<core::gcode::InputUnits> units);
  // The unit lengths are shown in (View ▸ Units shown): nullopt = Auto, the program's.
  std::optional<core::DisplayUnits> shownUnits() const;
  void setShownUnits(std::optional<core::DisplayUnits> units);

  QStringList recentFiles() const;
  // Puts path first, removes duplicates, keeps at most kMaxRecentFiles.
  void addRecentFile(const QString& path);
  void removeRecentFile(const QString& path);

  QByteArray windowGeometry() const;
  void setWindowGeometry(const QByteArray& g);
  QByteArray windowState() const;
  void setWindowState(const QByteArray& s);
  QByteArray splitterState() const;
  void setSplitterState(const QByteArray& s);

  // Job details for new programs; a plain file takes only its text fields
  // (project, programmer ...), never its stock (SPEC 2 ext).
  core::io::JobHeader lastJobHeader() const;
  void setLastJobHeader(const core::io::JobHeader& h);
  // Job details set for one plain G-code file, keyed by its absolute path
  // (stockSource = JobDetails); nullopt when none were set.
  std::optional<core::io::JobHeader> jobDetailsFor(const QString& path) const;
  void setJobDetailsFor(const QString& path, const core::io::JobHeader& h);
  void removeJobDetailsFor(const QString& path);  // back to an inferred stock

  bool optionalStop() const;
  void setOptionalStop(bool on);
  bool blockSkip() const;
  void setBlockSkip(bool on);

  QString lastDirectory() const;
  void setLastDirectory(const QString& dir);

  // How often unsaved work goes to the recovery folder (1..3600 s, default 30).
  int autosaveSeconds() const;
  void setAutosaveSeconds(int seconds);

 private:
  mutable QSettings settings_;
};

}  // namespace klueng::gui
