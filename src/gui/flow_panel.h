#pragma once
// The program-flow dock (issue 9): while stepping, the call stack (main
// program, subprograms, macros, with L passes), the macro variables with the
// ones the last step changed in bold, and the source of a subprogram file
// when the running block is in one. It shows what the core recorded
// (Timeline::flow, machine/flow_view.h); it computes nothing itself.
#include <QDockWidget>
#include <QHash>
#include <QString>
#include <string>
#include <vector>

#include "klueng/core/machine/timeline.h"

class QLabel;
class QPlainTextEdit;
class QTreeWidget;

namespace klueng::gui {

class RunController;

class FlowPanel : public QDockWidget {
  Q_OBJECT
 public:
  explicit FlowPanel(QWidget* parent = nullptr);

  // Shows the state after snapshot `snapshot` of `timeline` (nullptr / -1: nothing).
  // `previous` is the snapshot shown before: variables written since are highlighted.
  // `files` are the program's files (Program::files); `file`/`line` the running block.
  void showStep(const core::machine::Timeline* timeline, int snapshot, int previous,
                const std::vector<std::string>& files, int file, int line);
  void clear();
  void retranslateUi();
  // Follows a run: refreshes when the running block changes, raises itself the
  // first time a run has calls or macro variables to show.
  void follow(RunController* runner);

  QTreeWidget* callStack() const { return stack_; }
  QTreeWidget* variables() const { return variables_; }
  QPlainTextEdit* source() const { return source_; }
  QLabel* sourceTitle() const { return sourceTitle_; }

 signals:
  // A frame was activated: show its calling line (file 0 = the editor's program).
  void callerActivated(int file, int line);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void showSource(const std::vector<std::string>& files, int file, int line);

  QTreeWidget* stack_ = nullptr;
  QTreeWidget* variables_ = nullptr;
  QLabel* sourceTitle_ = nullptr;
  QPlainTextEdit* source_ = nullptr;
  int sourceFile_ = -1;
  std::string sourcePath_;
  QHash<QString, QString> cache_;  // path -> text
  // What showStep() last got, for retranslateUi().
  const core::machine::Timeline* timeline_ = nullptr;
  int snapshot_ = -1, previous_ = -1, file_ = 0, line_ = 0;
  std::vector<std::string> files_;
  RunController* runner_ = nullptr;
  int shownSnapshot_ = -2;
  bool raisedForRun_ = false;
};

}  // namespace klueng::gui
