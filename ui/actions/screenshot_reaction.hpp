#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// File > Export screenshot: writes the view as PNG.
class ScreenshotReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
