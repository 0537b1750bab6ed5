#pragma once
// Small synthetic input for the Registration dock's GUI tests: the surfaces of a room with a
// pillar (well constrained in every direction for ICP), as a scan sampled on a grid and as a
// triangle model. Small enough that every task finishes in a second or two.
#include <Eigen/Geometry>

#include <array>
#include <filesystem>
#include <fstream>
#include <memory>
#include <vector>

#include "model/bim_model.hpp"
#include "model/dataset.hpp"

namespace plumb::test {

/// Axis-aligned boxes of the room: the room (8 x 6 x 3 m) and a pillar off its centre.
inline std::vector<std::array<Eigen::Vector3d, 2>> roomBoxes() {
  return {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(8, 6, 3)},
          {Eigen::Vector3d(2.5, 1.5, 0), Eigen::Vector3d(3.1, 2.3, 3)}};
}

/// Points on every face of roomBoxes() every `spacing` metres, moved by `pose`; the layer
/// showing it is called `name`.ply.
inline std::shared_ptr<const Dataset> roomScan(double spacing, const RigidTransform& pose,
                                               const std::string& name) {
  PointCloud cloud;
  for (const auto& [lo, hi] : roomBoxes())
    for (int axis = 0; axis < 3; ++axis)
      for (double side : {lo[axis], hi[axis]}) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (double a = lo[u]; a <= hi[u] + 1e-9; a += spacing)
          for (double b = lo[v]; b <= hi[v] + 1e-9; b += spacing) {
            Eigen::Vector3d p;
            p[axis] = side, p[u] = a, p[v] = b;
            cloud.positions.push_back(pose.apply(p).cast<float>());
          }
      }
  auto data = std::make_shared<Dataset>(Dataset::fromCloud(std::move(cloud), name));
  data->source = name + ".ply";  // names the layer; nothing is read from it
  return data;
}

/// A copy of `data` whose points carry timestamps, 1 ms apart in point order (a mobile scan
/// without sensor origins, for attaching a trajectory).
inline std::shared_ptr<const Dataset> withTimestamps(const std::shared_ptr<const Dataset>& data) {
  auto timed = std::make_shared<Dataset>(*data);
  for (Scan& scan : timed->scans)
    for (std::size_t i = 0; i < scan.cloud.size(); ++i) scan.cloud.timestamps.push_back(0.001 * double(i));
  return timed;
}

/// A trajectory file ("t x y z") crossing the room at mid height over the times of
/// withTimestamps for `points` points.
inline std::filesystem::path writeRoomTrajectory(const std::filesystem::path& path, std::size_t points) {
  std::ofstream(path) << "# t x y z\n-1 1 3 1.5\n" << 0.001 * double(points) + 1.0 << " 7 3 1.5\n";
  return path;
}

/// The faces of roomBoxes() as triangles (two per face).
inline std::shared_ptr<const BimModel> roomModel() {
  auto model = std::make_shared<BimModel>();
  model->format = "test";
  model->elements.push_back({"IfcWall", "room", ""});
  TriangleMesh& m = model->mesh;
  for (const auto& [lo, hi] : roomBoxes())
    for (int axis = 0; axis < 3; ++axis)
      for (double side : {lo[axis], hi[axis]}) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const auto base = static_cast<std::uint32_t>(m.vertices.size());
        for (const auto& [a, b] : {std::pair{lo[u], lo[v]}, {hi[u], lo[v]}, {hi[u], hi[v]}, {lo[u], hi[v]}}) {
          Eigen::Vector3d p;
          p[axis] = side, p[u] = a, p[v] = b;
          m.vertices.push_back(p);
        }
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
      }
  model->triangle_element.assign(m.triangles.size(), 0);
  return model;
}

/// The scan's pose in the tests: 1 degree about z and a few centimetres off.
inline RigidTransform scanOffset() {
  return RigidTransform(Eigen::AngleAxisd(0.0175, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                        Eigen::Vector3d(0.06, -0.04, 0.02));
}

}  // namespace plumb::test
