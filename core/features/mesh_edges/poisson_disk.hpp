#pragma once
// Poisson-disk sampling of a triangle mesh (2023 §IV-A, for simulation and cloud-to-model QA):
// dense area-uniform candidates, then greedy elimination in a seeded random order so that no
// two kept samples are closer than `radius`. Deterministic for a seed.
#include <cstdint>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

struct PoissonDiskParams {
  double radius = 0.05;          ///< minimum distance between samples, metres, (0, 100]
  double candidates_per_disk = 8; ///< candidate density: candidates per radius^2*pi, [1, 100]
  std::uint64_t seed = 42;
  static const ParamSchema<PoissonDiskParams>& schema();
};

/// Samples the mesh; the cloud carries positions (offset = mesh bounds minimum) and normals.
PointCloud samplePoissonDisk(const TriangleMesh& mesh, const PoissonDiskParams& params = {},
                             Progress* progress = nullptr);

}  // namespace plumb
