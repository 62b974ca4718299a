#include "gui/file_save.h"

#include "gui/language.h"
#include "klueng/core/io/file_write.h"
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

QString outputIsInput(const QString& output, const QString& input) {
  if (input.isEmpty()) return {};
  return text(core::io::outputOverwritesInput(output.toStdString(), {input.toStdString()}));
}

}  // namespace klueng::gui
