#pragma once
// ParaView-style reaction: the behaviour behind one menu/toolbar action, in its own class.
// A reaction is a child of its QAction and runs onTriggered() when the action fires.
#include <QAction>
#include <QObject>

namespace plumb::ui {

struct AppContext;

class Reaction : public QObject {
  Q_OBJECT
 public:
  Reaction(QAction* action, AppContext& app);
  QAction* action() const { return action_; }

 protected:
  virtual void onTriggered() = 0;
  AppContext& app() const { return app_; }

 private:
  QAction* action_;
  AppContext& app_;
};

}  // namespace plumb::ui
