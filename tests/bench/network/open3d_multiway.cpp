// Open3D's multiway registration on Plumb's links (open3d_multiway.hpp).
#include "open3d_multiway.hpp"

#include <open3d/pipelines/registration/GlobalOptimization.h>
#include <open3d/pipelines/registration/PoseGraph.h>
#include <open3d/utility/Logging.h>

#include <chrono>
#include <cmath>

namespace plumb::bench {
namespace {

namespace reg = open3d::pipelines::registration;

Eigen::Matrix6d informationOf(const AdjustmentLink& l, double correspondences) {
  const double lever = l.sigma_translation / (l.sigma_rotation_deg * M_PI / 180.0);
  Eigen::Matrix6d m = Eigen::Matrix6d::Identity() * correspondences;
  m.topLeftCorner<3, 3>() *= lever * lever;
  return m;
}

/// Station poses chained along the certain links from the reference (nullopt: unreached).
std::vector<std::optional<RigidTransform>> chainOdometry(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                                         const std::vector<bool>& certain, std::size_t reference,
                                                         const RigidTransform& reference_pose) {
  std::vector<std::optional<RigidTransform>> pose(stations);
  pose[reference] = reference_pose;
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t k = 0; k < links.size(); ++k) {
      const auto& l = links[k];
      if (!certain[k]) continue;
      if (pose[l.a] && !pose[l.b]) pose[l.b] = *pose[l.a] * l.transform, grew = true;
      else if (pose[l.b] && !pose[l.a]) pose[l.a] = *pose[l.b] * l.transform.inverse(), grew = true;
    }
  }
  return pose;
}

}  // namespace

std::vector<bool> consecutiveLinks(std::size_t stations, const std::vector<AdjustmentLink>& links) {
  std::vector<bool> out;
  for (const auto& l : links)
    out.push_back(l.b == l.a + 1 || (l.a == stations - 1 && l.b == 0) || (l.b == stations - 1 && l.a == 0));
  return out;
}

MultiwayResult open3dMultiway(std::size_t stations, const std::vector<AdjustmentLink>& links,
                              const std::vector<bool>& certain, std::size_t reference,
                              const RigidTransform& reference_pose, double correspondences,
                              double max_correspondence_distance) {
  open3d::utility::SetVerbosityLevel(open3d::utility::VerbosityLevel::Error);
  MultiwayResult out;
  const auto start = chainOdometry(stations, links, certain, reference, reference_pose);
  reg::PoseGraph graph;
  for (std::size_t i = 0; i < stations; ++i) graph.nodes_.emplace_back(start[i].value_or(RigidTransform()).matrix());
  for (std::size_t k = 0; k < links.size(); ++k) {  // Open3D: source b, target a, transformation b -> a
    const auto& l = links[k];
    if (start[l.a] && start[l.b])
      graph.edges_.emplace_back(int(l.b), int(l.a), l.transform.matrix(), informationOf(l, correspondences),
                                !certain[k]);
  }
  const auto t0 = std::chrono::steady_clock::now();
  reg::GlobalOptimization(graph, reg::GlobalOptimizationLevenbergMarquardt(), reg::GlobalOptimizationConvergenceCriteria(),
                          reg::GlobalOptimizationOption(max_correspondence_distance, 0.25, 1.0, int(reference)));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (std::size_t i = 0; i < stations; ++i) {
    const Eigen::Matrix4d m = graph.nodes_[i].pose_;
    out.poses.push_back(start[i] ? std::optional<RigidTransform>(RigidTransform(m.topLeftCorner<3, 3>(), m.topRightCorner<3, 1>()))
                                 : std::nullopt);
  }
  // The pruned edges are removed from the graph: a link is kept when an edge with its nodes
  // and its measurement is left.
  for (const auto& l : links) {
    bool kept = false;
    for (const auto& e : graph.edges_)
      kept = kept || (e.source_node_id_ == int(l.b) && e.target_node_id_ == int(l.a) &&
                      e.transformation_.isApprox(l.transform.matrix(), 1e-12));
    out.pruned.push_back(!kept);
  }
  return out;
}

}  // namespace plumb::bench
