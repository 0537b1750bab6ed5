#pragma once
// The coarse-to-fine point-to-plane ICP loop and its final figures (docs/ALGORITHMS.md §8),
// against any target surface (target_surface.hpp): the source points are PCL points in the
// refinement's local frame; the surface may change with the pose (the model triangles visible
// from the stations are found again at each stage). Internal to the refinement module.
#include <Eigen/Core>

#include <functional>
#include <vector>

#include "common/progress.hpp"
#include "registration/common/refine_result.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "registration/refine/point_target.hpp"

namespace plumb::refine_detail {

/// The refinement's pose in the local frame, applied after the initial transform.
struct LocalPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

/// The target surface for the source placed by a pose; called at the start of each stage and
/// once for the final figures. The reference stays valid until the next call.
using SurfaceAt = std::function<const TargetSurface&(const LocalPose&)>;

struct LoopOutcome {
  LocalPose pose;
  int iterations = 0;
  bool converged = false;
};

/// The sensor origin of each source point (local frame, aligned with the source cloud) when
/// correspondences must be surfaces both stations saw (TargetSurface::nearestSeenFrom); null:
/// the nearest surface point, whichever side of it was seen.
using SourceViewers = const std::vector<Eigen::Vector3d>*;

/// Coarse-to-fine point-to-plane ICP: stages of shrinking correspondence distance, early
/// stages on a regular quarter of the source points, the last on all of them. Converged when a
/// step of some stage was small.
LoopOutcome runPointToPlane(const Cloud& src, const SurfaceAt& surface, const RefineParams& p,
                            Progress* progress, SourceViewers viewers = nullptr);

/// Final figures at `pose` (untrimmed: the overlap is what it is): inliers, RMS, overlap,
/// normal matrix, fit cost and (p.slide_test) the slide resistance, into res. `origin`: world
/// position of the local frame's origin.
void measureFit(const Cloud& src, const TargetSurface& surface, const LocalPose& pose,
                const Eigen::Vector3d& origin, const RefineParams& p, RefineResult& res,
                SourceViewers viewers = nullptr);

}  // namespace plumb::refine_detail
