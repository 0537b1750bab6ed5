#pragma once
// View menu inspection actions: the measuring tool and the projection.
#include <QTimer>

#include "ui/actions/reaction.hpp"
#include "ui/layers/layer.hpp"

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

/// View > Blink before/after (B, checkable): the registration source (else the current dataset)
/// shown alternately without and with its registration transform every `kPeriodMs`, to judge a
/// registration by eye; off (or the layer removed): shown registered again.
class BlinkReaction : public Reaction {
  Q_OBJECT
 public:
  static constexpr int kPeriodMs = 500;
  BlinkReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;

 private:
  void tick();
  void stop();
  QTimer timer_;
  LayerRef layer_;
};

}  // namespace plumb::ui
