#pragma once
// First-hit ray casting against a triangle mesh (any mesh: generated buildings, imported IFC).
// Backends: a CGAL AABB tree (always) and Embree (when libembree-dev is installed; compiled
// in with PLUMB_HAVE_EMBREE). Batches run in parallel with TBB; results do not depend on the
// thread count. The caster is immutable after construction and safe to share across threads.
#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "model/bim_model.hpp"

namespace plumb {

struct Ray {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< unit length
};

struct RayHit {
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  double distance = std::numeric_limits<double>::infinity();  ///< along the unit direction
  std::uint32_t triangle = kNone;  ///< index into the mesh given to the caster
  bool hit() const { return triangle != kNone; }
};

enum class RayCasterBackend { Cgal, Embree };

class RayCaster {
 public:
  /// Builds the acceleration structure over `mesh` (copied), skipping triangles with
  /// skip[i] true (e.g. glass the laser passes through); skip may be empty.
  /// Throws InputError if the Embree backend is requested but not available.
  RayCaster(const TriangleMesh& mesh, std::vector<bool> skip = {},
            RayCasterBackend backend = defaultBackend());
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  /// Nearest hit within (min_range, max_range]; RayHit{} when none.
  RayHit cast(const Ray& ray, double max_range = 1e30, double min_range = 0.0) const;
  /// Casts every ray in parallel (TBB); hits[i] for rays[i]. Any ray order (traced as
  /// incoherent packets in fixed chunks: identical results for any thread count).
  void castAll(const std::vector<Ray>& rays, std::vector<RayHit>& hits, double max_range = 1e30,
               double min_range = 0.0) const;

  /// Casts rays[0..n) on the calling thread; hits[i] for rays[i]. For rays in scan order (a
  /// scanner row or profile: neighbours have nearby origins and directions), which Embree
  /// traces as coherent packets. Deterministic for the same batch; a ray grazing a triangle
  /// edge may pick the neighbouring triangle compared with cast().
  void castBatch(const Ray* rays, std::size_t n, RayHit* hits, double max_range = 1e30,
                 double min_range = 0.0) const;

  const TriangleMesh& mesh() const;
  /// Unit normal of mesh() triangle t (precomputed; zero for degenerate triangles).
  const Eigen::Vector3d& triangleNormal(std::uint32_t t) const;
  RayCasterBackend backend() const { return backend_; }
  static bool embreeAvailable();
  /// Embree when available (much faster), else CGAL.
  static RayCasterBackend defaultBackend();
  static std::string backendName(RayCasterBackend b);

  struct Impl;  ///< backend implementation (cgal_ray_caster.cpp / embree_ray_caster.cpp)

 private:
  RayCasterBackend backend_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace plumb
