#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

class LodController;

/// View > Full detail when still (may be slow): a checkable action; on, the still frame draws
/// every point however long it takes (software OpenGL: seconds for millions of points), off,
/// the still frame keeps to its time budget (LodController).
class FullDetailReaction : public Reaction {
  Q_OBJECT
 public:
  FullDetailReaction(QAction* action, AppContext& app, LodController& lod);

 protected:
  void onTriggered() override;

 private:
  LodController& lod_;
};

}  // namespace plumb::ui
