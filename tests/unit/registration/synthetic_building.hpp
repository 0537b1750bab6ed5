#pragma once
// Synthetic ground-truth features of an asymmetric two-storey building (no 180° symmetry) for
// registration unit tests, plus the perturbations of the acceptance protocol: random rigid
// transform (yaw in [-180, 180] deg, shift up to 20 m), noise, dropped features, outliers.
#include <Eigen/Geometry>

#include <random>
#include <vector>

#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"

namespace plumb::test {

/// Axis-aligned rectangle polygon in the plane through `origin` spanned by u, v (sizes w, h),
/// with optional rectangular holes given as (s0, t0, s1, t1) in (u, v) coordinates.
PlanarPolygon makeRectPolygon(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                              const Eigen::Vector3d& v, double w, double h,
                              const std::vector<Eigen::Vector4d>& holes = {},
                              std::size_t inliers = 0);

struct Room {
  Eigen::Vector3d min, max;
};

/// Features of a set of rooms: 6 polygons per room (walls with window holes on x-facing
/// walls), the 12 box edges and window edges as segments, windows as openings.
FeatureSet roomFeatures(const std::vector<Room>& rooms, bool windows = true);

/// An L-shaped, asymmetric floor plan of several rooms (two storeys).
std::vector<Room> asymmetricRooms();

/// Random pose of the acceptance protocol: yaw uniform in [-180, 180] degrees, horizontal
/// shift up to `max_shift` metres, vertical shift up to 2 m.
RigidTransform randomPose(std::mt19937_64& rng, double max_shift = 20.0);

struct Perturbation {
  double position_noise = 0.005;  ///< m, Gaussian on segment endpoints / polygon offsets
  double angle_noise_deg = 0.05;
  double drop_fraction = 0.2;     ///< features removed
  int outliers = 10;              ///< random features added
};
/// Applies noise, drops and outliers (segments, planes) deterministically from rng.
FeatureSet perturb(const FeatureSet& in, const Perturbation& p, std::mt19937_64& rng);

}  // namespace plumb::test
