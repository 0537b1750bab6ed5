#pragma once
#include "ui/actions/reaction.hpp"
#include "ui/view/standard_view.hpp"

namespace plumb::ui {

/// View > Top/Front/Side/Iso...: places the camera along a standard direction.
class StandardViewReaction : public Reaction {
  Q_OBJECT
 public:
  StandardViewReaction(QAction* action, AppContext& app, StandardView view);

 protected:
  void onTriggered() override;

 private:
  StandardView view_;
};

}  // namespace plumb::ui
