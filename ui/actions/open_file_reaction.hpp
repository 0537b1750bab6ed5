#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// File > Open: choose files and load them in the background.
class OpenFileReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
