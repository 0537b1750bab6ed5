#pragma once
// Façades, interior points and openings (2021 §3.1, 2023 §III-A, docs/ALGORITHMS.md §2).
//  1. Façade selection: polygons whose plane is vertical within `vertical_tolerance_deg` and
//     whose area is at least `min_facade_area`.
//  2. Ray tracing: for each point P with sensor origin O, the segment O->P is intersected with
//     each façade plane; when the hit lies inside the convex hull of the façade's outer ring
//     (doors are notches of the ring, not holes) and |P - hit| >
//     `min_depth` (d_min), P is an interior point and the hit is evidence of an opening.
//     Without per-point sensor origins this step cannot run: it is reported, never guessed.
//  3. Openings: connected components of the evidence (graph edge when two hits are closer
//     than `link_distance`) -> minimum-area rectangle aligned with the vertical -> 4 corners.
//     Each side is then moved to the nearest façade inliers (the wall edge of the opening),
//     at any distance when the evidence stops short (rays through the opening that return
//     nothing, e.g. indoor rays to the sky through a door's upper part), and onto the reveal
//     surface (jamb, sill, lintel) behind it when the scan saw one from the viewer's side.
//  4. Indoor side / no sensor origins: holes of wall polygons become openings too.
// Corners follow plumb::Opening, seen from the side the scanner saw the façade from (the
// sensor side; without sensor origins, the side where most of the cloud lies). That is the
// outside for an outdoor scan and the room side for an indoor scan.
#include <cstdint>
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

enum class OpeningSource {
  Auto,        ///< ray tracing when sensor origins exist, plus polygon holes
  RayTracing,  ///< ray tracing only (InputError when the cloud has no sensor origins)
  Holes        ///< holes of wall polygons only
};

struct OpeningDetectionParams {
  OpeningSource source = OpeningSource::Auto;
  double vertical_tolerance_deg = 3.0;  ///< façade verticality, degrees, [0, 45]
  double min_facade_area = 4.0;         ///< m^2, [0, 1e6]
  double min_depth = 1.0;               ///< d_min: P must be this far behind the façade, m
  double link_distance = 0.15;          ///< evidence connectivity, metres, [0.005, 5]
  int min_evidence = 30;                ///< points per opening component, [1, 1e7]
  double min_width = 0.3;               ///< opening size limits, metres
  double min_height = 0.3;
  double max_width = 10.0;
  double max_height = 6.0;
  /// Sides move to the nearest façade inliers beyond them (the wall edge): within this
  /// distance (and 15 cm) to the middle between evidence and wall, farther (evidence stopped
  /// short) to half a sampling step before the wall. 0 disables snapping. Metres, [0, 2].
  double snap_distance = 0.4;
  static const ParamSchema<OpeningDetectionParams>& schema();
};

struct OpeningDetectionResult {
  std::vector<int> facades;      ///< indices into the input planes
  std::vector<Opening> openings; ///< Opening::facade indexes the input planes
  std::vector<std::uint32_t> interior_points;  ///< cloud indices behind a façade
  std::size_t evidence_count = 0;              ///< ray/façade hits found
  bool ray_tracing_ran = false;
  /// Human-readable notes, e.g. "ray tracing cannot run: the cloud has no sensor origins".
  std::vector<std::string> messages;
};

/// Selects façades among `planes` (PlanarPolygon::inliers are used for snapping when present).
std::vector<int> selectFacades(const std::vector<PlanarPolygon>& planes,
                               double vertical_tolerance_deg, double min_facade_area);

/// Finds interior points and openings. `planes` come from extractPlanes on the same cloud.
OpeningDetectionResult detectOpenings(const PointCloud& cloud,
                                      const std::vector<PlanarPolygon>& planes,
                                      const OpeningDetectionParams& params = {},
                                      Progress* progress = nullptr);

}  // namespace plumb
