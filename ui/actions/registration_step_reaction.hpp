#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// Registration > Detect features / Register / Colour by distance / Accept / Revert: runs
/// that step of the Registration dock.
class RegistrationStepReaction : public Reaction {
  Q_OBJECT
 public:
  enum class Step { DetectFeatures, Register, ColourByDistance, Accept, Revert };
  RegistrationStepReaction(QAction* action, AppContext& app, Step step);

 protected:
  void onTriggered() override;

 private:
  Step step_;
};

}  // namespace plumb::ui
