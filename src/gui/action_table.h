#pragma once
// One table of the main window's commands (issue 12): name, icon, shortcut,
// text, tip, the menu and tool bar that show it and when it is enabled. Menus,
// tool bars, retranslation and the run-state gates all read this table, so an
// action is named once. The window only connects `triggered` to its slot.
#include <QHash>
#include <QObject>
#include <QString>

#include "gui/run_controller.h"

class QAction;
class QMainWindow;
class QMenu;
class QToolBar;

namespace klueng::gui {

// When an action is enabled, by the run state (the Edit actions follow the editor instead).
enum class EnabledWhen {
  Always,         // not gated by the run
  NotRunning,     // New, Open, the setup dialogs: nothing changes under an animation
  CanGo,          // idle, paused, finished, or switching a Step into Go
  CanStep,        // idle, paused, finished, or a Go switching into a Step
  Running,        // Pause
  Started,        // Stop: anything but Idle
  StoppedMidRun,  // Step Back: a run that is not animating and not reset
};

class ActionTable : public QObject {
  Q_OBJECT
 public:
  // Creates every action of the table (and the speed actions, `speedCount` of them), owned by `window`.
  ActionTable(QMainWindow* window, int speedCount);

  QAction* action(const QString& name) const { return actions_.value(name, nullptr); }
  // An action made elsewhere (a dock's or tool bar's toggle) that a menu of the table lists by name.
  void add(const QString& name, QAction* action);

  // The menu bar and tool bars, in the table's order. Tool bars first: the View
  // menu lists their toggles.
  void buildToolBars();
  void buildMenus();
  QMenu* menu(const QString& name) const { return menus_.value(name, nullptr); }
  QToolBar* toolBar(const QString& name) const { return toolBars_.value(name, nullptr); }

  // Texts, tips (with the shortcut), menu and tool bar titles in the UI language.
  void retranslate();
  // Enables each gated action for `state`.
  void applyRunState(RunState state);
  static bool enabledIn(EnabledWhen when, RunState state);

 private:
  QMainWindow* window_;
  QHash<QString, QAction*> actions_;
  QHash<QString, QMenu*> menus_;
  QHash<QString, QToolBar*> toolBars_;
};

}  // namespace klueng::gui
