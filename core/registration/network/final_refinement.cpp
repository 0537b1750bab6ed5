#include "registration/network/final_refinement.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "registration/refine/icp_refinement.hpp"

namespace plumb {
namespace {

/// The station's points' box in the registered frame (the corners of its own box moved).
Bounds placedBox(const Station& s, const RigidTransform& pose) {
  const Bounds own = s.input.cloud.bounds();
  Bounds b;
  for (int c = 0; c < 8; ++c)
    b.extend(pose.apply(Eigen::Vector3d(c & 1 ? own.max.x() : own.min.x(), c & 2 ? own.max.y() : own.min.y(),
                                        c & 4 ? own.max.z() : own.min.z())));
  return b;
}

bool boxesOverlap(const Bounds& a, const Bounds& b) {
  return (a.min.array() <= b.max.array()).all() && (b.min.array() <= a.max.array()).all();
}

bool rejected(const std::vector<Link>& links, std::size_t a, std::size_t b) {
  return std::any_of(links.begin(), links.end(), [&](const Link& l) {
    return l.decision == "rejected" && ((l.a == a && l.b == b) || (l.a == b && l.b == a));
  });
}

RefineParams refineParams(const NetworkParams& p) {
  RefineParams r = p.link.refinement;
  r.start_distance = p.final_refinement.start_distance;
  r.final_distance = p.final_refinement.final_distance;
  r.stages = 3;
  return r;
}

Link refinedLink(std::size_t a, std::size_t b, const RefineResult& r, const NetworkParams& p) {
  Link l;
  l.a = a, l.b = b;
  l.reason = kFinalRefinementReason;
  l.transform = r.transform;
  l.registered = l.accepted = true;
  l.level = VerdictLevel::Usable;
  l.verdict = "refined on points at the adjusted poses";
  l.status = "success";
  l.method = kFinalRefinementReason;
  l.overlap = r.overlap;
  l.point_rms = r.rms;
  l.length_scale = r.length_scale;
  l.weakest_resistance = *std::min_element(r.direction_resistance.begin(), r.direction_resistance.end());
  weighLink(l, p.weights);
  return l;
}

}  // namespace

std::vector<Link> refinedPairLinks(const std::vector<Station>& stations,
                                   const std::vector<std::optional<RigidTransform>>& poses,
                                   const std::vector<std::size_t>& skip, const std::vector<Link>& links,
                                   const NetworkParams& params, FinalRefinementSummary& summary) {
  const auto t0 = std::chrono::steady_clock::now();
  const RefineParams rp = refineParams(params);
  const auto usable = [&](std::size_t i) {
    return poses[i] && !stations[i].is_model && std::find(skip.begin(), skip.end(), i) == skip.end();
  };
  std::vector<Bounds> boxes(stations.size());
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (usable(i)) boxes[i] = placedBox(stations[i], *poses[i]);
  std::vector<Link> out;
  for (std::size_t a = 0; a < stations.size(); ++a) {
    if (!usable(a)) continue;
    std::unique_ptr<RefineTarget> target;  // built once per target station, when a pair needs it
    for (std::size_t b = a + 1; b < stations.size(); ++b) {
      if (!usable(b) || !boxesOverlap(boxes[a], boxes[b]) || rejected(links, a, b)) continue;
      ++summary.pairs_tried;
      if (!target) target = std::make_unique<RefineTarget>(stations[a].input.cloud, rp, stations[a].input.viewpoint);
      const RigidTransform initial = poses[a]->inverse() * *poses[b];  // b's frame -> a's frame
      const RefineResult r = refineRegistration(stations[b].input.cloud, *target, initial, rp, nullptr,
                                                stations[b].input.viewpoint);
      if (r.overlap < params.final_refinement.min_overlap || r.inliers == 0) continue;
      out.push_back(refinedLink(a, b, r, params));
    }
  }
  summary.pairs_used = out.size();
  summary.done = true;
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

std::vector<Link> withRefinedPairs(const std::vector<Link>& links, const std::vector<Link>& refined) {
  std::vector<Link> out;
  for (const auto& l : links)
    if (l.reason != kFinalRefinementReason) out.push_back(l);
  out.insert(out.end(), refined.begin(), refined.end());
  return out;
}

}  // namespace plumb
