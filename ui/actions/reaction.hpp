#pragma once
// ParaView-style reaction: the behaviour behind one menu/toolbar action, in its own class.
// A reaction is a child of its QAction and runs onTriggered() when the action fires. Like
// ParaView's updateEnableState, a reaction whose action cannot always run says when it can
// (canRun) and re-evaluates it on the signals it follows (enableWhileNoTaskHolds...).
#include <QAction>
#include <QObject>

namespace plumb::ui {

struct AppContext;

class Reaction : public QObject {
  Q_OBJECT
 public:
  Reaction(QAction* action, AppContext& app);
  QAction* action() const { return action_; }
  /// Enables the action when canRun().
  void updateEnableState();

 protected:
  virtual void onTriggered() = 0;
  AppContext& app() const { return app_; }
  /// Whether the action can run in the current state (it is disabled otherwise).
  virtual bool canRun() const { return true; }
  /// Re-evaluates canRun() whenever a background task starts or finishes (and now).
  void followTasks();

 private:
  QAction* action_;
  AppContext& app_;
};

}  // namespace plumb::ui
