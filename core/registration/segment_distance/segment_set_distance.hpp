#pragma once
// Global robust distance between two segment sets (2023 §II, eqs. 7-8), evaluated through a
// uniform-grid spatial index on the target set so that one evaluation costs about
// O(|S1| * neighbours) instead of O(|S1| |S2|) (docs/ALGORITHMS.md §5). This is the inner loop of
// the segments and openings RANSACs.
#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/params.hpp"
#include "model/feature_set.hpp"
#include "model/rigid_transform.hpp"

namespace plumb {

struct SegmentDistanceParams {
  /// Robustness distance d of eq. 7, metres, [0.001, 10]. Segments farther apart count as
  /// unmatched. Default 0.10 m: a few times the noise of building scans and BIM tolerance.
  double robust_distance = 0.10;
  /// Only near-parallel segments can match: max angle, degrees, [0.5, 45].
  double max_angle_deg = 5.0;
  static const ParamSchema<SegmentDistanceParams>& schema();
};

/// Per-segment result of eq. 7 and the best match, for reports and refinement.
struct SegmentMatch {
  int target = -1;            ///< best target segment (largest term of the sum), -1 if none
  double cost = 0.0;          ///< eq. 7 clamped to [0, d^2]
  double distance = 0.0;      ///< eq. 4 to the best target
};

/// A target segment set with its spatial index. Build once, evaluate many transforms.
class SegmentSetIndex {
 public:
  SegmentSetIndex(std::vector<Segment3D> target, const SegmentDistanceParams& params);

  const std::vector<Segment3D>& segments() const { return target_; }
  const SegmentDistanceParams& params() const { return params_; }

  /// Eq. 7 for one (already transformed) source segment, clamped at 0 (the sum can exceed d^2
  /// when a long segment is covered by several short ones: docs/ALGORITHMS.md §5).
  SegmentMatch match(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

  /// Eq. 8: sum over the source segments, mapped by `t`, of eq. 7. Lower is better; the value
  /// for no match at all is |S1| d^2.
  double distance(const std::vector<Segment3D>& source, const RigidTransform& t) const;

  /// Similarity form used to rank hypotheses: sum of (1 - eq.7 / d^2), in "matched segments"
  /// (|S1| when every source segment is perfectly covered, 0 when nothing matches).
  double similarity(const std::vector<Segment3D>& source, const RigidTransform& t) const;

  /// Candidates near a point (target indices, possibly repeated across calls; no ordering).
  void candidates(const Eigen::Vector3d& p, std::vector<std::uint32_t>& out) const;

 private:
  std::uint64_t key(const Eigen::Vector3d& p) const;
  std::vector<Segment3D> target_;
  std::vector<Eigen::Vector3d> dir_;
  SegmentDistanceParams params_;
  double cell_ = 1.0;
  double cos_max_angle_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;
};

}  // namespace plumb
