#pragma once
// Level of detail with two adaptive budgets (LodBudget), both learned from measured frame
// times, so that no frame blocks the UI thread (VTK renders in paintGL) for long:
//  - moving: while the camera moves, a small random subset sized for kMovingTargetMs per frame;
//  - still: once the camera has been still for kSettleMs, the largest subset that renders in
//    about kStillTargetMs, or the full clouds when they fit (a GPU draws 20 M points in a few
//    tens of ms; software GL needs seconds). When a still frame was much faster than the target,
//    the next larger subset is drawn in a later event-loop turn (each such frame again within
//    the target) until the still budget settles or everything is drawn.
// "Full detail when still" (View menu) forces the full clouds when still, however long they take.
// Layers added while still (loading a file) get the still budget too: loading 20 M points does
// not freeze the UI on its first frame either.
#include <QObject>
#include <QString>
#include <QTimer>

#include "ui/view/lod_budget.hpp"

namespace plumb::ui {

class Scene;
class VtkViewWidget;

class LodController : public QObject {
  Q_OBJECT
 public:
  /// The still frame is drawn after the camera has been still this long.
  static constexpr int kSettleMs = 250;
  /// Frame time aimed at while the camera moves, ms.
  static constexpr double kMovingTargetMs = 50.0;
  /// Frame time aimed at for still frames, ms: the longest the UI thread is blocked by a frame.
  static constexpr double kStillTargetMs = 400.0;
  /// Still budget before any still frame was measured (about 0.3 s on software GL).
  static constexpr std::size_t kInitialStillPoints = 400'000;

  LodController(VtkViewWidget& view, Scene& scene, QObject* parent = nullptr);
  const LodBudget& budget() const { return budget_; }
  const LodBudget& stillBudget() const { return still_; }

  /// View > "Full detail when still": the still frame draws every point, however slow.
  void setFullDetailWhenStill(bool on);
  bool fullDetailWhenStill() const { return force_full_; }

  /// What the camera does (connected to the view's interaction signals; public for benchmarks).
  void startMoving();
  void stopMoving();
  /// The camera is still: applies the still detail and asks for a frame.
  void showStill();
  bool moving() const { return moving_; }
  /// A larger still subset is waiting for its frame (progressive refinement).
  bool refinementPending() const { return refine_pending_; }
  /// Still, the still frame drawn and no larger subset waiting.
  bool settled() const { return !moving_ && !settle_.isActive() && !refine_pending_; }

  /// Points of the visible scans (what full detail draws).
  std::size_t totalPointCount() const;
  /// "Showing N of M points" while fewer than all visible points are drawn, else empty.
  QString detailText() const { return detail_text_; }

 signals:
  /// The status text changed (empty: full detail).
  void detailTextChanged(const QString& text);
  /// A still frame drew `drawn` points in `ms` milliseconds.
  void stillFrameDrawn(double ms, std::size_t drawn);

 private:
  void onFrame(double ms);
  void onStillFrame(double ms);
  /// Still detail for the current scene: the still subset, or full clouds when they fit.
  void applyStill();
  void updateDetailText();

  VtkViewWidget& view_;
  Scene& scene_;
  QTimer settle_;
  LodBudget budget_;
  LodBudget still_;
  bool moving_ = false;
  bool force_full_ = false;
  bool refine_pending_ = false;
  int moving_frames_ = 0;  ///< frames drawn since the interaction started
  /// Frames not to measure: the first after a switch or a budget change uploads the subset.
  int skip_frames_ = 0;
  QString detail_text_;
};

/// "Showing N of M points" (N < M), numbers with the locale's group separators; empty when
/// N >= M.
QString detailStatusText(std::size_t drawn, std::size_t total);

}  // namespace plumb::ui
