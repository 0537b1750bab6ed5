#pragma once
// 3D line segments from an unorganized point cloud, after Lu, Liu, Li 2019 ("Fast 3D line
// segment detection from unorganized point cloud", docs/ALGORITHMS.md §7): normals, region growing
// into planar patches, patch merging, rasterised contours in each patch plane, splitting into
// straight pieces, least-squares lines lifted back to 3D, short/unstructured ones dropped,
// collinear ones merged. Own implementation (no OpenCV). Differences, for speed and accuracy:
// normals and region growing run on a voxel grid (moments summed over 3x3x3 cells) instead of
// per-point kNN, and a segment lying on the intersection of two patches is snapped onto the
// intersection line of their planes.
#include <cstdint>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"

namespace plumb {

struct SegmentDetectionParams {
  /// Voxel edge for normals and region growing, metres, [0.005, 5].
  double voxel_size = 0.08;
  /// Neighbouring voxels join a patch when their normals differ by less than this, degrees.
  double smoothness_deg = 8.0;
  /// Point-to-plane tolerance of a patch, metres, [0.001, 1].
  double plane_tolerance = 0.02;
  /// Patches whose normals differ by less than this and whose planes are closer than
  /// plane_tolerance are merged, degrees, [0, 30].
  double merge_angle_deg = 3.0;
  int min_patch_points = 200;  ///< [3, 1e7]
  /// Raster pixel in the patch plane, metres (0 = 1.5 x the patch's mean point spacing).
  double pixel_size = 0.0;
  /// Max deviation of contour pixels from a straight piece, pixels, [0.5, 20].
  double split_tolerance_px = 1.5;
  double min_length = 0.3;  ///< metres, [0, 100]
  /// Collinear segments closer than this (metres) and within merge_angle_deg are merged.
  double merge_distance = 0.03;
  /// Snap to the intersection of two patches when both planes are within this distance of
  /// the segment and meet at more than 20 degrees, metres, [0, 0.5] (0 = off).
  double snap_distance = 0.05;
  /// Line-support regions: boundary pixels join when their directions differ by less than
  /// this, degrees, [1, 60] ...
  double line_angle_deg = 20.0;
  /// ... and regions grow from pixels at least this linear (1 - eigenvalue ratio), [0, 1].
  double min_linearity = 0.9;
  /// Snap only onto patches meeting the segment's patch at more than this, degrees, [1, 89].
  double snap_min_angle_deg = 20.0;
  /// Points of a patch lie "next to" a snapped line within max(this, 0.4 voxel_size), metres,
  /// [0.001, 0.5]: the snapped segment is trimmed to where both patches have such points.
  double snap_near_distance = 0.03;
  /// Keep only segments where two patches meet (snapped onto their intersection): real
  /// edges. Contour pieces along occlusion shadows, scan limits and furniture outlines on a
  /// single patch are dropped. false = Lu et al.'s full output.
  bool intersections_only = true;
  static const ParamSchema<SegmentDetectionParams>& schema();
};

struct SegmentDetectionResult {
  std::vector<Segment3D> segments;       ///< world coordinates, by decreasing length
  std::vector<PlanarPolygon> patches;    ///< the planar patches (no rings), for display
  std::vector<int> point_patch;          ///< per point: index into patches or -1
  double seconds = 0.0;
};

SegmentDetectionResult detectSegments(const PointCloud& cloud,
                                      const SegmentDetectionParams& params = {},
                                      Progress* progress = nullptr);

}  // namespace plumb
