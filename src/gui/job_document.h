#pragma once
// The inputs of the open document's job (issue 30 item 1), kept in one place:
// the machine setup as read (with its machine's keys), which stations have a
// tool, the dialect and power-on units, the stations the user set for this
// file; and the last Job the check made from them. The window asks it for the
// check's input and for the job's tools; nobody else keeps a copy.
#include <memory>
#include <optional>
#include <vector>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"
#include "klueng/core/infer/tool_inference.h"

namespace klueng::gui {

class JobDocument {
 public:
  const core::machine::MachineSetup& setup() const { return setup_; }
  // A setup just read: the last Job's tools no longer hold (the next check decides them).
  void setSetup(const core::machine::MachineSetup& setup, std::optional<std::vector<int>> toolsWithBitmap);
  void setMachine(const core::io::MachineConfig& machine);  // the dialect's machine keys joined in
  // Offset rows set at the operator panel (touch-off): the last Job's tools no longer hold.
  void setOffsets(const core::io::OffsetTable& offsets);
  bool hasToolTable() const { return toolsWithBitmap_.has_value(); }

  core::gcode::Dialect dialect() const { return dialect_; }
  void setDialect(core::gcode::Dialect dialect) { dialect_ = dialect; }
  std::optional<core::gcode::InputUnits> powerOnUnits() const { return powerOnUnits_; }
  void setPowerOnUnits(std::optional<core::gcode::InputUnits> units) { powerOnUnits_ = units; }

  const std::vector<core::machine::StationOverride>& overrides() const { return overrides_; }
  void setOverrides(std::vector<core::machine::StationOverride> overrides) { overrides_ = std::move(overrides); }

  // The last check's Job; its tools are what a run, the Part panel and the reports use.
  const std::shared_ptr<const core::job::Job>& job() const { return job_; }
  // The Job it replaces is let go on a worker thread: a 100,000-block program's words take
  // tens of milliseconds to free, which the GUI thread must not spend.
  void setJob(std::shared_ptr<const core::job::Job> job);
  // The job's tools: the last Job's, else the setup as read.
  const core::machine::ToolInference& tools() const { return job_ ? job_->tools() : setupOnly_; }

  // What the editor's check makes a Job from: `file` is the header and line
  // numbering (its text goes in off the GUI thread), `folder` where subprogram files are.
  core::job::JobInput checkInput(core::io::ProgramFile file, const std::string& folder) const;

 private:
  core::machine::MachineSetup setup_;
  std::optional<std::vector<int>> toolsWithBitmap_;
  core::gcode::Dialect dialect_ = core::gcode::Dialect::Fanuc;
  std::optional<core::gcode::InputUnits> powerOnUnits_;  // nullopt: as the dialect's machine
  std::vector<core::machine::StationOverride> overrides_;
  std::shared_ptr<const core::job::Job> job_;
  core::machine::ToolInference setupOnly_;  // tools() before the first Job: the setup as read
};

}  // namespace klueng::gui
