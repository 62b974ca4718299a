#include "gui/document.h"

#include <QFileInfo>

namespace klueng::gui {

Document::Document(QObject* parent) : QObject(parent) {}

LoadedProgram Document::load(const QString& path, const core::io::JobHeader& defaultsForPlain) {
  LoadedProgram out;
  out.path = QFileInfo(path).absoluteFilePath();
  auto result = core::io::readProgramFile(path.toStdString(), defaultsForPlain);
  out.diagnostics = std::move(result.diagnostics);
  if (result.value) {
    out.ok = true;
    out.file = std::move(*result.value);
    out.gcode = QString::fromStdString(out.file.gcode);
    out.file.gcode.clear();  // the editor owns the text from now on
  }
  return out;
}

void Document::reset(const core::io::JobHeader& header) {
  file_ = core::io::ProgramFile{};
  file_.header = header;
  file_.plainGcode = false;
  file_.gcodeFirstLine = 7;
  fileDiagnostics_.clear();
  headerModified_ = false;
  path_.clear();
  emit pathChanged(path_);
  emit headerChanged();
}

void Document::adopt(const LoadedProgram& loaded) {
  file_ = loaded.file;
  fileDiagnostics_ = loaded.diagnostics;
  headerModified_ = false;
  path_ = loaded.path;
  emit pathChanged(path_);
  emit headerChanged();
}

std::string Document::formatted(const QString& gcode) const {
  core::io::ProgramFile f = file_;
  f.gcode = gcode.toStdString();
  return core::io::formatProgramFile(f);
}

bool Document::save(const QString& path, const QString& gcode, QString* error) {
  std::string err;
  if (!core::io::writeTextFileAtomic(path.toStdString(), formatted(gcode), &err)) {
    if (error) *error = QString::fromStdString(err);
    return false;
  }
  headerModified_ = false;
  const QString abs = QFileInfo(path).absoluteFilePath();
  if (abs != path_) {
    path_ = abs;
    emit pathChanged(path_);
  }
  return true;
}

QString Document::displayName() const {
  return path_.isEmpty() ? tr("untitled.txt") : QFileInfo(path_).fileName();
}

void Document::setHeader(const core::io::JobHeader& header) {
  file_.header = header;
  // The old header's diagnostics (lines 1-6, e.g. a bad stock size) no longer apply.
  if (!file_.plainGcode)
    std::erase_if(fileDiagnostics_, [](const core::Diagnostic& d) { return d.range.line >= 1 && d.range.line <= 6; });
  headerModified_ = true;
  emit headerChanged();
}

}  // namespace klueng::gui
