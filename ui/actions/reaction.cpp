#include "ui/actions/reaction.hpp"

namespace plumb::ui {

Reaction::Reaction(QAction* action, AppContext& app) : QObject(action), action_(action), app_(app) {
  connect(action, &QAction::triggered, this, [this] { onTriggered(); });
}

}  // namespace plumb::ui
