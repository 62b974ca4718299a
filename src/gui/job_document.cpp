#include "gui/job_document.h"

#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <utility>

#include "klueng/core/gcode/machine_profile.h"
#include "klueng/core/machine/setup_files.h"

namespace klueng::gui {

namespace {
bool sameOverrides(const std::vector<core::machine::StationOverride>& a,
                   const std::vector<core::machine::StationOverride>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const auto& x, const auto& y) { return x.station == y.station && x.libraryId == y.libraryId; });
}
}  // namespace

bool SetupEdit::sameAs(const SetupEdit& o) const {
  // Compared as the files would be written: the flags decoding sets are not edits.
  return core::io::formatToolTable(tools) == core::io::formatToolTable(o.tools) &&
         core::io::formatOffsetTable(offsets) == core::io::formatOffsetTable(o.offsets) &&
         sameOverrides(overrides, o.overrides);
}

JobDocument::JobDocument() : undo_(std::make_unique<QUndoStack>()) { markSetupSaved(); }

void JobDocument::setSetup(const core::machine::MachineSetup& setup, std::optional<std::vector<int>> toolsWithBitmap) {
  setup_ = setup;
  toolsWithBitmap_ = std::move(toolsWithBitmap);
  savedTools_ = core::io::formatToolTable(setup_.tools);
  savedOffsets_ = core::io::formatOffsetTable(setup_.offsets);
  runOffsets_.reset();
  setJob(nullptr);
  setupOnly_ = {};
  setupOnly_.setup = setup_;
}

void JobDocument::setOffsets(const core::io::OffsetTable& offsets) {
  runOffsets_ = offsets;
  setJob(nullptr);
  setupOnly_ = {};
  setupOnly_.setup = runSetup();
}

core::machine::MachineSetup JobDocument::runSetup() const {
  core::machine::MachineSetup s = setup_;
  if (runOffsets_) s.offsets = *runOffsets_;
  return s;
}

void JobDocument::applyEdit(const SetupEdit& edit) {
  const bool toolsChanged = core::io::formatToolTable(edit.tools) != core::io::formatToolTable(setup_.tools);
  // Offsets defined in Offset Define are the run's from now on, the panel's given up.
  if (core::io::formatOffsetTable(edit.offsets) != core::io::formatOffsetTable(setup_.offsets)) runOffsets_.reset();
  setup_.tools = edit.tools;
  setup_.offsets = edit.offsets;
  overrides_ = edit.overrides;
  // A tool table edited in memory is one: its stations with a bitmap are checked (E305).
  if (toolsChanged || toolsWithBitmap_) toolsWithBitmap_ = core::machine::toolsWithBitmap(setup_);
  setJob(nullptr);
  setupOnly_ = {};
  setupOnly_.setup = runSetup();
}

bool JobDocument::toolsModified() const { return core::io::formatToolTable(setup_.tools) != savedTools_; }
bool JobDocument::offsetsModified() const { return core::io::formatOffsetTable(setup_.offsets) != savedOffsets_; }
bool JobDocument::overridesModified() const { return !sameOverrides(overrides_, savedOverrides_); }

void JobDocument::markSetupSaved(bool overridesToo) {
  savedTools_ = core::io::formatToolTable(setup_.tools);
  savedOffsets_ = core::io::formatOffsetTable(setup_.offsets);
  if (overridesToo) savedOverrides_ = overrides_;
}

void JobDocument::setSavedOverrides(std::vector<core::machine::StationOverride> overrides) {
  overrides_ = std::move(overrides);
  savedOverrides_ = overrides_;
}

void JobDocument::setJob(std::shared_ptr<const core::job::Job> job) {
  std::shared_ptr<const core::job::Job> old = std::exchange(job_, std::move(job));
  if (old) (void)QtConcurrent::run([old = std::move(old)]() mutable { old.reset(); });
}

void JobDocument::setMachine(const core::io::MachineConfig& machine) {
  setup_.machine = machine;
  setupOnly_.setup = runSetup();
}

core::job::JobInput JobDocument::checkInput(core::io::ProgramFile file, const std::string& folder) const {
  core::job::JobInput r;
  r.file = std::move(file);
  r.run.dialect = dialect_;
  r.run.powerOnUnits = powerOnUnits_;
  r.toolTable = toolsWithBitmap_.has_value();  // no tool table read: T words are not checked
  r.modalRules = true;                         // issue 11: the alarms the modal state shows, while typing
  const int profileLimit = core::gcode::machineProfile(dialect_).maxToolStation;
  r.stations = profileLimit > 0 ? std::min(profileLimit, setup_.tools.stations) : setup_.tools.stations;
  r.setup = runSetup();
  r.overrides = overrides_;
  r.folder = folder;
  return r;
}

}  // namespace klueng::gui
