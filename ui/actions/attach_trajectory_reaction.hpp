#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// File > Attach trajectory: asks for the vehicle trajectory ("t x y z" per line) of the current
/// mobile scan and gives its points sensor origins in the background (startAttachTrajectory),
/// as `plumb-cli register --source-trajectory/--target-trajectory` does.
class AttachTrajectoryReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
