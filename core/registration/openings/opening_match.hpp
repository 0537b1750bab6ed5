#pragma once
// Matching indoor openings to outdoor openings through a wall of unknown thickness (beyond the
// 2023 paper, docs/ALGORITHMS.md §6). The paper scores a hypothesis with the global robust segment
// distance (2023 eqs. 7-8) between opening edges placed with zero façade thickness, which
// only lets the openings of ONE façade match (the indoor faces of the other walls stay a
// wall thickness away from their façades) and so cannot tell apart shifts by one window
// spacing of a regular façade. Here every source opening is matched on every façade at once:
//  - an opening's outward normal comes from its corner order (plumb::Opening: counter-
//    clockwise seen from the scanner side), so an indoor opening faces INTO the room and an
//    outdoor one OUT of the building; a source opening can only pair with a target façade it
//    faces away from (R n_in = -n_out);
//  - the source opening must lie behind the target façade face (inside the building) by a
//    plausible wall thickness, in [-d, max_thickness] (d = robust distance of eq. 7);
//  - its edges are then moved along the façade normal onto the façade face and scored with
//    eq. 7 against the target opening edges (spatial index of segment_set_distance), so the
//    thickness does not count, only the in-plane agreement of the edges.
// The per-façade offsets of the matched openings measure the wall thickness.
#include <Eigen/Core>

#include <array>
#include <vector>

#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"
#include "registration/segment_distance/segment_set_distance.hpp"

namespace plumb {

/// An opening with what the matcher needs: outward normal (towards the scanner side), centre,
/// bottom height, width.
struct OrientedOpening {
  int index = -1;  ///< into FeatureSet::openings
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();  ///< unit, towards the scanner side
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double width = 0.0, height = 0.0;
  std::array<Segment3D, 4> edges;
};

/// Openings of `f` lying in vertical walls (within `vertical_tolerance_deg`), oriented by their
/// corner order. Degenerate ones (zero area) are skipped.
std::vector<OrientedOpening> orientedOpenings(const FeatureSet& f, double vertical_tolerance_deg);

/// One source opening edge matched under a hypothesis.
struct ThickEdgeMatch {
  Eigen::Vector3d a, b;         ///< source edge endpoints, transformed, moved onto the façade
  int target_edge = -1;         ///< into the index's segments
  Eigen::Vector3d facade_normal;  ///< outward normal of the target façade
  double similarity = 0.0;      ///< 1 - eq.7 / d^2, in [0, 1]
  double thickness = 0.0;       ///< how far a, b were moved along facade_normal, metres
};

struct ThickScore {
  double score = 0.0;       ///< sum of edge similarities ("matched opening edges")
  int matched_openings = 0; ///< source openings with at least 2 edges matched
  /// Wall thickness of each matched source opening (distance of its wall face behind the
  /// target façade face), metres.
  std::vector<double> thickness;
  std::vector<ThickEdgeMatch> matches;  ///< filled only when requested
};

class ThickOpeningMatcher {
 public:
  /// `target` openings (oriented) and their edges indexed for eq. 7.
  ThickOpeningMatcher(std::vector<OrientedOpening> target, const SegmentDistanceParams& distance,
                      double max_thickness, double angle_tolerance_deg);

  /// Score of `source` openings mapped by `t` (see the header comment).
  ThickScore score(const std::vector<OrientedOpening>& source, const RigidTransform& t,
                   bool keep_matches = false) const;

  /// Least squares on the matched edges: yaw and translation (2023 eqs. 11-14 generalised,
  /// point-to-line on both endpoints, with the façade-normal component removed from each
  /// residual: the thickness is free). Returns `t` unchanged when the system is not
  /// determined (e.g. openings on one façade only leave the normal DOF free).
  RigidTransform polish(const std::vector<OrientedOpening>& source, const RigidTransform& t,
                        int iterations, double* rms = nullptr) const;

  const std::vector<OrientedOpening>& target() const { return target_; }

 private:
  std::vector<OrientedOpening> target_;
  SegmentSetIndex index_;
  double max_thickness_, cos_tol_, d_;
};

}  // namespace plumb
