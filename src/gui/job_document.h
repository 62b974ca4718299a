#pragma once
// The inputs of the open document's job (issue 30 item 1), kept in one place:
// the machine setup as read (with its machine's keys), which stations have a
// tool, the dialect and power-on units, the stations the user set for this
// file; and the last Job the check made from them. The window asks it for the
// check's input and for the job's tools; nobody else keeps a copy.
//
// Issue 30 item 2: the tool and offset tables and the stations set for this
// program are edited here, in memory, by undo commands on the document's own
// stack (setup_commands.h); the files are written by File ▸ Save. The setup as
// last read or saved is kept to say what is unsaved.
#include <QUndoStack>
#include <memory>
#include <optional>
#include <vector>

#include "klueng/core/gcode/code_table.h"
#include "klueng/core/io/program_file.h"
#include "klueng/core/job/job.h"
#include "klueng/core/infer/tool_inference.h"

namespace klueng::gui {

// What the setup dialogs edit: the tables of tools.cfg and offset.cfg and this program's stations.
struct SetupEdit {
  core::io::ToolTable tools;
  core::io::OffsetTable offsets;
  std::vector<core::machine::StationOverride> overrides;
  bool sameAs(const SetupEdit& o) const;  // the same files would be written, the same stations set
};

class JobDocument {
 public:
  JobDocument();
  JobDocument(const JobDocument&) = delete;
  JobDocument& operator=(const JobDocument&) = delete;

  const core::machine::MachineSetup& setup() const { return setup_; }
  // A setup just read from its folder (it is what is saved now): the last Job's tools no
  // longer hold (the next check decides them).
  void setSetup(const core::machine::MachineSetup& setup, std::optional<std::vector<int>> toolsWithBitmap);
  void setMachine(const core::io::MachineConfig& machine);  // the dialect's machine keys joined in
  // Offset rows set at the operator panel (touch-off), for the run only: not an edit of
  // offset.cfg (the panel's power on starts from the setup's again). Dropped when the
  // setup is read again or Offset Define edits the offsets. The last Job's tools no longer hold.
  void setOffsets(const core::io::OffsetTable& offsets);
  // The setup a check and a run use: setup() with the panel's offset rows, if any.
  core::machine::MachineSetup runSetup() const;

  // The edited setup (in memory) and putting one back (undo commands only).
  SetupEdit edit() const { return {setup_.tools, setup_.offsets, overrides_}; }
  void applyEdit(const SetupEdit& edit);
  // What File ▸ Save must write: tools.cfg, offset.cfg, the program's stations.
  bool toolsModified() const;
  bool offsetsModified() const;
  bool overridesModified() const;
  bool isSetupModified() const { return toolsModified() || offsetsModified() || overridesModified(); }
  // The files (and the stations, when `overridesToo`) were written: what is in memory is saved.
  void markSetupSaved(bool overridesToo = true);
  // The edits, text and setup, of this document in the order made (setup_commands.h).
  QUndoStack* undoStack() const { return undo_.get(); }
  bool hasToolTable() const { return toolsWithBitmap_.has_value(); }

  core::gcode::Dialect dialect() const { return dialect_; }
  void setDialect(core::gcode::Dialect dialect) { dialect_ = dialect; }
  std::optional<core::gcode::InputUnits> powerOnUnits() const { return powerOnUnits_; }
  void setPowerOnUnits(std::optional<core::gcode::InputUnits> units) { powerOnUnits_ = units; }

  const std::vector<core::machine::StationOverride>& overrides() const { return overrides_; }
  // The stations remembered for the file just opened (they are what is saved).
  void setSavedOverrides(std::vector<core::machine::StationOverride> overrides);

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
  std::optional<core::io::OffsetTable> runOffsets_;  // the operator panel's, for the run
  std::string savedTools_, savedOffsets_;            // formatted as the files were read or written
  std::vector<core::machine::StationOverride> savedOverrides_;
  std::unique_ptr<QUndoStack> undo_;
  std::shared_ptr<const core::job::Job> job_;
  core::machine::ToolInference setupOnly_;  // tools() before the first Job: the setup as read
};

}  // namespace klueng::gui
