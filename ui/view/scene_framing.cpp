#include "ui/view/scene_framing.hpp"

#include "ui/layers/layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

void frameScene(const Scene& scene, VtkViewWidget& widget, StandardView view) {
  const Bounds world = scene.visibleFramingBounds();
  double b[6];
  if (!world.empty()) scene.renderBounds(world, b);
  applyStandardView(widget.renderer(), view, world.empty() ? nullptr : b);
  widget.requestRender();
}

namespace {
/// The current camera direction fitted to `world`; renders. False (nothing done) when empty.
bool zoomToWorld(const Scene& scene, VtkViewWidget& widget, const Bounds& world) {
  if (world.empty()) return false;
  double b[6];
  scene.renderBounds(world, b);
  zoomToBounds(widget.renderer(), b);
  widget.requestRender();
  return true;
}
}  // namespace

bool frameLayer(const Scene& scene, VtkViewWidget& widget, const Layer& layer) {
  return zoomToWorld(scene, widget, layer.framingBounds());
}

bool frameVisible(const Scene& scene, VtkViewWidget& widget) {
  return zoomToWorld(scene, widget, scene.visibleFramingBounds());
}

}  // namespace plumb::ui
