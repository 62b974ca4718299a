#pragma once
// The bar above the editor that offers unsaved work a crash left behind
// ("01-step-shaft.txt, edited at 10:42: 3 lines differ from the file, the
// first at line 12") with Restore, Compare and Discard; one copy at a time.
#include <QVector>
#include <QWidget>

#include "gui/recovery.h"

class QLabel;
class QPushButton;

namespace klueng::gui {

class RecoveryBar : public QWidget {
  Q_OBJECT
 public:
  explicit RecoveryBar(QWidget* parent = nullptr);

  // Offers these copies (newest first); hides when there are none.
  void offer(QVector<RecoveryCopy> copies);
  const QVector<RecoveryCopy>& pending() const { return copies_; }
  QString text() const;
  // The buttons' work, for the window and tests: the first pending copy.
  void restoreFirst();
  void discardFirst();
  // What Compare shows for the first pending copy: per differing run of lines
  // "line N", then the file's lines "  - ..." and the copy's "  + ...".
  QString comparison() const;

 signals:
  void restoreRequested(const RecoveryCopy& copy);
  void discardRequested(const RecoveryCopy& copy);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void compareFirst();
  void next();

  QLabel* label_ = nullptr;
  QPushButton* restore_ = nullptr;
  QPushButton* compare_ = nullptr;
  QPushButton* discard_ = nullptr;
  QVector<RecoveryCopy> copies_;
};

}  // namespace klueng::gui
