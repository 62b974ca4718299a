#pragma once
// Help > About: name, version, what Klueng is, its 1999 origin, licences.
//
// Public API
//   AboutDialog dlg(parent); dlg.exec();
#include <QDialog>

class QLabel;
class QDialogButtonBox;

namespace klueng::gui {

class AboutDialog : public QDialog {
  Q_OBJECT
 public:
  explicit AboutDialog(QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  QLabel* title_ = nullptr;
  QLabel* body_ = nullptr;
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace klueng::gui
