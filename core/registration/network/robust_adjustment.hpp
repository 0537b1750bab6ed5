#pragma once
// The robust network adjustment (docs/NETWORK.md): initial poses from a spanning tree of the
// links (links to the BIM first, then sequence links, then by triangle support, then by weight), the pose graph solved with a Cauchy
// loss (pose_graph.hpp), then the link whose residual disagrees most with the network beyond
// the drop thresholds is dropped and the network solved again, until no link is beyond them.
// Stations the kept links do not connect to the reference are not placed (reported, not forced).
#include <map>
#include <optional>
#include <vector>

#include "registration/network/graph_tools.hpp"
#include "registration/network/network_params.hpp"
#include "registration/network/pose_graph.hpp"

namespace plumb {

struct AdjustmentLink {
  std::size_t a = 0, b = 0;
  RigidTransform transform;  ///< b's frame -> a's frame
  double sigma_translation = 0.001;  ///< m
  double sigma_rotation_deg = 0.01;  ///< deg
  /// Stations shot one after the other (sequence neighbours): such links come first in the
  /// initial spanning tree (shot order is evidence the geometry of identical rooms cannot fake).
  bool sequence = false;
  /// A station registered onto the BIM: absolute evidence, checked against copies of the
  /// station elsewhere in the building by the pipeline's copy search.
  bool anchor = false;
};

struct LinkOutcome {
  EdgeResidual residual;      ///< after the final adjustment (also for dropped links)
  bool flagged = false;       ///< residual beyond the flag thresholds
  bool dropped = false;       ///< removed by the robust loop
  /// Dropped by the georeferencing: the control points contradict it (georeference.hpp).
  bool dropped_by_control = false;
  TriangleSupport triangles;  ///< with all links, before any drop
  /// A kept link that is the only connection between two parts: nothing checks it.
  bool bridge = false;
};

struct NetworkAdjustment {
  std::vector<std::optional<RigidTransform>> poses;  ///< station -> reference frame; empty: not placed
  std::vector<Eigen::Vector3d> sigma_position, sigma_rotation_deg;  ///< m, deg
  std::vector<LinkOutcome> links;                    ///< per input link
  std::vector<LoopClosure> loops;                    ///< of the kept links (edge = input link index)
  /// The same kept links chained along their best spanning tree (smallest sigma first), no
  /// adjustment: the comparison a network must beat.
  std::vector<std::optional<RigidTransform>> chain_poses;
  std::vector<std::size_t> dropped_order;  ///< input link indices, in the order dropped
  int solves = 0;
  bool converged = false;
  bool covariance_ok = false;
  std::string message;  ///< the last solver summary
};

/// The pose-graph edge of a link (its rotation sigma in radians).
PoseGraphEdge poseGraphEdge(const AdjustmentLink& link);

/// A link's residual beyond the flag thresholds: the link disagrees with the network.
bool beyondFlag(const EdgeResidual& residual, const PoseGraphParams& params);

/// Two poses of one station are the same placement: within the drop thresholds of each other.
bool samePlacement(const RigidTransform& a, const RigidTransform& b, const PoseGraphParams& params);

/// Stations held at a given pose (station -> reference frame): the surveyor locked them.
using LockedStations = std::map<std::size_t, RigidTransform>;

/// `forced`: links (indices into `links`) taken as true: first in the initial tree and never
/// dropped (competing_placements.hpp asks what the network says if a dropped link was right;
/// the surveyor accepts a link). `locked`: stations the links place are held at these poses
/// (the others still come from the links); the robust loop then drops links that disagree.
NetworkAdjustment adjustNetwork(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                std::size_t reference, const RigidTransform& reference_pose,
                                const PoseGraphParams& params, const std::vector<std::size_t>& forced = {},
                                const LockedStations& locked = {});

}  // namespace plumb
