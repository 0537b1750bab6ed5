#include "ui/view/standard_view.hpp"

#include <vtkCamera.h>
#include <vtkRenderer.h>

namespace plumb::ui {

namespace {

struct Placement {
  double direction[3];  ///< from focal point towards the camera
  double up[3];
};

Placement placementOf(StandardView view) {
  switch (view) {
    case StandardView::Top: return {{0, 0, 1}, {0, 1, 0}};
    case StandardView::Bottom: return {{0, 0, -1}, {0, 1, 0}};
    case StandardView::Front: return {{0, -1, 0}, {0, 0, 1}};
    case StandardView::Back: return {{0, 1, 0}, {0, 0, 1}};
    case StandardView::Left: return {{-1, 0, 0}, {0, 0, 1}};
    case StandardView::Right: return {{1, 0, 0}, {0, 0, 1}};
    case StandardView::Iso: break;
  }
  return {{1, -1, 1}, {0, 0, 1}};
}

}  // namespace

void applyStandardView(vtkRenderer* renderer, StandardView view, const double* bounds) {
  vtkCamera* camera = renderer->GetActiveCamera();
  const Placement p = placementOf(view);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(p.direction);
  camera->SetViewUp(p.up);
  if (bounds) renderer->ResetCamera(bounds);
  else renderer->ResetCamera();
  renderer->ResetCameraClippingRange();
}

void zoomToBounds(vtkRenderer* renderer, const double bounds[6]) {
  renderer->ResetCamera(bounds);
  renderer->ResetCameraClippingRange();
}

void resetCamera(vtkRenderer* renderer) { applyStandardView(renderer, StandardView::Iso); }

}  // namespace plumb::ui
