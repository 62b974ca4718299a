#pragma once
// The strip above the editor (SPEC 12): an alarm or a refused run in red, a
// warning (a machine setup with errors) in yellow; selectable text, a close button.
#include <QWidget>

class QLabel;

namespace klueng::gui {

class Banner : public QWidget {
  Q_OBJECT
 public:
  explicit Banner(QWidget* parent = nullptr);
  void showMessage(const QString& text, bool error);
  void dismiss();
  // The text shown; empty when hidden.
  QString text() const;

 private:
  QLabel* label_;
};

}  // namespace klueng::gui
