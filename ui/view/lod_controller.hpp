#pragma once
// Level of detail: layers draw their reduced representation while the camera moves and the
// full one once the camera has been still for a short while. The size of the reduced
// representation adapts to the measured frame times of moving frames (LodBudget).
#include <QObject>
#include <QTimer>

#include "ui/view/lod_budget.hpp"

namespace plumb::ui {

class Scene;
class VtkViewWidget;

class LodController : public QObject {
  Q_OBJECT
 public:
  /// Full detail returns after the camera has been still this long.
  static constexpr int kSettleMs = 250;
  LodController(VtkViewWidget& view, Scene& scene, QObject* parent = nullptr);
  const LodBudget& budget() const { return budget_; }

 private:
  VtkViewWidget& view_;
  Scene& scene_;
  void onFrame(double ms);
  QTimer settle_;
  LodBudget budget_;
  bool moving_ = false;
  int moving_frames_ = 0;  ///< frames drawn since the interaction started
  /// Frames not to measure: the first after a switch or a budget change uploads the subset.
  int skip_frames_ = 0;
};

}  // namespace plumb::ui
