#pragma once
// The GUI's way to write a file (issue 29): core::io::writeFileAtomic, the
// same as klueng-cli's. Every write, the flush and the close are checked, the
// old file keeps its bytes on failure, and a read-only file is refused (root
// too, which QSaveFile would replace). Why, in the UI language, from the core's
// bilingual catalog.
#include <QString>
#include <string>
#include <string_view>
#include <vector>

#include "klueng/core/machine/interpreter.h"

namespace klueng::gui {

// An empty string when `bytes` are in `path`; else why (path and reason), in the UI language.
QString writeFileChecked(const QString& path, std::string_view bytes);

// Why `output` must not be written because it is `input` (F126), or empty.
QString outputIsInput(const QString& output, const QString& input);
// The same for every file in `inputs` (issue 42 item 2).
QString outputIsAnyInput(const QString& output, const std::vector<std::string>& inputs);
// Every file a run with `setup` reads besides its program (core::job::setupInputFiles): the setup
// tables of its folder, the tool pictures, the library, the cutting speeds, the machine files.
std::vector<std::string> setupInputs(const core::machine::MachineSetup& setup);

}  // namespace klueng::gui
