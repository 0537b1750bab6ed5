// The contour steps of the segment detector one at a time (docs/ALGORITHMS.md §7): pixel size,
// closing, boundary pixels and their directions, line-support regions, line fits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "features/planes/plane_fit.hpp"
#include "features/segments/patch_lines.hpp"
#include "features/segments/patch_raster.hpp"

namespace plumb::segments_detail {
namespace {

/// A W x H raster whose mask is the rectangle [i0, i1] x [j0, j1].
PatchRaster rectangleRaster(int W, int H, int i0, int i1, int j0, int j1) {
  PatchRaster r;
  r.W = W;
  r.H = H;
  r.px = 1.0;
  r.mask.assign(std::size_t(W) * H, 0);
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) r.mask[r.at(i, j)] = 1;
  r.occupied = r.mask;
  return r;
}

/// The square [0, 1) x [0, 1) of the plane z = 0 sampled every `step`, as one patch.
struct SquarePatch {
  PointCloud cloud;
  Patch patch;
  PlanarPolygon frame;
};
SquarePatch squarePatch(double step) {
  SquarePatch s;
  for (double x = step / 2; x < 1.0; x += step)
    for (double y = step / 2; y < 1.0; y += step) {
      s.patch.points.push_back(static_cast<std::uint32_t>(s.cloud.positions.size()));
      s.cloud.positions.emplace_back(float(x), float(y), 0.f);
    }
  s.frame.normal = Eigen::Vector3d::UnitZ();
  s.frame.centroid = Eigen::Vector3d(0.5, 0.5, 0.0);
  setPlaneFrame(s.frame);
  return s;
}

TEST(PatchRaster, PixelSizeIsTheRequestedOneOrOneAndAHalfSpacings) {
  std::vector<Eigen::Vector2d> uv;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) uv.emplace_back(0.01 * i, 0.01 * j);
  const Eigen::Vector2d lo(0, 0), hi(0.99, 0.99);
  EXPECT_EQ(patchPixelSize(uv, lo, hi, 0.04), 0.04);
  // 1 m^2 covered (100 cells of 10 cm) by 10,000 points: spacing 1 cm, pixel 1.5 cm.
  EXPECT_NEAR(patchPixelSize(uv, lo, hi, 0.0), 0.015, 1e-12);
  // One point per 10 cm cell: 1.5 x 10 cm.
  EXPECT_NEAR(patchPixelSize({{0, 0}, {0.99, 0.99}}, lo, hi, 0.0), 0.15, 1e-12);
  // 10,000 points in one cell (1 mm spacing) are clamped to 5 mm.
  std::vector<Eigen::Vector2d> dense;
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) dense.emplace_back(0.0009 * i, 0.0009 * j);
  EXPECT_EQ(patchPixelSize(dense, lo, Eigen::Vector2d(0.0891, 0.0891), 0.0), 0.005);
}

TEST(PatchRaster, ClosingFillsOnePixelGapsAndKeepsLonePixels) {
  PatchRaster r = rectangleRaster(12, 12, 2, 9, 2, 9);
  std::vector<char> occ = r.mask;
  occ[r.at(5, 5)] = 0;  // a hole of one pixel inside
  occ[r.at(10, 10)] = 0;
  const std::vector<char> mask = closeMask(occ, r.W, r.H);
  EXPECT_EQ(mask[r.at(5, 5)], 1);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(mask[r.at(k, 0)], 0);
    EXPECT_EQ(mask[r.at(0, k)], 0);
  }
  std::vector<char> lone(std::size_t(12) * 12, 0);
  lone[r.at(6, 6)] = 1;
  const std::vector<char> kept = closeMask(lone, 12, 12);
  EXPECT_EQ(std::count(kept.begin(), kept.end(), 1), 1);
  EXPECT_EQ(kept[r.at(6, 6)], 1);
}

TEST(PatchRaster, BoundaryPixelsAreTheRimAndPointAlongIt) {
  const PatchRaster r = rectangleRaster(30, 20, 3, 26, 3, 16);
  const BoundaryPixels b = boundaryPixels(r);
  // The rim of a 24 x 14 rectangle.
  EXPECT_EQ(b.pixels.size(), std::size_t(2 * 24 + 2 * 14 - 4));
  for (const auto& p : b.pixels)
    EXPECT_TRUE(p.x() == 3 || p.x() == 26 || p.y() == 3 || p.y() == 16) << p.transpose();
  const int bottom = b.index[r.at(14, 3)], side = b.index[r.at(3, 10)];
  ASSERT_GE(bottom, 0);
  ASSERT_GE(side, 0);
  EXPECT_NEAR(std::abs(b.dir[bottom].x()), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(b.dir[side].y()), 1.0, 1e-9);
  EXPECT_GT(b.linearity[bottom], 0.99);
  EXPECT_LT(b.linearity[b.index[r.at(3, 3)]], 0.9);  // the corner
  EXPECT_EQ(b.index[r.at(10, 10)], -1);              // inside
}

TEST(PatchLines, ARegionGrownFromAnEdgeStaysOnThatEdge) {
  const PatchRaster r = rectangleRaster(30, 20, 3, 26, 3, 16);
  const BoundaryPixels b = boundaryPixels(r);
  std::vector<char> used(b.pixels.size(), 0);
  const LineRegion region = growLineRegion(r, b, b.index[r.at(14, 3)], std::cos(20.0 * M_PI / 180.0), 1.5, used);
  EXPECT_GE(region.pixels.size(), 18u);  // most of the 24-pixel edge (the corners turn away)
  for (int p : region.pixels) {
    EXPECT_EQ(b.pixels[p].y(), 3);
    EXPECT_TRUE(used[p]);
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), std::ptrdiff_t(region.pixels.size()));
}

TEST(PatchLines, ASquarePatchGivesItsFourEdges) {
  const SquarePatch s = squarePatch(0.01);
  SegmentDetectionParams p;
  p.pixel_size = 0.02;
  const auto lines = patchLines(s.cloud, s.patch, s.frame, p);
  ASSERT_EQ(lines.size(), 4u);
  int on_x = 0, on_y = 0;
  for (const auto& l : lines) {
    const Eigen::Vector3d a = s.frame.to3d(l.a), b = s.frame.to3d(l.b);
    EXPECT_GT((a - b).norm(), 0.8);
    EXPECT_GT(l.support, 50.0);
    // On an edge of the square: both ends share x = 0 or 1, or y = 0 or 1, within 1 cm (the
    // outermost points are 5 mm inside).
    const bool vertical = std::abs(a.x() - b.x()) < 0.01;
    const double c = vertical ? a.x() : a.y();
    EXPECT_LT(std::min(std::abs(c), std::abs(c - 1.0)), 0.01) << a.transpose() << " / " << b.transpose();
    (vertical ? on_x : on_y) += 1;
  }
  EXPECT_EQ(on_x, 2);
  EXPECT_EQ(on_y, 2);
}

}  // namespace
}  // namespace plumb::segments_detail
