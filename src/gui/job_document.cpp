#include "gui/job_document.h"

#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <utility>

#include "klueng/core/gcode/machine_profile.h"

namespace klueng::gui {

void JobDocument::setSetup(const core::machine::MachineSetup& setup, std::optional<std::vector<int>> toolsWithBitmap) {
  setup_ = setup;
  toolsWithBitmap_ = std::move(toolsWithBitmap);
  setJob(nullptr);
  setupOnly_ = {};
  setupOnly_.setup = setup_;
}

void JobDocument::setOffsets(const core::io::OffsetTable& offsets) {
  core::machine::MachineSetup setup = setup_;
  setup.offsets = offsets;
  setSetup(setup, toolsWithBitmap_);
}

void JobDocument::setJob(std::shared_ptr<const core::job::Job> job) {
  std::shared_ptr<const core::job::Job> old = std::exchange(job_, std::move(job));
  if (old) (void)QtConcurrent::run([old = std::move(old)]() mutable { old.reset(); });
}

void JobDocument::setMachine(const core::io::MachineConfig& machine) {
  setup_.machine = machine;
  setupOnly_.setup = setup_;
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
  r.setup = setup_;
  r.overrides = overrides_;
  r.folder = folder;
  return r;
}

}  // namespace klueng::gui
