#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// View > Reset camera: iso view of everything visible.
class ResetCameraReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
