#include "io/lod/lod_select.hpp"

#include <cmath>

namespace plumb {

LodView lodPerspectiveView(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double fov_y_rad, double aspect,
                           double viewport_height_px, double near, double far) {
  const Eigen::Vector3d f = (target - eye).normalized();
  Eigen::Vector3d s = f.cross(Eigen::Vector3d::UnitZ());
  if (s.norm() < 1e-9) s = f.cross(Eigen::Vector3d::UnitY());  // looking straight up or down
  s.normalize();
  const Eigen::Vector3d u = s.cross(f);
  // The view matrix works on (p - eye): exact for national-grid coordinates.
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = s.transpose();
  view.block<1, 3>(1, 0) = u.transpose();
  view.block<1, 3>(2, 0) = -f.transpose();
  view(0, 3) = -s.dot(eye), view(1, 3) = -u.dot(eye), view(2, 3) = f.dot(eye);
  const double t = 1 / std::tan(fov_y_rad / 2);
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = t / aspect, proj(1, 1) = t;
  proj(2, 2) = -(far + near) / (far - near), proj(2, 3) = -2 * far * near / (far - near), proj(3, 2) = -1;
  LodView v;
  v.eye = eye;
  v.view_projection = proj * view;
  v.fov_y_rad = fov_y_rad;
  v.viewport_height_px = viewport_height_px;
  return v;
}

}  // namespace plumb
