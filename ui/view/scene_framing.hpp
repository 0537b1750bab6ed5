#pragma once
// Camera framing of the scene on its robust bounds (issue 17: a few far returns made the default
// view frame 140 m of ground around a house, and Zoom to layer zoom out).
#include "ui/view/standard_view.hpp"

namespace plumb::ui {

class Scene;
class Layer;
class VtkViewWidget;

/// The standard view `view` fitted to the visible layers' framing bounds (every prop when the
/// scene has none); renders.
void frameScene(const Scene& scene, VtkViewWidget& widget, StandardView view = StandardView::Iso);
/// The current camera direction fitted to `layer`'s framing bounds; renders. False when the
/// layer has no bounds.
bool frameLayer(const Scene& scene, VtkViewWidget& widget, const Layer& layer);
/// The current camera direction fitted to the visible layers' framing bounds; renders. False
/// when nothing visible has bounds.
bool frameVisible(const Scene& scene, VtkViewWidget& widget);

}  // namespace plumb::ui
