#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// File > Open project: replaces the scene with a project's layers and setup. Disabled while
/// a running task holds layers (its result would go to a removed layer).
class OpenProjectReaction : public Reaction {
  Q_OBJECT
 public:
  OpenProjectReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
  bool canRun() const override;
};

/// File > Save project: layers (files, transforms, visibility) and registration setup.
class SaveProjectReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
