#pragma once
// Standard camera placements (Z up, as scans and converted BIM models are).
class vtkRenderer;

namespace plumb::ui {

enum class StandardView { Top, Bottom, Front, Back, Left, Right, Iso };

/// Points the camera of `renderer` along the standard direction and fits `bounds` (render
/// coordinates: xmin,xmax,ymin,ymax,zmin,zmax), or every visible prop when null.
void applyStandardView(vtkRenderer* renderer, StandardView view, const double* bounds = nullptr);
/// Fits the camera to a box given in render coordinates (xmin,xmax,ymin,ymax,zmin,zmax).
void zoomToBounds(vtkRenderer* renderer, const double bounds[6]);
/// Iso view of everything visible.
void resetCamera(vtkRenderer* renderer);

}  // namespace plumb::ui
