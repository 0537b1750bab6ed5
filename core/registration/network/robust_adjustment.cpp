#include "registration/network/robust_adjustment.hpp"

#include <algorithm>
#include <cmath>

namespace plumb {
namespace {

std::vector<GraphEdge> graphEdges(const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& kept) {
  std::vector<GraphEdge> edges;
  for (std::size_t k : kept) edges.push_back({links[k].a, links[k].b, links[k].transform});
  return edges;
}

/// Kept links (local indices) ordered for the initial tree: forced links, then links to the BIM,
/// then sequence links, then most
/// closing triangles minus failing ones, then the smallest sigma.
std::vector<std::size_t> treeOrder(const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& kept,
                                   const std::vector<TriangleSupport>& support, const std::vector<bool>& forced) {
  std::vector<std::size_t> order(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    if (forced[kept[x]] != forced[kept[y]]) return bool(forced[kept[x]]);
    if (links[kept[x]].anchor != links[kept[y]].anchor) return links[kept[x]].anchor;
    if (links[kept[x]].sequence != links[kept[y]].sequence) return links[kept[x]].sequence;
    const int sx = support[x].closing - support[x].failing, sy = support[y].closing - support[y].failing;
    if (sx != sy) return sx > sy;
    return links[kept[x]].sigma_translation < links[kept[y]].sigma_translation;
  });
  return order;
}

std::vector<std::size_t> sigmaOrder(const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& kept) {
  std::vector<std::size_t> order(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return links[kept[x]].sigma_translation < links[kept[y]].sigma_translation;
  });
  return order;
}

PoseGraphProblem problemFor(const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& kept,
                            const std::vector<std::optional<RigidTransform>>& initial, std::size_t reference,
                            const PoseGraphParams& params, const LockedStations& locked) {
  PoseGraphProblem pg;
  for (const auto& p : initial) pg.initial.push_back(p.value_or(RigidTransform()));
  pg.reference = reference;
  for (const auto& [i, pose] : locked)
    if (initial.at(i)) pg.fixed.push_back(i);
  pg.robust_scale = params.robust_scale;
  pg.max_iterations = params.max_iterations;
  for (std::size_t k : kept) {
    const auto& l = links[k];
    if (initial[l.a] && initial[l.b])
      pg.edges.push_back(poseGraphEdge(l));
  }
  return pg;
}

/// How far beyond the drop thresholds a residual is (> 1: beyond).
double dropRatio(const EdgeResidual& r, const PoseGraphParams& p) {
  return std::max(r.translation / p.drop_translation, r.rotation_deg / p.drop_rotation);
}

/// Initial poses from the tree of the kept links, then one solve; fills poses, sigmas and the
/// residual of every link whose stations are placed. Returns the tree (indices into kept).
std::vector<std::size_t> solveOnce(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                   const std::vector<std::size_t>& kept, std::size_t reference,
                                   const RigidTransform& reference_pose, const PoseGraphParams& params,
                                   const std::vector<bool>& forced, const LockedStations& locked,
                                   NetworkAdjustment& out) {
  const auto edges = graphEdges(links, kept);
  const auto support = triangleSupport(stations, edges, params.triangle_tolerance, params.drop_rotation);
  const auto tree = spanningTree(stations, edges, treeOrder(links, kept, support, forced));
  out.poses = chainPoses(stations, edges, tree, reference, reference_pose);
  for (const auto& [i, pose] : locked)
    if (out.poses.at(i)) out.poses[i] = pose;  // placed by the links, held where the surveyor locked it
  const PoseGraphSolution s = solvePoseGraph(problemFor(links, kept, out.poses, reference, params, locked));
  ++out.solves;
  for (std::size_t i = 0; i < stations; ++i)
    if (out.poses[i] && !locked.count(i)) out.poses[i] = s.poses[i];  // a locked pose stays bit for bit
  out.sigma_position = s.sigma_position;
  out.sigma_rotation_deg = s.sigma_rotation_deg;
  out.converged = s.converged || s.residuals.empty();
  out.covariance_ok = s.covariance_ok;
  out.message = s.message;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const auto& l = links[k];
    if (out.poses[l.a] && out.poses[l.b])
      out.links[k].residual = edgeResidual(poseGraphEdge(l), *out.poses[l.a], *out.poses[l.b]);
  }
  return tree;
}

