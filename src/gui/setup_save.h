#pragma once
// File ▸ Save for the setup a document holds (issue 30 item 2): tools.cfg and
// offset.cfg are written only here, and only the ones that were edited, each
// atomically (file_save.h). A setup folder or file that is read-only is never
// written over: the user is asked whether to save to the per-user setup folder
// (core::io::ensureUserConfigDir), as a read-only program asks for another name
// (issue 29 item 2); there the edited tables go with the rest of the setup.
#include <QString>

#include "klueng/core/io/tool_config.h"

class QWidget;

namespace klueng::gui {

struct SetupToSave {
  QString dir;  // the folder the setup was read from
  const core::io::ToolTable* tools = nullptr;
  const core::io::OffsetTable* offsets = nullptr;
  bool toolsEdited = false, offsetsEdited = false;
};

// True when tools.cfg and offset.cfg in `dir` can be written (tried, not asked).
bool setupFolderWritable(const QString& dir);

// Writes the edited tables; returns the folder they are in now (`setup.dir`, or the
// per-user folder the user agreed to), or empty when cancelled or failed (a box said why).
QString saveSetupFiles(QWidget* parent, const SetupToSave& setup);

}  // namespace klueng::gui
