#include "gui/setup_commands.h"

#include <QCoreApplication>
#include <utility>

namespace klueng::gui {

JobDetailsCommand::JobDetailsCommand(Document::HeaderState before, Document::HeaderState after, Apply apply)
    : before_(std::move(before)), after_(std::move(after)), apply_(std::move(apply)) {
  setText(QCoreApplication::translate("klueng::gui::SetupCommands", "Job Details"));
}

void JobDetailsCommand::undo() { apply_(before_); }
void JobDetailsCommand::redo() { apply_(after_); }

SetupCommand::SetupCommand(const QString& text, SetupEdit before, SetupEdit after, Apply apply)
    : before_(std::move(before)), after_(std::move(after)), apply_(std::move(apply)) {
  setText(text);
}

void SetupCommand::undo() { apply_(before_); }
void SetupCommand::redo() { apply_(after_); }

TextEditCommand::TextEditCommand(QPlainTextEdit* editor) : editor_(editor) {
  setText(QCoreApplication::translate("klueng::gui::SetupCommands", "Typing"));
}

void TextEditCommand::undo() {
  if (editor_) editor_->undo();
}

void TextEditCommand::redo() {
  if (std::exchange(done_, false)) return;
  if (editor_) editor_->redo();
}

}  // namespace klueng::gui
