#include "gui/setup_commands.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>

#include "gui/file_save.h"
#include "klueng/core/io/program_file.h"

namespace klueng::gui {

JobDetailsCommand::JobDetailsCommand(Document::HeaderState before, Document::HeaderState after, Apply apply)
    : before_(std::move(before)), after_(std::move(after)), apply_(std::move(apply)) {
  setText(QCoreApplication::translate("klueng::gui::SetupCommands", "Job details"));
}

void JobDetailsCommand::undo() { apply_(before_); }

void JobDetailsCommand::redo() {
  if (std::exchange(done_, false)) return;
  apply_(after_);
}

bool SetupSnapshot::operator==(const SetupSnapshot& o) const {
  if (files != o.files || overrides.size() != o.overrides.size()) return false;
  for (std::size_t i = 0; i < overrides.size(); ++i)
    if (overrides[i].station != o.overrides[i].station || overrides[i].libraryId != o.overrides[i].libraryId)
      return false;
  return true;
}

SetupSnapshot SetupSnapshot::read(const QString& dir, std::vector<core::machine::StationOverride> overrides) {
  SetupSnapshot s;
  for (const char* file : {"tools.cfg", "offset.cfg"}) {
    const QString name = QString::fromLatin1(file);
    QFile f(QDir(dir).filePath(name));
    s.files[name] = f.open(QIODevice::ReadOnly) ? std::optional<QByteArray>(f.readAll()) : std::nullopt;
  }
  s.overrides = std::move(overrides);
  return s;
}

SetupFilesCommand::SetupFilesCommand(const QString& text, QString dir, SetupSnapshot before, SetupSnapshot after,
                                     Reload reload)
    : dir_(std::move(dir)), before_(std::move(before)), after_(std::move(after)), reload_(std::move(reload)) {
  setText(text);
}

void SetupFilesCommand::restore(const SetupSnapshot& snapshot) {
  QString error;
  for (const auto& [name, contents] : snapshot.files) {
    const QString path = QDir(dir_).filePath(name);
    if (!contents) {
      if (QFile::exists(path) && !QFile::remove(path)) error = path;
    } else if (const QString why = writeFileChecked(
                   path, std::string_view(contents->constData(), static_cast<std::size_t>(contents->size())));
               !why.isEmpty()) {
      error = why;  // names the path, in the UI language
    }
  }
  reload_(dir_, snapshot.overrides, error);
}

void SetupFilesCommand::undo() { restore(before_); }

void SetupFilesCommand::redo() {
  if (std::exchange(done_, false)) return;
  restore(after_);
}

}  // namespace klueng::gui
