// The BIM's own planes, façades and openings (features/bim) against the exact truth of
// generated buildings: every truth face plane, its area, the exterior faces, and every
// window/door once per wall face it pierces.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "features/bim/bim_features.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"

namespace plumb {
namespace {

/// A generated building without glass panes (they are no wall or slab face of the truth).
GeneratedBuilding withoutGlass(const std::string& preset) {
  BuildingSpec spec = buildingPreset(preset);
  spec.glass = false;
  return generateBuilding(spec);
}

bool samePlane(const Eigen::Vector3d& n, double d, const Eigen::Vector3d& m, double e) {
  return n.dot(m) > 1.0 - 1e-9 && std::abs(d - e) < 1e-6;
}

/// Total area of the polygons lying in the plane (n, d).
double areaInPlane(const std::vector<PlanarPolygon>& planes, const Eigen::Vector3d& n, double d) {
  double a = 0.0;
  for (const auto& p : planes) a += samePlane(p.normal, p.offset, n, d) ? p.area : 0.0;
  return a;
}

/// Distinct planes among (normal, offset) pairs.
template <class T, class F>
std::size_t distinctPlanes(const std::vector<T>& items, F plane_of) {
  std::vector<std::pair<Eigen::Vector3d, double>> seen;
  for (const auto& it : items) {
    const auto [n, d] = plane_of(it);
    bool known = false;
    for (const auto& [m, e] : seen) known = known || samePlane(n, d, m, e);
    if (!known) seen.emplace_back(n, d);
  }
  return seen.size();
}

/// Index of the opening whose corners are those of `t` within `tol`, or -1.
int matchingOpening(const std::vector<Opening>& openings, const std::array<Eigen::Vector3d, 4>& t,
                    double tol) {
  for (std::size_t i = 0; i < openings.size(); ++i) {
    bool same = true;
    for (int c = 0; c < 4; ++c) same = same && (openings[i].corners[c] - t[c]).norm() < tol;
    if (same) return int(i);
  }
  return -1;
}

/// For failure messages: the corners 0 and 2 of the opening whose corner 0 is nearest to c.
std::string nearestCorners(const std::vector<Opening>& openings, const Eigen::Vector3d& c) {
  const Opening* best = nullptr;
  for (const auto& o : openings)
    if (!best || (o.corners[0] - c).norm() < (best->corners[0] - c).norm()) best = &o;
  if (!best) return "none";
  std::ostringstream s;
  s << best->corners[0].transpose() << " / " << best->corners[2].transpose();
  return s.str();
}

class BimFeaturesOnPresets : public ::testing::TestWithParam<std::string> {};

TEST_P(BimFeaturesOnPresets, PlanesAreTheTruthFacesWithTheirAreas) {
  const GeneratedBuilding b = withoutGlass(GetParam());
  BimFeatureParams p;
  p.min_polygon_area = 0.0;
  const auto planes = bimPlanes(b.model, p);
  const auto truth_plane = [](const TruthPlane& t) { return std::pair{t.normal, t.offset}; };
  const auto polygon_plane = [](const PlanarPolygon& q) { return std::pair{q.normal, q.offset}; };
  EXPECT_EQ(distinctPlanes(planes, polygon_plane), distinctPlanes(b.truth.planes, truth_plane));
  double total = 0.0;
  for (const auto& t : b.truth.planes) {
    double truth_area = 0.0;  // the faces of every element in that plane
    for (const auto& u : b.truth.planes)
      truth_area += samePlane(u.normal, u.offset, t.normal, t.offset) ? u.area : 0.0;
    // Coordinates are snapped to the micrometre before the union: 1e-5 relative.
    EXPECT_NEAR(areaInPlane(planes, t.normal, t.offset), truth_area, 1e-5 * truth_area + 1e-6)
        << t.element_type << " " << t.face;
    total += t.area;
  }
  double found = 0.0;
  for (const auto& q : planes) found += q.area;
  EXPECT_NEAR(found, total, 1e-5 * total);
  for (const auto& pl : planes) {
    EXPECT_NEAR(pl.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(pl.area, 0.0);
    // Rings: outer counter-clockwise, holes clockwise, in the plane's frame.
    EXPECT_GT(pl.rings.front().size(), 2u);
    EXPECT_NEAR(pl.signedDistance(pl.centroid), 0.0, 1e-9);
  }
  // The default area threshold drops only small pieces (reveals of 0.4 x 0.4 m stay).
  const auto kept = bimPlanes(b.model);
  EXPECT_LE(kept.size(), planes.size());
  for (const auto& pl : kept) EXPECT_GE(pl.area, BimFeatureParams{}.min_polygon_area);
}

TEST_P(BimFeaturesOnPresets, FacadesAreTheExteriorWallFaces) {
  const GeneratedBuilding b = withoutGlass(GetParam());
  const auto r = extractBimFeatures(b.model);
  const auto exterior = [&b](const PlanarPolygon& q) {
    for (const auto* t : b.truth.planesWithFace("exterior"))
      if (samePlane(q.normal, q.offset, t->normal, t->offset)) return true;
    return false;
  };
  ASSERT_FALSE(r.features.facades.empty());
  double facade_area = 0.0, exterior_area = 0.0;
  for (int f : r.features.facades) {
    const auto& pl = r.features.planes[std::size_t(f)];
    EXPECT_TRUE(exterior(pl)) << "a façade that is no exterior face, area " << pl.area;
    facade_area += pl.area;
  }
  // Every exterior face is a façade, with the slab edges flush with it (one plane).
  for (const auto& t : b.truth.planes)
    for (const auto* e : b.truth.planesWithFace("exterior"))
      if (samePlane(t.normal, t.offset, e->normal, e->offset)) {
        exterior_area += t.area;
        break;
      }
  EXPECT_NEAR(facade_area, exterior_area, 1e-6 * exterior_area);
}

TEST_P(BimFeaturesOnPresets, OpeningsAreTheWindowsAndDoorsOnBothWallFaces) {
  const GeneratedBuilding b = generateBuilding(buildingPreset(GetParam()));
  const auto r = extractBimFeatures(b.model);
  EXPECT_FALSE(r.openings_from_holes);
  EXPECT_EQ(r.openings_without_host, 0u);
  ASSERT_EQ(r.features.openings.size(), b.truth.openings.size());
  for (const auto& t : b.truth.openings) {
    const int i = matchingOpening(r.features.openings, t.corners, 1e-3);
    ASSERT_GE(i, 0) << t.element_type << " on the " << t.face << " face of wall " << t.wall
                    << ", corners " << t.corners[0].transpose() << " / " << t.corners[2].transpose()
                    << ", nearest " << nearestCorners(r.features.openings, t.corners[0]);
    const Opening& o = r.features.openings[std::size_t(i)];
    const bool door = t.element_type == "IfcDoor";
    EXPECT_NEAR(o.width(), door ? b.spec.door_width : b.spec.window_width, 1e-3);
    // The opening's plane is the wall face it lies on.
    const auto& face = r.features.planes[std::size_t(o.facade)];
    EXPECT_GT(face.normal.dot(t.face_normal), 0.9999);
    for (const auto& c : o.corners) EXPECT_NEAR(face.signedDistance(c), 0.0, 1e-6);
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, BimFeaturesOnPresets,
                         ::testing::Values("two-rooms", "l-shaped", "non-manhattan"));

TEST(BimFeatures, WithoutElementTypesTheWindowsComeFromWallHoles) {
  GeneratedBuilding b = generateBuilding(buildingPreset("two-rooms"));
  for (auto& e : b.model.elements) e.type.clear();  // as an OBJ/PLY mesh
  const auto r = extractBimFeatures(b.model);
  EXPECT_TRUE(r.openings_from_holes);
  // Every window (both faces of its wall) is a hole; doors reaching the floor are notches of
  // their wall faces, except where the slab edge closes them below (the entrance door's
  // exterior face): every hole found is a truth opening.
  std::size_t windows = 0;
  for (const auto& t : b.truth.openings)
    if (t.element_type == "IfcWindow") {
      ++windows;
      EXPECT_GE(matchingOpening(r.features.openings, t.corners, 1e-3), 0);
    }
  EXPECT_GE(r.features.openings.size(), windows);
  for (const auto& o : r.features.openings) {
    bool known = false;
    for (const auto& t : b.truth.openings)
      known = known || matchingOpening({o}, t.corners, 1e-3) == 0;
    EXPECT_TRUE(known) << o.corners[0].transpose() << " / " << o.corners[2].transpose();
  }
}

TEST(BimFeatures, RejectsParametersOutOfRange) {
  const GeneratedBuilding b = generateBuilding(buildingPreset("two-rooms"));
  BimFeatureParams p;
  p.angle_tolerance_deg = 45;
  EXPECT_ANY_THROW(bimPlanes(b.model, p));
}

}  // namespace
}  // namespace plumb
