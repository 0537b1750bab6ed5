#include "ui/actions/registration_step_reaction.hpp"

#include "ui/app_context.hpp"
#include "ui/registration/registration_panel.hpp"

namespace plumb::ui {

RegistrationStepReaction::RegistrationStepReaction(QAction* action, AppContext& app, Step step)
    : Reaction(action, app), step_(step) {}

void RegistrationStepReaction::onTriggered() {
  RegistrationPanel* panel = app().registration;
  if (!panel) return;
  switch (step_) {
    case Step::DetectFeatures: panel->detectFeatures(); break;
    case Step::Register: panel->startRegistration(); break;
    case Step::ColourByDistance: panel->colourByDistance(); break;
    case Step::Accept: panel->accept(); break;
    case Step::Revert: panel->revert(); break;
  }
}

}  // namespace plumb::ui
