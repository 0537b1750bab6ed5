#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// Edit > Remove layer: removes the current root layer.
class RemoveLayerReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
