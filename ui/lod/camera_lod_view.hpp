#pragma once
// The view of a level-of-detail cache (io/lod/lod_select.hpp) from the VTK camera: the cache
// is in its dataset's frame, the camera in render coordinates (world - scene origin, see
// ui/layers/render_frame.hpp), and the dataset is drawn through its registration transform.
#include <Eigen/Core>

#include "io/lod/lod_select.hpp"
#include "model/rigid_transform.hpp"

class vtkCamera;

namespace plumb::ui {

/// `view_projection` (VTK's composite projection of the camera, render frame), `eye` (render
/// frame), the viewport height in pixels, the camera's parallel scale when orthographic (0:
/// perspective, `fov_y_deg` used), the scene origin and the dataset -> world transform.
struct CameraState {
  Eigen::Matrix4d view_projection = Eigen::Matrix4d::Identity();
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  double viewport_height_px = 1000;
  double fov_y_deg = 30;
  double parallel_scale = 0;  ///< > 0: orthographic, half the view's height in metres
};

/// Reads the camera's state for a viewport of `width` x `height` pixels.
CameraState cameraState(vtkCamera& camera, int width, int height);

/// The camera as a LodView in the cache's (dataset) frame.
LodView lodViewInDataset(const CameraState& camera, const Eigen::Vector3d& origin,
                         const RigidTransform& dataset_to_world);

}  // namespace plumb::ui
