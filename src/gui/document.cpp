#include "gui/document.h"

#include <QFileInfo>

#include "gui/file_save.h"
#include "klueng/core/diagnostic_codes.h"
#include "klueng/core/infer/stock_inference.h"

namespace klueng::gui {

Document::Document(QObject* parent) : QObject(parent) {}

namespace {
void takeStock(core::io::JobHeader& h, const core::io::JobHeader& from) { h.takeStockFrom(from); }
}  // namespace

LoadedProgram Document::load(const QString& path, const core::io::JobHeader& defaultsForPlain,
                             const std::optional<core::io::JobHeader>& jobDetails) {
  LoadedProgram out;
  out.path = QFileInfo(path).absoluteFilePath();
  // Never another file's stock, project, part or material (issue 28 item 3).
  core::io::JobHeader defaults = newProgramHeader(defaultsForPlain);
  takeStock(defaults, core::io::JobHeader{});
  if (jobDetails) defaults = *jobDetails;
  auto result = core::io::readProgramFile(path.toStdString(), defaults);
  out.diagnostics = std::move(result.diagnostics);
  if (result.value) {
    out.ok = true;
    out.file = std::move(*result.value);
    core::io::ProgramFile& f = out.file;
    // A plain file's bar is not inferred here: the first check's Job reads it from the run it
    // records for the tools (one recording of the program, issue 40 item 2), and the window
    // takes it then (Document::takeInferredStock).
    out.stockNotes = core::machine::stockNotes(f.header, nullptr, f.gcode, f.gcodeFirstLine);
    out.gcode = QString::fromStdString(out.file.gcode);
    out.file.gcode.clear();  // the editor owns the text from now on
  }
  return out;
}

bool Document::takeInferredStock(const core::io::JobHeader& resolved, std::vector<core::Diagnostic> notes) {
  const auto source = file_.header.stockSource;
  if (!file_.plainGcode || (source != core::io::StockSource::Inferred && source != core::io::StockSource::Default))
    return false;
  core::io::JobHeader header = file_.header;
  takeStock(header, resolved);
  stockNotes_ = std::move(notes);
  const bool changed = header.diameter != file_.header.diameter || header.length != file_.header.length ||
                       header.bore != file_.header.bore || header.diameterUnit != file_.header.diameterUnit;
  file_.header = header;
  emit headerChanged();
  return changed;
}

int Document::firstOmittedLine() const {
  for (const core::Diagnostic& d : fileDiagnostics_)
    if (d.code == core::codes::kLineTooLong) return d.range.line;
  return 0;
}

core::io::JobHeader Document::newProgramHeader(const core::io::JobHeader& remembered) {
  core::io::JobHeader h = remembered;
  h.project.clear();
  h.part.clear();
  h.material.clear();
  h.calculatorInput.reset();
  h.toolsBeyondCentre.reset();
  return h;
}

void Document::reset(const core::io::JobHeader& header) {
  file_ = core::io::ProgramFile{};
  file_.header = header;
  file_.header.stockSource = core::io::StockSource::Header;  // a new program is written with a header
  stockNotes_ = core::machine::stockNotes(file_.header, nullptr, {}, 1);
  file_.plainGcode = false;
  file_.gcodeFirstLine = 7;
  fileDiagnostics_.clear();
  headerModified_ = false;
  design_.reset();
  path_.clear();
  emit pathChanged(path_);
  emit headerChanged();
}

void Document::adopt(const LoadedProgram& loaded) {
  file_ = loaded.file;
  // The editor holds the G-code from now on; a second copy here would only cost memory (issue 29 item 8).
  std::string().swap(file_.gcode);
  fileDiagnostics_ = loaded.diagnostics;
  stockNotes_ = loaded.stockNotes;
  headerModified_ = false;
  design_.reset();
  path_ = loaded.path;
  emit pathChanged(path_);
  emit headerChanged();
}

std::string Document::formatted(const QString& gcode) const {
  core::io::ProgramFile f;
  f.header = file_.header;
  f.plainGcode = file_.plainGcode;
  f.gcodeFirstLine = file_.gcodeFirstLine;
  f.encoding = file_.encoding;
  f.gcode = gcode.toStdString();
  return core::io::formatProgramFile(f);
}

bool Document::save(const QString& path, const QString& gcode, QString* error) {
  // Checked and atomic; a read-only file is refused (DocumentManager asks before).
  if (const QString why = writeFileChecked(path, formatted(gcode)); !why.isEmpty()) {
    if (error) *error = why;
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

QString Document::displayName() const { return path_.isEmpty() ? tr("untitled.txt") : QFileInfo(path_).fileName(); }

Document::HeaderState Document::headerStateFor(const core::io::JobHeader& header) const {
  HeaderState s{header, {}, headerModified_ || !file_.plainGcode};
  s.header.stockSource = file_.plainGcode ? core::io::StockSource::JobDetails : core::io::StockSource::Header;
  s.stockNotes = core::machine::stockNotes(s.header, nullptr, {}, 1);
  return s;
}

void Document::setHeader(const core::io::JobHeader& header) {
  const HeaderState s = headerStateFor(header);
  file_.header = s.header;
  stockNotes_ = s.stockNotes;
  // The old header's diagnostics (lines 1-6, e.g. a bad stock size) no longer apply.
  if (!file_.plainGcode)
    std::erase_if(fileDiagnostics_, [](const core::Diagnostic& d) { return d.range.line >= 1 && d.range.line <= 6; });
  // A plain file is saved without a header: its Job details are remembered elsewhere.
  headerModified_ = s.modified;
  emit headerChanged();
}

void Document::restoreHeader(const HeaderState& state) {
  file_.header = state.header;
  stockNotes_ = state.stockNotes;
  headerModified_ = state.modified;
  emit headerChanged();
}

}  // namespace klueng::gui
