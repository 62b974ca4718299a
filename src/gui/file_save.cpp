#include "gui/file_save.h"

#include "gui/language.h"
#include "klueng/core/io/file_write.h"
#include "klueng/core/job/run_inputs.h"
#include "klueng/core/messages.h"

namespace klueng::gui {

namespace {

QString text(const std::optional<core::Diagnostic>& d) {
  return d ? QString::fromStdString(core::formatMessage(*d, Language::coreLang(), core::Surface::Gui)) : QString();
}

}  // namespace

QString writeFileChecked(const QString& path, std::string_view bytes) {
  return text(core::io::writeFileAtomic(path.toStdString(), bytes));
}

QString outputIsAnyInput(const QString& output, const std::vector<std::string>& inputs) {
  return text(core::io::outputOverwritesInput(output.toStdString(), inputs));
}

std::vector<std::string> setupInputs(const core::machine::MachineSetup& setup) {
  core::machine::LoadedSetup loaded;
  loaded.dir = setup.tools.folder;  // the folder of tools.cfg is the setup's folder
  loaded.setup = setup;
  return core::job::setupInputFiles(loaded);
}

QString outputIsInput(const QString& output, const QString& input) {
  if (input.isEmpty()) return {};
  return text(core::io::outputOverwritesInput(output.toStdString(), {input.toStdString()}));
}

}  // namespace klueng::gui
