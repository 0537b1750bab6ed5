#include "registration/network/footprint_pairs.hpp"

#include <algorithm>
#include <cmath>

#include "registration/network/graph_tools.hpp"
#include "registration/network/robust_adjustment.hpp"

namespace plumb {
namespace {

std::uint64_t cellKey(double x, double y, double cell) {
  const auto ix = static_cast<std::int64_t>(std::floor(x / cell));
  const auto iy = static_cast<std::int64_t>(std::floor(y / cell));
  return (static_cast<std::uint64_t>(ix) << 32) ^ (static_cast<std::uint64_t>(iy) & 0xffffffffULL);
}

/// The accepted links as the adjustment takes them.
std::vector<AdjustmentLink> adjustmentLinks(const std::vector<Station>& stations, const std::vector<Link>& links) {
  std::vector<AdjustmentLink> out;
  for (const auto& l : links)
    if (l.accepted) out.push_back(adjustmentLink(l, stations));
  return out;
}

}  // namespace

Footprint placedFootprint(const Station& station, const RigidTransform& pose, double cell, std::size_t max_points) {
  Footprint f;
  const PointCloud& c = station.input.cloud;
  const std::size_t step = std::max<std::size_t>(1, c.size() / std::max<std::size_t>(1, max_points));
  for (std::size_t i = 0; i < c.size(); i += step) {
    const Eigen::Vector3d p = pose.apply(c.world(i));
    if (p.allFinite()) f.cells.insert(cellKey(p.x(), p.y(), cell));
  }
  return f;
}

double footprintOverlap(const Footprint& a, const Footprint& b) {
  if (a.cells.empty() || b.cells.empty()) return 0.0;
  const Footprint& small = a.cells.size() <= b.cells.size() ? a : b;
  const Footprint& large = &small == &a ? b : a;
  std::size_t shared = 0;
  for (const auto k : small.cells) shared += large.cells.count(k);
  return double(shared) / double(small.cells.size());
}

PartPlacements placeParts(const std::vector<Station>& stations, const std::vector<Link>& links,
                          const PoseGraphParams& params) {
  const std::size_t n = stations.size();
  const auto adj = adjustmentLinks(stations, links);
  std::vector<GraphEdge> edges;
  for (const auto& l : adj) edges.push_back({l.a, l.b, l.transform});
  PartPlacements out;
  out.part = connectedComponents(n, edges);
  out.poses.assign(n, std::nullopt);
  std::vector<bool> done(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    if (done[out.part[i]]) continue;
    done[out.part[i]] = true;
    const auto size = std::count(out.part.begin(), out.part.end(), out.part[i]);
    if (size < 2) continue;
    const NetworkAdjustment a = adjustNetwork(n, adj, i, RigidTransform{}, params);
    for (std::size_t j = 0; j < n; ++j)
      if (out.part[j] == out.part[i] && a.poses[j]) out.poses[j] = a.poses[j];
  }
  return out;
}

std::vector<CandidatePair> footprintPairs(const std::vector<Station>& stations, const PartPlacements& placed,
                                          const std::set<std::pair<std::size_t, std::size_t>>& tried,
                                          const PairSelectionParams& params) {
  const std::size_t n = stations.size();
  if (params.footprint_per_station <= 0) return {};
  std::vector<std::optional<Footprint>> prints(n);
  for (std::size_t i = 0; i < n; ++i)
    if (placed.poses[i] && !stations[i].is_model)
      prints[i] = placedFootprint(stations[i], *placed.poses[i], params.footprint_cell);
  std::vector<CandidatePair> all;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!prints[i] || !prints[j] || placed.part[i] != placed.part[j] || tried.count({i, j})) continue;
      const double overlap = footprintOverlap(*prints[i], *prints[j]);
      if (overlap >= params.footprint_overlap) all.push_back({i, j, overlap, "footprint"});
    }
  auto out = bestPerStation(std::move(all), params.footprint_per_station, n);
  std::sort(out.begin(), out.end(),
            [](const CandidatePair& x, const CandidatePair& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  return out;
}

}  // namespace plumb
