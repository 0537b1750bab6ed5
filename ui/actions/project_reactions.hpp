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

/// Asks where to save the project and saves it; the undo history's clean point moves there (the
/// applied transforms are saved). False when canceled or the write failed (logged).
bool saveProjectAs(AppContext& app);

}  // namespace plumb::ui
