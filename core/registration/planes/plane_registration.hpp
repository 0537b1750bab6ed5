#pragma once
// Plane-based registration (2021 §3.2-3.4, docs/ALGORITHMS.md §4), indoor/indoor and
// indoor/outdoor:
//  1. Cluster polygon normals (2021 Alg. 1, one angle tolerance).
//  2. Rotations from cluster frames (eqs. 11-19), enumerating every association and sign
//     (+ up/down flip when enabled), not only the smallest-angle pairing of eq. 11.
//  3. Translations from three plane pairs of three associated clusters with independent
//     normals (eq. 22 with the sign of eq. 21 derived from n' = R n, d' = d + n'·t), with a
//     conditioning check. Rather than all of I1 x I2 x I3, the candidate offsets of each
//     association are reduced to their strongest modes (pairs agreeing within d_thr, weighted
//     by area) and every triple of modes is tried.
//  4. Each hypothesis is scored by the polygon overlap similarity (eq. 10 as a similarity,
//     raster overlap areas); the best one is polished by least squares on all matched pairs.
#include <cstdint>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "registration/clustering/direction_clustering.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/common/rotation_from_directions.hpp"

namespace plumb {

struct PlaneRegistrationParams {
  /// cluster-angle 10°, max-clusters 6 (nested in the schema; cluster-angle is also the
  /// rotation enumeration's tolerance).
  DirectionClusteringParams clustering;
  RotationEnumerationParams rotations;   ///< Z-up, tilt <= 10° (nested in the schema)
  /// d_thr of eq. 10, metres, [0.005, 5]: polygon pairs farther apart do not count.
  double distance_threshold = 0.10;
  /// Normals are oriented consistently in both datasets (e.g. towards the scanner, see
  /// orientTowards()): only pairs facing the same way match. Separates a ceiling from the floor
  /// above it (slab thickness) and a wall's two faces.
  bool oriented_normals = false;
  /// Offset modes kept per cluster association, [1, 50]; hypotheses = rotations x modes^3.
  int modes_per_association = 8;
  /// Minimum conditioning of the 3x3 system of eq. 22 (smallest / largest singular value), [0, 1].
  double min_conditioning = 0.2;
  /// Polygons smaller than this are ignored, m^2, [0, 100].
  double min_polygon_area = 0.25;
  /// Raster resolution of polygons for the overlap areas (cells on the longer side), [16, 4096].
  int raster_cells = 128;
  /// Acceptance: minimum similarity (m^2 of overlap at zero distance), [0, 1e6].
  double min_score = 2.0;
  /// Ambiguity: the runner-up must score at least this fraction below the best, [0, 1].
  double min_relative_gap = 0.05;
  /// Hypotheses are pre-scored with coarse overlaps; this many best are rescored exactly, [1, 1e5].
  int rescored_hypotheses = 48;
  /// Least-squares polish iterations on matched pairs, [0, 50].
  int polish_iterations = 3;
  static const ParamSchema<PlaneRegistrationParams>& schema();
};

/// Flips polygon normals (and their frames) to face `viewpoint`, e.g. the scanner position.
void orientTowards(std::vector<PlanarPolygon>& planes, const Eigen::Vector3d& viewpoint);

/// Eq. 10 similarity of `source` mapped by `t` against `target` (m^2), for reports and tests.
double planeSimilarity(const std::vector<PlanarPolygon>& source,
                       const std::vector<PlanarPolygon>& target, const RigidTransform& t,
                       const PlaneRegistrationParams& params);

/// Registers source polygons onto target polygons.
GlobalRegistrationResult registerPlanes(const std::vector<PlanarPolygon>& source,
                                        const std::vector<PlanarPolygon>& target,
                                        const PlaneRegistrationParams& params,
                                        Progress* progress = nullptr);

}  // namespace plumb
