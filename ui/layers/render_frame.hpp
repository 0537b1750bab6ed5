#pragma once
// Render coordinates: world coordinates minus a scene origin (double), so georeferenced data
// (coordinates in the millions) keeps its precision in VTK's float vertex buffers. Geometry
// stays in its local float frame; each actor's user matrix carries local -> render in double.
#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include "model/point_cloud.hpp"

#include <vtkMatrix4x4.h>

namespace plumb::ui {

/// Local coordinates relative to `anchor` -> the frame `anchor` is in: a translation (the
/// float geometry of scans, models, features and detail is stored relative to such an anchor).
Eigen::Matrix4d anchorMatrix(const Eigen::Vector3d& anchor);
/// Actor matrix: render = local_to_world * local - origin.
vtkSmartPointer<vtkMatrix4x4> renderMatrix(const Eigen::Vector3d& origin,
                                           const Eigen::Matrix4d& local_to_world);
/// Axis-aligned box of the 8 corners of `local` mapped by `local_to_world`.
Bounds transformBounds(const Bounds& local, const Eigen::Matrix4d& local_to_world);
/// VTK bounds (xmin,xmax,ymin,ymax,zmin,zmax) in render coordinates.
void toRenderBounds(const Bounds& world, const Eigen::Vector3d& origin, double out[6]);

}  // namespace plumb::ui
