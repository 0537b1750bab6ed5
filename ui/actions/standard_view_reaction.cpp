#include "ui/actions/standard_view_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

StandardViewReaction::StandardViewReaction(QAction* action, AppContext& app, StandardView view)
    : Reaction(action, app), view_(view) {}

void StandardViewReaction::onTriggered() {
  frameScene(app().scene, app().view, view_);
}

}  // namespace plumb::ui
