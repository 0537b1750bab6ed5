#pragma once
// Internal to the segments module: a planar patch rasterised in its plane, and the boundary
// pixels of that raster with their local direction (Lu, Liu, Li 2019 step 4: "rasterisation of
// each patch in its plane, contours").
#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

#include "features/segments/voxel_patches.hpp"
#include "model/feature_set.hpp"

namespace plumb::segments_detail {

/// A patch's points in its (u, v) frame on a pixel grid with a one-pixel empty margin.
struct PatchRaster {
  std::vector<Eigen::Vector2d> uv;  ///< the points, metres (local coordinates of the cloud)
  Eigen::Vector2d lo = Eigen::Vector2d::Zero();  ///< lower corner of the points' box
  double px = 0.0;                  ///< pixel size, metres
  int W = 0, H = 0;                 ///< pixels across and up, margins included
  std::vector<char> occupied;       ///< a point falls in the pixel
  std::vector<char> mask;           ///< occupied after a 3x3 closing

  std::size_t at(int i, int j) const { return std::size_t(j) * W + i; }
  /// Pixel (i, j) of a point in metres.
  std::pair<int, int> pixel(const Eigen::Vector2d& p) const {
    return {int((p.x() - lo.x()) / px) + 1, int((p.y() - lo.y()) / px) + 1};
  }
};

/// `requested` unless it is 0 or less; otherwise 1.5 x sqrt(area / n), the area counted on a 10 cm
/// grid, clamped to [5 mm, 20 cm].
double patchPixelSize(const std::vector<Eigen::Vector2d>& uv, const Eigen::Vector2d& lo,
                      const Eigen::Vector2d& hi, double requested);

/// The raster of a patch; false (and nothing to draw) when it would exceed 6e7 pixels.
bool rasterisePatch(const PointCloud& cloud, const Patch& patch, const PlanarPolygon& frame,
                    double pixel_size, PatchRaster& out);

/// Closing (3x3 dilation then erosion) of `occupied` on a W x H grid; occupied pixels stay
/// set. Fills pixel-size gaps of the sampling. The outer ring of pixels stays empty.
std::vector<char> closeMask(const std::vector<char>& occupied, int W, int H);

/// Boundary pixels (set, with an empty 4-neighbour) and the direction of the boundary at each:
/// the PCA of the boundary pixels in its 7x7 window.
struct BoundaryPixels {
  std::vector<int> index;                ///< per raster pixel: its boundary number, or -1
  std::vector<Eigen::Vector2i> pixels;   ///< (i, j) of each boundary pixel
  std::vector<Eigen::Vector2d> dir;      ///< unit direction (zero: fewer than 3 in the window)
  std::vector<double> linearity;         ///< 1 - lambda_min / lambda_max (0: no direction)
};
BoundaryPixels boundaryPixels(const PatchRaster& raster);

}  // namespace plumb::segments_detail
