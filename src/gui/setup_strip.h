#pragma once
// The job's setup above the output screen, before a run (issue 26): where the
// stock came from (its I15x note) and, for a plain G-code file, the tool Klueng
// took for each station the program uses with the reason (I401..I409 notes) and
// the tool side when the program works beyond the centre line (I412), marked
// "guessed from the program", and how lengths without a decimal point are read
// when that is worth saying (increments, the program's I103/I104 note, or the
// file's Job details choice). One click on a line changes it: the bar and the
// decimal-point line open Job details, a station opens Tool Select on that
// station. Display only: every text is a core note or a library tool's name,
// in the UI language.
//
// Public API
//   showSetup(stockNotes, stockGuessed, plainGcode, inference, points)  what to show (kept; re-read on a language
//   change) stockText()          the stock line as shown in full (first note, capitalised) stations()           the
//   stations listed, in order stationText(n)       station n's line in full ("T02  Grooving tool, 3 mm — grooving cycle
//   G75 on line 16") titleText()          the "guessed from the program" title ("" when hidden) sideText() the
//   beyond-the-centre line ("" when hidden) pointText()          the decimal-point reading line ("" when hidden)
//   stationLine(n)       the clickable line of station n (tests)
// Signals: stockActivated(), stationActivated(station), pointReadingActivated(), toolSideActivated()
#include <QFrame>
#include <QLabel>
#include <QList>
#include <optional>
#include <vector>

#include "klueng/core/diagnostic.h"
#include "klueng/core/infer/tool_inference.h"

class QGridLayout;

namespace klueng::gui {

// One line of the strip: plain text cut with "…" at the pane's edge (the tooltip
// has all of it); never widens the pane. Clickable when `clickable`.
class SetupLine : public QLabel {
  Q_OBJECT
 public:
  explicit SetupLine(QWidget* parent = nullptr);
  void setFullText(const QString& text);
  QString fullText() const { return full_; }
  void setClickable(bool on);
  QSize minimumSizeHint() const override;

 signals:
  void clicked();

 protected:
  void resizeEvent(QResizeEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  void elide();
  QString full_;
  bool clickable_ = false;
};

// How the job reads lengths without a decimal point, as far as the strip says it.
// The reading itself is inference.setup.machine.calculatorInput.
struct PointReadingShown {
  std::optional<bool> chosen;            // the file's Job details choice (JobHeader::calculatorInput)
  std::optional<core::Diagnostic> note;  // the check's I103/I104: the word that decided
  std::optional<bool> sideChosen;        // the file's tool side from Job details (JobHeader::toolsBeyondCentre)
};

class SetupStrip : public QFrame {
  Q_OBJECT
 public:
  explicit SetupStrip(QWidget* parent = nullptr);
  void showSetup(const std::vector<core::Diagnostic>& stockNotes, bool stockGuessed, bool plainGcode,
                 const core::machine::ToolInference& inference, const PointReadingShown& points = {});
  QString stockText() const;
  QList<int> stations() const;
  QString stationText(int station) const;
  SetupLine* stationLine(int station) const;
  QString titleText() const;
  QString sideText() const;
  QString pointText() const;
  void retranslateUi();

 signals:
  void stockActivated();
  void stationActivated(int station);
  void pointReadingActivated();
  void toolSideActivated();

 protected:
  void changeEvent(QEvent* event) override;

 private:
  QString pointReadingText(QString* tip) const;  // "" when not worth a line
  struct Row {
    int station = 0;
    SetupLine* line = nullptr;
  };
  std::vector<core::Diagnostic> stockNotes_;
  bool stockGuessed_ = false;
  bool plain_ = false;
  core::machine::ToolInference inference_;
  PointReadingShown points_;

  QLabel* title_ = nullptr;
  SetupLine* stock_ = nullptr;
  SetupLine* side_ = nullptr;
  SetupLine* point_ = nullptr;
  QGridLayout* grid_ = nullptr;
  std::vector<Row> rows_;
};

}  // namespace klueng::gui
