#include "ui/actions/network_reaction.hpp"

#include <QDockWidget>
#include <QMainWindow>

#include "ui/app_context.hpp"
#include "ui/network/network_panel.hpp"

namespace plumb::ui {

NetworkReaction::NetworkReaction(QAction* action, AppContext& app) : Reaction(action, app) {
  action->setToolTip(tr("Register every scan of the open point datasets as one network of stations"));
}

void NetworkReaction::onTriggered() {
  if (!app().network) return;
  for (QWidget* w = app().network; w; w = w->parentWidget())
    if (auto* dock = qobject_cast<QDockWidget*>(w)) {
      dock->show();
      dock->raise();
      return;
    }
}

}  // namespace plumb::ui
