#pragma once
// Planar polygon extraction (2021 §2, docs/ALGORITHMS.md §1): detect planes, split each plane's
// inliers into connected parts, and outline each part with a 2D alpha shape (outer ring +
// holes). Three detectors share this entry point:
//  - Msac: MSAC (eq. 2) on the whole cloud, refit on inliers, remove, repeat.
//  - SensorTopology: RANSAC with samples drawn in the scan-grid neighbourhood of the first one
//    and region growing over grid adjacency (2021 §2.1); needs row/column (organized scan).
//  - RegionGrowing: PCL's normal-based region growing, then a least-squares plane per region.
// Auto = Msac, chosen by measurement (bench_features, 1.04 M point simulated indoor TLS of
// "house", 2 threads; tests/integration/features for the MMS scans):
//  - Msac: 1.5 s, wall recall 32/32, façade polygons keep their windows as holes; on the
//    simulated MMS of "house" 16/16 exterior openings within 5 cm.
//  - SensorTopology: 1.9 s, wall recall 32/32 but fragmented (hits max_planes = 60): grid
//    adjacency breaks where rays enter windows, so façades split into hole-less pieces and
//    ray tracing on the MMS of "house" finds 0/16 openings within 5 cm.
//  - RegionGrowing (PCL kNN normals + pcl::RegionGrowing): 13.3 s (9x slower), recall 32/32.
// SensorTopology and RegionGrowing stay available by name.
#include <cstdint>
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/seed.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

enum class PlaneDetector { Auto, Msac, SensorTopology, RegionGrowing };

struct PlaneExtractionParams {
  PlaneDetector detector = PlaneDetector::Auto;
  /// Inlier distance t of eq. (2), metres, [0.001, 1]. Ignored when auto_threshold is set.
  double distance_threshold = 0.02;
  /// Select the threshold by the a-contrario NFA criterion (2021 eqs. 3-6) among
  /// `threshold_candidates` values spread geometrically over
  /// [threshold_range_min, threshold_range_max]. Off by default: as printed, the criterion
  /// picks the smallest candidate whatever the noise (docs/ALGORITHMS.md §1, measured).
  bool auto_threshold = false;
  int threshold_candidates = 6;  ///< [2, 20]
  /// Range of the a-contrario candidates, metres, [0.001, 1]: 5 mm (below it TLS range noise
  /// splits walls) to 10 cm (above it a door leaf merges with its wall). min < max.
  double threshold_range_min = 0.005;
  double threshold_range_max = 0.1;
  /// Smallest plane (min_size of eq. 3), points, [3, 1e7]. Detection stops below it.
  int min_inliers = 300;
  int max_planes = 60;  ///< [1, 10000]
  /// MSAC hypotheses per extracted plane, [10, 100000].
  int iterations = 400;
  /// Hypotheses are scored on a random subset of this many points (whole cloud if smaller),
  /// then the best is refitted on the whole remaining cloud. [1000, 1e8]
  int score_sample = 40000;
  /// Inliers closer than this (metres, in the plane) are connected; each connected part
  /// becomes one polygon. [0.005, 10]
  double component_distance = 0.15;
  /// Parts with fewer inliers than this are dropped, points, [1, 1e7].
  int min_component_inliers = 100;
  /// Alpha-shape radius, metres, [0.01, 10] (CGAL alpha = radius^2).
  double alpha_radius = 0.12;
  /// Ring vertices are simplified (Douglas-Peucker) with this tolerance, metres, [0, 1].
  double simplify_tolerance = 0.01;
  /// Region growing (PCL) and sensor topology: max normal angle between neighbours, degrees.
  double smoothness_deg = 5.0;
  int normal_neighbours = 16;  ///< k of the kNN normals (region growing), [3, 100]
  /// Sensor topology: grid half-window for the 2nd/3rd samples, cells, [1, 100].
  int grid_window = 4;
  bool keep_inlier_indices = true;  ///< fill PlanarPolygon::inliers
  /// MSAC: every other hypothesis draws its 2nd and 3rd points in the grid cell of this size
  /// holding its 1st, metres, [0.05, 10] (local samples find small planes in large scenes).
  double msac_local_cell = 0.6;
  static const ParamSchema<PlaneExtractionParams>& schema();
};

struct PlaneExtractionResult {
  std::vector<PlanarPolygon> planes;  ///< one per connected part, by decreasing inlier count
  PlaneDetector detector_used = PlaneDetector::Msac;
  double distance_threshold_used = 0.0;  ///< metres
  /// Per point: index into planes, or -1 (unassigned / dropped part).
  std::vector<int> point_plane;
  std::size_t planes_detected = 0;  ///< planes before splitting into connected parts
  double seconds = 0.0;
};

/// Detects planar polygons in the cloud (world coordinates of the result = cloud.world()).
/// `seed` drives the random samples of MSAC and sensor-topology RANSAC (deterministic for a
/// seed); the registration pipeline passes PipelineParams::seed, so `plumb-cli features` and
/// `plumb-cli register` detect the same planes for the same --seed.
/// Throws InputError for invalid params, or SensorTopology without a grid.
PlaneExtractionResult extractPlanes(const PointCloud& cloud,
                                    const PlaneExtractionParams& params = {},
                                    std::uint64_t seed = kDefaultSeed,
                                    Progress* progress = nullptr);

std::string detectorName(PlaneDetector d);

}  // namespace plumb
