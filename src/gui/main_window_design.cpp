// Job details as the dialog's OK sets them (an undo command), and File > Part
// designer... (issue 14): the designer dialog wired to the window —
// the bar and material from Job details (and back, when a part file brings its
// own bar), the generated program into the editor as a new file.
#include "gui/document_manager.h"
#include "gui/main_window.h"
#include "gui/part_designer.h"
#include "gui/settings.h"
#include "gui/setup_commands.h"

namespace klueng::gui {

void MainWindow::setJobDetails(const core::io::JobHeader& header) {
  // The command is the edit: its first redo sets the header (issue 30 item 2).
  jobDoc_.undoStack()->push(new JobDetailsCommand(
      document_->headerState(), document_->headerStateFor(header), [this](const Document::HeaderState& state) {
        document_->restoreHeader(state);
        if (!document_->isPlainGcode())
          settings_->setLastJobHeader(state.header);
        else if (!document_->isUntitled() && state.header.stockSource == core::io::StockSource::JobDetails)
          settings_->setJobDetailsFor(document_->filePath(), state.header);
        else if (!document_->isUntitled())
          settings_->removeJobDetailsFor(document_->filePath());
        checkNow();
      }));
}

void MainWindow::showPartDesigner() {
  if (designer_) {
    designer_->show();
    designer_->raise();
    designer_->activateWindow();
    return;
  }
  // Closing only hides it: reopened in the same session it still holds the design (issue 28 item 8).
  designer_ = new PartDesignerDialog(jobDoc_.setup(), jobDoc_.dialect(), document_->header(), this);
  connect(document_, &Document::headerChanged, designer_, [this] { designer_->setJobHeader(document_->header()); });
  connect(designer_, &PartDesignerDialog::jobDetailsRequested, this, &MainWindow::showJobDetails);
  connect(designer_, &PartDesignerDialog::useStock, this, [this](double diameter, double length, double bore) {
    core::io::JobHeader h = document_->header();
    h.diameter = diameter;
    h.length = length;
    h.bore = bore;
    h.diameterUnit = h.lengthUnit = core::io::LengthUnit::Millimetre;
    h.stockSource = core::io::StockSource::JobDetails;
    setJobDetails(h);
  });
  connect(designer_, &PartDesignerDialog::programReady, this, [this](const QString& text) {
    // The program keeps this job's project, programmer and material words.
    const core::io::JobHeader job = document_->header();
    docs_->newFromProgram(text);
    core::io::JobHeader h = document_->header();
    if (!job.project.empty()) h.project = job.project;
    if (!job.programmer.empty()) h.programmer = job.programmer;
    if (!job.material.empty()) h.material = job.material;
    document_->setHeader(h);
    document_->setDesign(designer_->design());
    setDialect(designer_->dialect());
    raise();
    activateWindow();
  });
  designer_->show();
}

}  // namespace klueng::gui
