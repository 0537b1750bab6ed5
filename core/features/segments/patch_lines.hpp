#pragma once
// Internal to the segments module: straight lines along a patch's contour (Lu, Liu, Li 2019
// steps 5-6: "straight pieces, line fits"), in the patch's (u, v) frame.
#include <Eigen/Core>

#include <optional>
#include <vector>

#include "features/segments/patch_raster.hpp"
#include "features/segments/segment_detection.hpp"

namespace plumb::segments_detail {

struct Line2 {
  Eigen::Vector2d a, b;
  double support = 0;  ///< points behind the line's offset
};

/// Contour lines of one patch, in its (u, v) frame (local coordinates of the cloud): boundary
/// pixels grouped greedily into line-support regions (most linear seeds first), each fitted.
std::vector<Line2> patchLines(const PointCloud& cloud, const Patch& patch, const PlanarPolygon& frame,
                              const SegmentDetectionParams& params);

/// A line-support region: boundary pixels and the moments of their (i, j).
struct LineRegion {
  std::vector<int> pixels;  ///< boundary numbers, the seed first
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
};

/// Grows from `seed` over 8-connected unused boundary pixels whose direction is within
/// acos(cos_dir) of the region's line and that lie within tol_px of it; the line is refitted
/// each time the region doubles (4, 8, ... pixels). Marks the pixels it takes in `used`.
LineRegion growLineRegion(const PatchRaster& raster, const BoundaryPixels& boundary, int seed, double cos_dir,
                          double tol_px, std::vector<char>& used);

/// The region's least-squares line, turned towards the empty side, spanning the region's
/// pixels, and moved to the 90th percentile of the offsets of the points in those pixels (the
/// outermost points, not pixel centres). None when fewer than 3 points are in its pixels.
std::optional<Line2> fitRegionLine(const PatchRaster& raster, const BoundaryPixels& boundary,
                                   const LineRegion& region);

}  // namespace plumb::segments_detail
