#include "ui/view/lod_controller.hpp"

#include <QLocale>

#include <limits>

#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {

LodBudget::Params movingParams() {
  LodBudget::Params p;
  p.target_ms = LodController::kMovingTargetMs;
  return p;
}

LodBudget::Params stillParams() {
  LodBudget::Params p;
  p.target_ms = LodController::kStillTargetMs;
  p.min_points = 20'000;
  p.max_points = std::numeric_limits<std::size_t>::max() / 2;  // bounded by the scene instead
  p.initial_points = LodController::kInitialStillPoints;
  // One still frame is drawn per camera stop: take the measured step at once (undamped,
  // within the fixed cost of the target, see LodBudget::Params::damped), growing at most 64x
  // (a GPU reaches full detail from the initial subset in one or two frames).
  p.damped = false;
  p.max_growth = 64.0;
  p.dead_band = 0.2;
  return p;
}

std::size_t visiblePoints(const Layer& layer) {
  if (!layer.effectivelyVisible()) return 0;
  std::size_t n = 0;
  if (layer.kind() == LayerKind::Scan) n += static_cast<const ScanLayer&>(layer).scan().cloud.size();
  for (const auto& c : layer.children()) n += visiblePoints(*c);
  return n;
}

}  // namespace

QString detailStatusText(std::size_t drawn, std::size_t total) {
  if (drawn >= total) return {};
  QLocale c;
  c.setNumberOptions(c.numberOptions() & ~QLocale::OmitGroupSeparator);
  return QObject::tr("Showing %1 of %2 points")
      .arg(c.toString(static_cast<qulonglong>(drawn)), c.toString(static_cast<qulonglong>(total)));
}

LodController::LodController(VtkViewWidget& view, Scene& scene, QObject* parent)
    : QObject(parent), view_(view), scene_(scene), budget_(movingParams()), still_(stillParams()) {
  scene_.setLodBudget(budget_.points());
  settle_.setSingleShot(true);
  settle_.setInterval(kSettleMs);
  // Every frame is timed to its end (glFinish): moving and still frames both feed a budget.
  view_.setFrameTiming(true);
  connect(&view_, &VtkViewWidget::interactionStarted, this, &LodController::startMoving);
  connect(&view_, &VtkViewWidget::interactionEnded, this, &LodController::stopMoving);
  connect(&view_, &VtkViewWidget::frameRendered, this, &LodController::onFrame);
  connect(&settle_, &QTimer::timeout, this, &LodController::showStill);
  // New, removed, shown or hidden layers change what a still frame may draw: apply the still
  // budget before their first frame (scene signals come before the view's next paint).
  auto rescope = [this] {
    if (!moving_ && !settle_.isActive()) applyStill();
  };
  connect(&scene_, &Scene::layersChanged, this, rescope);
  connect(&scene_, &Scene::renderNeeded, this, rescope);
  applyStill();
}

void LodController::startMoving() {
  settle_.stop();
  refine_pending_ = false;
  moving_ = true;
  moving_frames_ = 0;
  scene_.setLodBudget(budget_.points());  // unchanged budget: nothing to do
  scene_.setMovingDetail(true);            // toggles the scans' actors only
  skip_frames_ = 1;
}

void LodController::stopMoving() {
  moving_ = false;
  // A click (no frame drawn while "moving") goes straight back to still detail: waiting for
  // the settle delay would draw one reduced frame and then one still frame for nothing.
  if (moving_frames_ == 0) {
    applyStill();
    return;
  }
  settle_.start();
}

void LodController::showStill() {
  settle_.stop();
  moving_ = false;
  applyStill();
  view_.requestRender();
}

void LodController::setFullDetailWhenStill(bool on) {
  if (on == force_full_) return;
  force_full_ = on;
  if (!moving_) showStill();
}

std::size_t LodController::totalPointCount() const {
  std::size_t n = 0;
  for (const auto& l : scene_.layers()) n += visiblePoints(*l);
  return n;
}

void LodController::applyStill() {
  const std::size_t total = totalPointCount();
  // The still subsets are kept while moving: back to still only toggles actors, unless the
  // still budget changed (then each scan makes a new prefix poly data, no copy).
  scene_.setStillBudget(force_full_ || still_.points() >= total ? Scene::kFullDetail
                                                                : still_.points());
  scene_.setMovingDetail(false);
  updateDetailText();
}

void LodController::updateDetailText() {
  const QString text = detailStatusText(scene_.drawnPointCount(), totalPointCount());
  if (text == detail_text_) return;
  detail_text_ = text;
  emit detailTextChanged(detail_text_);
}

void LodController::onFrame(double ms) {
  if (!moving_) {
    if (!settle_.isActive()) onStillFrame(ms);
    return;
  }
  updateDetailText();
  if (!scene_.movingDetail()) return;
  ++moving_frames_;
  if (skip_frames_ > 0) {
    --skip_frames_;
    return;
  }
  if (budget_.addFrame(scene_.drawnPointCount(), ms)) {
    scene_.setLodBudget(budget_.points());
    skip_frames_ = 1;
  }
}

void LodController::onStillFrame(double ms) {
  refine_pending_ = false;
  const std::size_t drawn = scene_.drawnPointCount();
  updateDetailText();
  emit stillFrameDrawn(ms, drawn);
  if (drawn == 0 || !still_.addFrame(drawn, ms)) return;
  // The budget grew past what was drawn: draw the larger subset in a later turn of the event
  // loop (input first), within the target again. A smaller budget waits for the next stop.
  if (force_full_ || still_.points() <= drawn || drawn >= totalPointCount()) return;
  refine_pending_ = true;
  QTimer::singleShot(0, this, [this, drawn] {
    if (moving_ || !refine_pending_) return;
    applyStill();
    if (scene_.drawnPointCount() > drawn) {
      view_.requestRender();
    } else {
      refine_pending_ = false;  // nothing more to draw
    }
  });
}

}  // namespace plumb::ui
