// The steps of growPatches (segment detector, docs/ALGORITHMS.md §7) one at a time: voxel grid,
// block normals, region growing, merging of coplanar regions, point assignment, adjacency.
#include <gtest/gtest.h>

#include <cmath>

#include "features/segments/voxel_grid.hpp"
#include "features/segments/voxel_patches.hpp"
#include "features/segments/voxel_regions.hpp"

namespace plumb::segments_detail {
namespace {

/// Points every `step` on the square [0, size)^2 of the plane z = 0 (floor) or, with `wall`,
/// of x = 0 (the square spans y and z).
void addSquare(PointCloud& cloud, double size, double step, bool wall) {
  for (double a = step / 2; a < size; a += step)
    for (double b = step / 2; b < size; b += step)
      cloud.positions.push_back(wall ? Eigen::Vector3f(0.f, float(a), float(b)) : Eigen::Vector3f(float(a), float(b), 0.f));
}

/// A floor and a wall meeting along the y axis: an "L" in the xz section.
PointCloud floorAndWall() {
  PointCloud cloud;
  addSquare(cloud, 1.0, 0.02, false);
  addSquare(cloud, 1.0, 0.02, true);
  return cloud;
}

TEST(VoxelGrid, KeysPackAndUnpackNegativeCoordinates) {
  std::int64_t x, y, z;
  unpackVoxelKey(packVoxelKey(-5, 0, 123456), x, y, z);
  EXPECT_EQ(x, -5);
  EXPECT_EQ(y, 0);
  EXPECT_EQ(z, 123456);
  EXPECT_NE(packVoxelKey(1, 0, 0), packVoxelKey(0, 1, 0));
}

TEST(VoxelGrid, CellsHoldTheirPointsMomentsAndSkipNonFinitePoints) {
  PointCloud cloud;
  cloud.positions = {{0.05f, 0.05f, 0.05f}, {0.15f, 0.05f, 0.05f}, {0.07f, 0.03f, 0.01f},
                     {std::nanf(""), 0.f, 0.f}};
  const VoxelGrid grid = buildVoxelGrid(cloud, 0.1);
  ASSERT_EQ(grid.keyed.size(), 3u);  // the NaN point is left out
  ASSERT_EQ(grid.cells.size(), 2u);
  const VoxelCell& first = grid.cells[grid.index.at(packVoxelKey(0, 0, 0))];
  EXPECT_EQ(first.count, 2.0);
  EXPECT_NEAR(first.centroid.x(), 0.06, 1e-6);
  EXPECT_NEAR(first.centroid.z(), 0.03, 1e-6);
  // Too few points (3 < 6) in every block: no normal, curvature stays 1 (not planar).
  EXPECT_EQ(first.normal.norm(), 0.0);
  EXPECT_EQ(first.curvature, 1.0);
  std::vector<int> nb;
  grid.neighbours(first, nb);
  ASSERT_EQ(nb.size(), 1u);
  EXPECT_EQ(grid.cells[nb[0]].key, packVoxelKey(1, 0, 0));
}

TEST(VoxelGrid, BlockNormalsOfAPlaneAreItsNormalWithZeroCurvature) {
  PointCloud cloud;
  addSquare(cloud, 1.0, 0.02, false);
  const VoxelGrid grid = buildVoxelGrid(cloud, 0.1);
  for (const auto& c : grid.cells) {
    EXPECT_NEAR(std::abs(c.normal.z()), 1.0, 1e-9);
    EXPECT_LT(c.curvature, 1e-9);
  }
}

TEST(VoxelRegions, AFloorAndAWallGrowIntoTwoRegionsThatDoNotMerge) {
  const PointCloud cloud = floorAndWall();
  const VoxelGrid grid = buildVoxelGrid(cloud, 0.1);
  const RegionGrowth g = growRegions(grid, 10.0, 0.02);
  ASSERT_EQ(g.regions.size(), 2u);
  std::size_t labelled = 0;
  for (int r = 0; r < 2; ++r) {
    for (int c : g.regions[r].cells) EXPECT_EQ(g.cell_region[c], r);
    labelled += g.regions[r].cells.size();
    EXPECT_TRUE(g.regions[r].fit.valid);
  }
  // The voxels on the corner see both planes (curvature above 0.02): in no region.
  EXPECT_LT(labelled, grid.cells.size());
  const double nz0 = std::abs(g.regions[0].fit.normal.z()), nz1 = std::abs(g.regions[1].fit.normal.z());
  EXPECT_NEAR(std::max(nz0, nz1), 1.0, 1e-9);
  EXPECT_NEAR(std::min(nz0, nz1), 0.0, 1e-9);
  const MergedRegions m = mergeCoplanarRegions(grid, g, 5.0, 0.02);
  EXPECT_EQ(m.fits.size(), 2u);
}

TEST(VoxelRegions, TwoTouchingRegionsOfOnePlaneMergeIntoOnePatch) {
  PointCloud cloud;
  addSquare(cloud, 1.0, 0.02, false);
  const VoxelGrid grid = buildVoxelGrid(cloud, 0.1);
  RegionGrowth g = growRegions(grid, 10.0, 0.02);
  ASSERT_EQ(g.regions.size(), 1u);
  // Cut the region in two halves by x, each with its own moments and fit.
  RegionGrowth halves;
  halves.cell_region.assign(grid.cells.size(), -1);
  halves.regions.resize(2);
  for (int c : g.regions[0].cells) {
    const int h = grid.cells[c].centroid.x() < 0.5 ? 0 : 1;
    auto& r = halves.regions[h];
    r.cells.push_back(c);
    r.count += grid.cells[c].count; r.sum += grid.cells[c].sum; r.outer += grid.cells[c].outer;
    halves.cell_region[c] = h;
  }
  for (auto& r : halves.regions) r.fit = fitPlaneFromMoments(r.count, r.sum, r.outer);
  const MergedRegions m = mergeCoplanarRegions(grid, halves, 5.0, 0.02);
  ASSERT_EQ(m.fits.size(), 1u);
  EXPECT_NEAR(m.fits[0].centroid.x(), 0.5, 1e-6);
  for (int c : g.regions[0].cells) EXPECT_EQ(m.cell_patch[c], 0);
  // Lifted 10 cm, the second half is parallel but not coplanar: two patches.
  halves.regions[1].fit.offset += 0.1;
  halves.regions[1].fit.centroid.z() += 0.1;
  EXPECT_EQ(mergeCoplanarRegions(grid, halves, 5.0, 0.02).fits.size(), 2u);
}

TEST(VoxelPatches, PointsJoinTheNearestPatchWithinToleranceAndEdgesMakeNeighbours) {
  PointCloud cloud = floorAndWall();
  cloud.positions.push_back({0.5f, 0.5f, 0.05f});  // 5 cm above the floor: beyond tolerance
  const VoxelGrid grid = buildVoxelGrid(cloud, 0.1);
  const MergedRegions m = mergeCoplanarRegions(grid, growRegions(grid, 10.0, 0.02), 5.0, 0.02);
  ASSERT_EQ(m.fits.size(), 2u);
  const auto point_patch = assignPointsToPatches(cloud, grid, m.cell_patch, m.fits, 0.02);
  std::size_t assigned = 0;
  for (std::size_t k = 0; k < grid.keyed.size(); ++k) {
    const auto i = grid.keyed[k].second;
    if (i + 1 == cloud.size()) {
      EXPECT_EQ(point_patch[k], -1) << "the lifted point";
      continue;
    }
    ASSERT_GE(point_patch[k], 0) << "point " << i;  // corner points too: edge cells look 2 voxels out
    const auto& f = m.fits[point_patch[k]];
    EXPECT_LT(std::abs(f.normal.dot(cloud.positions[i].cast<double>()) - f.offset), 0.02);
    ++assigned;
  }
  EXPECT_EQ(assigned, cloud.size() - 1);
  const auto adj = patchAdjacency(grid, m.cell_patch, 2);
  EXPECT_EQ(adj[0], std::set<int>{1});
  EXPECT_EQ(adj[1], std::set<int>{0});
  const auto patches = growPatches(cloud, SegmentDetectionParams{.voxel_size = 0.1, .smoothness_deg = 10,
                                                                  .plane_tolerance = 0.02},
                                   nullptr);
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_EQ(patches[0].points.size() + patches[1].points.size(), cloud.size() - 1);
  EXPECT_EQ(patches[0].neighbours, std::vector<int>{1});
}

}  // namespace
}  // namespace plumb::segments_detail
