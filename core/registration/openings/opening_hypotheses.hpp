#pragma once
// Internal to the openings registration: the steps that build its hypotheses (2023 §III-B,
// see opening_registration.hpp), apart so that each can be tested alone.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"
#include "registration/openings/opening_match.hpp"

namespace plumb::openings_detail {

/// A base hypothesis: source opening `s` onto target opening `t` (indices into the oriented
/// openings), `pairing` 0: source corner 0 onto target corner 1, 1: corner 1 onto corner 0.
struct Base {
  int s, t, pairing;
};

/// Every (source, target, pairing) in that order; beyond `max_hypotheses`, shuffled with
/// `seed` and cut to `max_hypotheses`.
std::vector<Base> baseHypotheses(std::size_t n_source, std::size_t n_target, int max_hypotheses,
                                 std::uint64_t seed);

/// Yaw-only rotation taking horizontal direction `from` onto `to` (scans are Z-up).
Eigen::Matrix3d yawBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

/// The paper's zero-thickness placement of a base: the source opening's wall onto the target
/// opening's façade (normals opposite, rotation about the vertical), the paired bottom
/// corners coincide.
RigidTransform zeroThicknessPlacement(const OrientedOpening& s, const Opening& os,
                                      const OrientedOpening& t, const Opening& ot, int pairing);

/// What limits the wall thickness candidates.
struct ThicknessSearch {
  double d;              ///< robust distance of eq. 7, metres
  double cos_tol;        ///< facing openings: normals opposite within this cosine
  double sin_tol;        ///< perpendicular openings: |n_k · n| below 2 sin_tol + 0.02
  double max_thickness;  ///< metres
};

/// Wall thickness candidates for the placement `t0` onto the façade with outward normal `n`:
/// each source opening on a wall perpendicular to the façade, paired with a facing target
/// opening at the same height and of the same width, gives the shift along n, kept when in
/// [-d, max_thickness]. Sorted, candidates closer than d/2 to the previous kept one dropped.
std::vector<double> thicknessCandidates(const std::vector<OrientedOpening>& src,
                                        const std::vector<OrientedOpening>& tgt,
                                        const RigidTransform& t0, const Eigen::Vector3d& n,
                                        const ThicknessSearch& search);

}  // namespace plumb::openings_detail
