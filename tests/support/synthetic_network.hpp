#pragma once
// A synthetic station network with known poses: stations on a ring of corridors and rooms,
// links between ring neighbours and chords, each measured with deterministic noise, and
// optionally one planted wrong link (as between two identical rooms).
#include <cmath>
#include <random>
#include <vector>

#include "registration/network/robust_adjustment.hpp"

namespace plumb::test {

struct SyntheticNetwork {
  std::vector<RigidTransform> truth;  ///< station -> reference frame
  std::vector<AdjustmentLink> links;
  std::size_t wrong_link = static_cast<std::size_t>(-1);
};

inline RigidTransform noisy(const RigidTransform& t, double sigma_m, double sigma_deg, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Vector3d axis(n(rng), n(rng), n(rng));
  const double angle = sigma_deg * M_PI / 180.0 * n(rng);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return RigidTransform(r, Eigen::Vector3d(n(rng), n(rng), n(rng)) * sigma_m) * t;
}

/// `count` stations on a ring of radius `radius`, random headings; links i -> i+1 (ring) and
/// i -> i+`chord` every second station; noise sigma_m / sigma_deg on each link.
inline SyntheticNetwork ringNetwork(std::size_t count, double radius, std::size_t chord, double sigma_m,
                                    double sigma_deg, std::uint64_t seed, bool plant_wrong_link) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI);
  SyntheticNetwork net;
  for (std::size_t i = 0; i < count; ++i) {
    const double a = 2 * M_PI * double(i) / double(count);
    net.truth.push_back(RigidTransform::fromYaw(yaw(rng), {radius * std::cos(a), radius * std::sin(a), 0.1 * double(i % 3)}));
  }
  auto add = [&](std::size_t a, std::size_t b) {
    AdjustmentLink l;
    l.a = a, l.b = b;
    l.transform = noisy(net.truth[a].inverse() * net.truth[b], sigma_m, sigma_deg, rng);
    l.sigma_translation = sigma_m, l.sigma_rotation_deg = sigma_deg;
    net.links.push_back(l);
  };
  for (std::size_t i = 0; i < count; ++i) add(i, (i + 1) % count);
  for (std::size_t i = 0; i < count; i += 2) add(i, (i + chord) % count);
  if (plant_wrong_link) {  // b placed one 4 m room further and turned by 180 deg: confident
    AdjustmentLink l;
    l.a = 1, l.b = count / 2 + 1;
    l.transform = RigidTransform::fromYaw(M_PI, {4.0, 0.0, 0.0}) * net.truth[l.a].inverse() * net.truth[l.b];
    l.sigma_translation = sigma_m, l.sigma_rotation_deg = sigma_deg;
    net.wrong_link = net.links.size();
    net.links.push_back(l);
  }
  return net;
}

/// Wrong links among `members` that agree with each other: each pair registered as if all
/// members stood at the same place (identical rooms stacked onto one another).
inline void addStackedClique(SyntheticNetwork& net, const std::vector<std::size_t>& members, double sigma_m,
                             double sigma_deg) {
  for (std::size_t i = 0; i < members.size(); ++i)
    for (std::size_t j = i + 1; j < members.size(); ++j) {
      AdjustmentLink l;
      l.a = members[i], l.b = members[j];
      l.sigma_translation = sigma_m, l.sigma_rotation_deg = sigma_deg;  // transform: identity
      net.links.push_back(l);
    }
}

/// The adjustment's parameters of these tests: drop thresholds 5 cm and 0.2 deg.
inline PoseGraphParams graphParams() {
  PoseGraphParams p;
  p.drop_translation = 0.05;
  p.drop_rotation = 0.2;
  return p;
}

/// Largest position error of the placed stations (m); unplaced stations count as infinite.
inline double maxPositionError(const std::vector<std::optional<RigidTransform>>& poses,
                               const std::vector<RigidTransform>& truth) {
  double worst = 0;
  for (std::size_t i = 0; i < truth.size(); ++i)
    worst = std::max(worst, poses[i] ? RigidTransform::translationError(*poses[i], truth[i]) : INFINITY);
  return worst;
}

}  // namespace plumb::test
