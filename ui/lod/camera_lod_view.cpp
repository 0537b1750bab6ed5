#include "ui/lod/camera_lod_view.hpp"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>

#include <algorithm>
#include <cmath>

namespace plumb::ui {

CameraState cameraState(vtkCamera& camera, int width, int height) {
  CameraState s;
  const double aspect = height > 0 ? double(width) / double(height) : 1.0;
  vtkMatrix4x4* m = camera.GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s.view_projection(r, c) = m->GetElement(r, c);
  double eye[3];
  camera.GetPosition(eye);
  s.eye = Eigen::Vector3d(eye[0], eye[1], eye[2]);
  s.viewport_height_px = std::max(1, height);
  s.fov_y_deg = camera.GetViewAngle();
  s.parallel_scale = camera.GetParallelProjection() ? camera.GetParallelScale() : 0.0;
  return s;
}

LodView lodViewInDataset(const CameraState& camera, const Eigen::Vector3d& origin,
                         const RigidTransform& dataset_to_world) {
  // render = T * p - origin, so clip = VP_render * M * p with M = [R, t - origin].
  Eigen::Matrix4d to_render = Eigen::Matrix4d::Identity();
  to_render.block<3, 3>(0, 0) = dataset_to_world.rotation();
  to_render.block<3, 1>(0, 3) = dataset_to_world.translation() - origin;
  LodView v;
  v.view_projection = camera.view_projection * to_render;
  v.eye = dataset_to_world.rotation().transpose() * (camera.eye + origin - dataset_to_world.translation());
  v.viewport_height_px = camera.viewport_height_px;
  v.fov_y_rad = camera.fov_y_deg * M_PI / 180.0;
  if (camera.parallel_scale > 0) v.metres_per_pixel = 2.0 * camera.parallel_scale / camera.viewport_height_px;
  return v;
}

}  // namespace plumb::ui
