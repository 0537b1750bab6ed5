#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// View > Zoom to layer: fits the camera to the current layer (all visible layers if none).
class ZoomToLayerReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
