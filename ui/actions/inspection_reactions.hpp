#pragma once
// View menu inspection actions: the measuring tool and the projection.
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// View > Measure point / distance (M, checkable): turns the MeasureTool on and off; manual
/// pair picking pauses while it is on.
class MeasureReaction : public Reaction {
  Q_OBJECT
 public:
  MeasureReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
};

/// View > Orthographic projection (O, checkable): parallel projection for plan and section views
/// (distances read the same across the view); off: perspective.
class ProjectionReaction : public Reaction {
  Q_OBJECT
 public:
  ProjectionReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
