// Choosing the nodes a view draws, on hand-made hierarchies: frustum culling, larger on
// screen first, parents before children, the point budget, and no refinement once the
// spacing is below a pixel.
#include <gtest/gtest.h>

#include <algorithm>

#include "io/lod/lod_select.hpp"

namespace plumb {
namespace {

/// A 64 m root cube at national-grid coordinates, its 8 children and the 8 children of child 0,
/// each node holding `points` points.
LodHierarchy twoLevels(std::uint64_t points = 1000) {
  LodHierarchy h;
  h.grid.origin = Eigen::Vector3d(651000, 6860000, 100);
  h.grid.quantum = 1.0 / 1024;  // root side 2^(levels + cell_bits) quanta = 64 m
  h.grid.cell_bits = 7;
  h.grid.levels = 9;
  const auto add = [&](const LodKey& key, std::uint32_t parent) {
    LodNode n;
    n.id = static_cast<std::uint32_t>(h.nodes.size());
    n.parent = parent;
    n.key = key;
    n.bounds = h.grid.bounds(key);
    n.spacing = h.grid.spacing(key.depth);
    n.point_count = points;
    h.nodes.push_back(n);
    if (parent != kNoLodNode) {
      const int o = static_cast<int>((key.xyz[0] & 1) | ((key.xyz[1] & 1) << 1) | ((key.xyz[2] & 1) << 2));
      h.nodes[parent].children[o] = n.id;
    }
    return n.id;
  };
  const std::uint32_t root = add(LodKey{}, kNoLodNode);
  std::uint32_t first = kNoLodNode;
  for (int o = 0; o < 8; ++o) {
    const std::uint32_t c = add(LodKey{}.child(o), root);
    if (o == 0) first = c;
  }
  for (int o = 0; o < 8; ++o) add(h.nodes[first].key.child(o), first);
  h.points = points * h.nodes.size();
  return h;
}

/// A square 1000-pixel perspective view.
LodView camera(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double fov_deg = 60, double far = 1e4) {
  return lodPerspectiveView(eye, target, fov_deg * M_PI / 180, 1.0, 1000, 0.1, far);
}

void expectParentsFirst(const LodHierarchy& h, const LodSelection& s) {
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const std::uint32_t parent = h.nodes[s.nodes[i]].parent;
    if (parent == kNoLodNode) continue;
    const auto at = std::find(s.nodes.begin(), s.nodes.begin() + i, parent);
    EXPECT_NE(at, s.nodes.begin() + i) << "node " << s.nodes[i] << " before its parent";
  }
}

TEST(LodSelect, WholeSceneInViewTakesEveryNodeParentsFirst) {
  const LodHierarchy h = twoLevels();
  const Eigen::Vector3d centre = h.nodes[0].bounds.center();
  const LodSelection s = selectLodNodes(h, camera(centre + Eigen::Vector3d(-100, -120, 80), centre));
  EXPECT_EQ(s.nodes.size(), h.nodes.size());
  EXPECT_EQ(s.nodes.front(), 0u);
  EXPECT_EQ(s.points, h.points);
  EXPECT_FALSE(s.budget_reached);
  expectParentsFirst(h, s);
}

TEST(LodSelect, BudgetStopsBeforeExceedingIt) {
  const LodHierarchy h = twoLevels();
  const Eigen::Vector3d centre = h.nodes[0].bounds.center();
  LodSelectParams p;
  p.point_budget = 4500;
  const LodSelection s = selectLodNodes(h, camera(centre + Eigen::Vector3d(-100, -120, 80), centre), p);
  EXPECT_EQ(s.nodes.size(), 4u);
  EXPECT_EQ(s.points, 4000u);
  EXPECT_TRUE(s.budget_reached);
  expectParentsFirst(h, s);
}

TEST(LodSelect, NodesBehindTheCameraOrBesideTheFrustumAreCulled) {
  const LodHierarchy h = twoLevels();
  // Standing in the +x half (x = 56 m of 64), looking further along +x: the -x half is behind.
  const Eigen::Vector3d eye = h.grid.origin + Eigen::Vector3d(56, 32, 32);
  const LodSelection s = selectLodNodes(h, camera(eye, eye + Eigen::Vector3d(10, 0, 0), 40));
  EXPECT_GT(s.culled, 0u);
  for (const std::uint32_t id : s.nodes) {
    const LodNode& n = h.nodes[id];
    if (n.depth() > 0) {
      EXPECT_GE(n.bounds.max.x(), eye.x()) << "node " << id << " lies behind the eye";
    }
  }
  // Child 0 (-x, -y, -z) and its children are never drawn.
  EXPECT_EQ(std::count(s.nodes.begin(), s.nodes.end(), 1u), 0);
  EXPECT_EQ(std::count_if(s.nodes.begin(), s.nodes.end(), [](std::uint32_t id) { return id >= 9; }), 0);
  EXPECT_NE(std::find(s.nodes.begin(), s.nodes.end(), 2u), s.nodes.end());  // +x child in view
}

TEST(LodSelect, NearerNodesComeBeforeFartherOnes) {
  const LodHierarchy h = twoLevels();
  // Near the -x, -y, -z corner (child 0) looking at the whole cube.
  const Eigen::Vector3d eye = h.grid.origin + Eigen::Vector3d(-10, -12, -8);
  const LodSelection s = selectLodNodes(h, camera(eye, h.nodes[0].bounds.center(), 90));
  ASSERT_GE(s.nodes.size(), 3u);
  EXPECT_EQ(s.nodes[0], 0u);
  EXPECT_EQ(s.nodes[1], 1u);  // child 0 (nearest) first among the children
  const auto pos = [&](std::uint32_t id) { return std::find(s.nodes.begin(), s.nodes.end(), id) - s.nodes.begin(); };
  EXPECT_LT(pos(9), pos(8));  // a grandchild near the eye before the farthest child (+x +y +z)
}

TEST(LodSelect, NoRefinementOnceTheSpacingIsBelowAPixel) {
  const LodHierarchy h = twoLevels();
  // 64 m root, spacing 0.5 m: one pixel at 30 degrees and 1000 px beyond ~1.87 km.
  const Eigen::Vector3d centre = h.nodes[0].bounds.center();
  const LodSelection far = selectLodNodes(h, camera(centre + Eigen::Vector3d(0, -3000, 0), centre, 30));
  EXPECT_EQ(far.nodes, std::vector<std::uint32_t>{0});
  LodView ortho = camera(centre + Eigen::Vector3d(0, -100, 0), centre, 30);
  ortho.metres_per_pixel = 0.3;  // children's spacing 0.25 m: below a pixel
  const LodSelection o = selectLodNodes(h, ortho);
  EXPECT_EQ(o.nodes.size(), 9u);  // root (0.5 m > 0.3) and its children, not the grandchildren
  EXPECT_TRUE(selectLodNodes(LodHierarchy{}, ortho).nodes.empty());
}

TEST(LodSelect, FrustumTestOfBoxes) {
  const LodView v = camera(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 0, 0), 60, 100);
  Bounds ahead, behind, beyond;
  ahead.extend(Eigen::Vector3d(5, -1, -1)), ahead.extend(Eigen::Vector3d(6, 1, 1));
  behind.extend(Eigen::Vector3d(-6, -1, -1)), behind.extend(Eigen::Vector3d(-5, 1, 1));
  beyond.extend(Eigen::Vector3d(200, -1, -1)), beyond.extend(Eigen::Vector3d(201, 1, 1));
  EXPECT_FALSE(lodOutsideFrustum(v, ahead));
  EXPECT_TRUE(lodOutsideFrustum(v, behind));
  EXPECT_TRUE(lodOutsideFrustum(v, beyond));  // past the far plane
  EXPECT_NEAR(lodPixels(v, 1.0, 10.0), 1.0 / (10 * std::tan(M_PI / 6)) * 500, 1e-9);
}

}  // namespace
}  // namespace plumb
