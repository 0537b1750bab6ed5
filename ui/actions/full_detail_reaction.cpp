#include "ui/actions/full_detail_reaction.hpp"

#include "ui/view/lod_controller.hpp"

namespace plumb::ui {

FullDetailReaction::FullDetailReaction(QAction* action, AppContext& app, LodController& lod)
    : Reaction(action, app), lod_(lod) {
  action->setCheckable(true);
  action->setChecked(lod_.fullDetailWhenStill());
  action->setToolTip(tr("Draw every point when the camera stops, even if the frame takes "
                        "seconds and the window does not respond meanwhile"));
}

void FullDetailReaction::onTriggered() { lod_.setFullDetailWhenStill(action()->isChecked()); }

}  // namespace plumb::ui
