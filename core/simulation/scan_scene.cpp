#include "simulation/scan_scene.hpp"

namespace plumb {

ScanScene::ScanScene(const BimModel& model, const std::vector<bool>& glass, const ScanSceneOptions& options) {
  TriangleMesh mesh;
  mesh.vertices = model.mesh.vertices;
  mesh.triangles = model.mesh.triangles;
  model_triangles_ = mesh.triangles.size();
  std::vector<bool> skip(mesh.triangles.size(), false);
  if (options.glass_transparent && glass.size() == skip.size()) skip = glass;
  const Bounds b = model.mesh.bounds();
  if (options.ground && !b.empty()) {
    const double m = options.ground_margin, z = b.min.z();
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.emplace_back(b.min.x() - m, b.min.y() - m, z);
    mesh.vertices.emplace_back(b.max.x() + m, b.min.y() - m, z);
    mesh.vertices.emplace_back(b.max.x() + m, b.max.y() + m, z);
    mesh.vertices.emplace_back(b.min.x() - m, b.max.y() + m, z);
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first, first + 2, first + 3});
    skip.insert(skip.end(), 2, false);
  }
  caster_ = std::make_unique<RayCaster>(mesh, std::move(skip), options.backend);
}

}  // namespace plumb