/// Position in kept of the link furthest beyond the drop thresholds (forced links excepted);
/// kept.size() if none is.
std::size_t worstBeyondDrop(const std::vector<std::size_t>& kept, const NetworkAdjustment& out,
                            const PoseGraphParams& params, const std::vector<bool>& forced) {
  std::size_t worst = kept.size();
  double worst_ratio = 1.0;
  for (std::size_t i = 0; i < kept.size(); ++i) {
    if (forced[kept[i]]) continue;
    const double ratio = dropRatio(out.links[kept[i]].residual, params);
    if (ratio > worst_ratio) worst_ratio = ratio, worst = i;
  }
  return worst;
}

/// Flags, loop closures and the chain comparison of the final kept links.
void summarise(std::size_t stations, const std::vector<AdjustmentLink>& links, const std::vector<std::size_t>& kept,
               const std::vector<std::size_t>& tree, std::size_t reference, const RigidTransform& reference_pose,
               const PoseGraphParams& params, NetworkAdjustment& out) {
  for (auto& o : out.links)
    o.flagged = o.dropped || beyondFlag(o.residual, params);
  const auto edges = graphEdges(links, kept);
  const auto bridge = bridgeEdges(stations, edges);
  for (std::size_t i = 0; i < kept.size(); ++i) out.links[kept[i]].bridge = bridge[i];
  out.loops = loopClosures(stations, edges, tree);
  for (auto& loop : out.loops) loop.edge = kept[loop.edge];
  out.chain_poses = chainPoses(stations, edges, spanningTree(stations, edges, sigmaOrder(links, kept)), reference,
                               reference_pose);
}

}  // namespace

PoseGraphEdge poseGraphEdge(const AdjustmentLink& l) {
  return {l.a, l.b, l.transform, l.sigma_translation, l.sigma_rotation_deg * M_PI / 180.0};
}

bool beyondFlag(const EdgeResidual& r, const PoseGraphParams& p) {
  return r.translation > p.flag_translation || r.rotation_deg > p.flag_rotation;
}

bool samePlacement(const RigidTransform& a, const RigidTransform& b, const PoseGraphParams& p) {
  return RigidTransform::translationError(a, b) <= p.drop_translation &&
         RigidTransform::rotationErrorDeg(a, b) <= p.drop_rotation;
}

NetworkAdjustment adjustNetwork(std::size_t stations, const std::vector<AdjustmentLink>& links,
                                std::size_t reference, const RigidTransform& reference_pose,
                                const PoseGraphParams& params, const std::vector<std::size_t>& forced_links,
                                const LockedStations& locked) {
  NetworkAdjustment out;
  out.links.resize(links.size());
  std::vector<bool> forced(links.size(), false);
  for (std::size_t k : forced_links) forced.at(k) = true;
  std::vector<std::size_t> kept(links.size());
  for (std::size_t k = 0; k < kept.size(); ++k) kept[k] = k;
  const auto all_support = triangleSupport(stations, graphEdges(links, kept), params.triangle_tolerance,
                                           params.drop_rotation);
  for (std::size_t k = 0; k < links.size(); ++k) out.links[k].triangles = all_support[k];
  while (true) {
    const auto tree = solveOnce(stations, links, kept, reference, reference_pose, params, forced, locked, out);
    const std::size_t worst = params.auto_drop ? worstBeyondDrop(kept, out, params, forced) : kept.size();
    if (worst == kept.size()) {
      summarise(stations, links, kept, tree, reference, reference_pose, params, out);
      return out;
    }
    out.links[kept[worst]].dropped = true;
    out.dropped_order.push_back(kept[worst]);
    kept.erase(kept.begin() + static_cast<long>(worst));
  }
}

}  // namespace plumb
