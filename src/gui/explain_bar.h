#pragma once
// Explain (issue 11): one line under the editor that says, in the UI language,
// what the block at the green arrow does — "G01 X30. Z-20. F0.2: cut in a
// straight line to Ø30 at Z-20, 0.2 mm per revolution; at 180 m/min (G96) the
// spindle turns 1910 rpm here" — while a run is paused, stepping or ended; the
// editor's hover help adds the same for the line under the mouse. The words come
// from core::machine::explainBlock (the GUI only picks the block and the state).
#include <QLabel>
#include <QString>

namespace klueng::gui {

class CodeEditor;
class RunController;

class ExplainBar : public QLabel {
  Q_OBJECT
 public:
  ExplainBar(RunController* runner, CodeEditor* editor, QWidget* parent = nullptr);
  // What the block on fileLine (of the program in the editor) does: with the
  // state it left the last time it ran, else from its words alone.
  QString explainLine(int fileLine) const;

 public slots:
  void refresh();  // the arrow moved, the run state or the language changed

 protected:
  void changeEvent(QEvent* event) override;

 private:
  RunController* runner_;
  CodeEditor* editor_;
};

}  // namespace klueng::gui
