#pragma once
// The bar above the editor on a first start with no file (issue 28 item 8):
// what to do first (open a sample, press Go) with the samples one click away.
#include <QWidget>

class QLabel;
class QPushButton;

namespace klueng::gui {

class FirstStepsBar : public QWidget {
  Q_OBJECT
 public:
  explicit FirstStepsBar(QWidget* parent = nullptr);

  // Shows the offer when the samples folder holds sample 01; else stays hidden.
  void offer(const QString& samplesFolder);
  QString text() const;
  QPushButton* openSampleButton() const { return openSample_; }

 signals:
  void openRequested(const QString& path);  // sample 01
  void browseRequested();                   // File ▸ Open, in the samples

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();

  QLabel* label_ = nullptr;
  QPushButton* openSample_ = nullptr;
  QPushButton* browse_ = nullptr;
  QString sample_;
};

}  // namespace klueng::gui
