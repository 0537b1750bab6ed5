#include "ui/layers/render_frame.hpp"

#include <vtkMatrix4x4.h>

namespace plumb::ui {

Eigen::Matrix4d anchorMatrix(const Eigen::Vector3d& anchor) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 1>(0, 3) = anchor;
  return m;
}

vtkSmartPointer<vtkMatrix4x4> renderMatrix(const Eigen::Vector3d& origin,
                                           const Eigen::Matrix4d& local_to_world) {
  Eigen::Matrix4d m = local_to_world;
  m.block<3, 1>(0, 3) -= origin;
  auto out = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out->SetElement(r, c, m(r, c));
  return out;
}

Bounds transformBounds(const Bounds& local, const Eigen::Matrix4d& local_to_world) {
  Bounds out;
  if (local.empty()) return out;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector4d corner((i & 1) ? local.max.x() : local.min.x(),
                                 (i & 2) ? local.max.y() : local.min.y(),
                                 (i & 4) ? local.max.z() : local.min.z(), 1.0);
    out.extend(Eigen::Vector3d((local_to_world * corner).head<3>()));
  }
  return out;
}

void toRenderBounds(const Bounds& world, const Eigen::Vector3d& origin, double out[6]) {
  for (int k = 0; k < 3; ++k) {
    out[2 * k] = world.min[k] - origin[k];
    out[2 * k + 1] = world.max[k] - origin[k];
  }
}

}  // namespace plumb::ui
