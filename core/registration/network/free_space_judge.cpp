#include "registration/network/free_space_judge.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "common/stopwatch.hpp"
#include "quality/station_range_images.hpp"
#include "registration/network/robust_adjustment.hpp"

namespace plumb {

namespace {

/// Axis-aligned box of `b` moved by `pose`.
Bounds placedBox(const Bounds& b, const RigidTransform& pose) {
  Bounds out;
  for (int c = 0; c < 8; ++c)
    out.extend(pose.apply(Eigen::Vector3d(c & 1 ? b.max.x() : b.min.x(), c & 2 ? b.max.y() : b.min.y(),
                                          c & 4 ? b.max.z() : b.min.z())));
  return out;
}

bool boxesMeet(const Bounds& a, const Bounds& b, double margin) {
  for (int k = 0; k < 3; ++k)
    if (a.min[k] > b.max[k] + margin || b.min[k] > a.max[k] + margin) return false;
  return true;
}

/// Every station's range images (built when first needed) and box, and the tallies of
/// station pairs at given poses (a pair is tested once per hypothesis).
class FreeSpaceTester {
 public:
  FreeSpaceTester(const std::vector<Station>& stations, const FreeSpaceJudgeParams& p, VisibilityParams v)
      : stations_(stations), params_(p), visibility_(std::move(v)), images_(stations.size()) {
    visibility_.max_test_points = p.test_points;
    for (const auto& s : stations) boxes_.push_back(s.is_model ? Bounds() : s.input.cloud.bounds());
  }

  /// Both directions between station i at pose pi and station j at pose pj; `key` names the
  /// hypothesis giving the poses (-1: the adopted solution).
  FreeSpaceTally pair(std::size_t i, const RigidTransform& pi, std::size_t j, const RigidTransform& pj, int key) {
    const auto id = std::make_tuple(std::min(i, j), std::max(i, j), key);
    if (const auto it = cache_.find(id); it != cache_.end()) return it->second;
    FreeSpaceTally t;
    if (boxesMeet(placedBox(boxes_[i], pi), placedBox(boxes_[j], pj), params_.box_margin)) {
      t.add(oneWay(j, pj.inverse() * pi, i));
      t.add(oneWay(i, pi.inverse() * pj, j));
    }
    return cache_[id] = t;
  }

 private:
  FreeSpaceTally oneWay(std::size_t observer, const RigidTransform& tested_to_observer, std::size_t tested) {
    const Station& s = stations_[tested];
    const VisibilityEvidence e =
        freeSpaceEvidence(images(observer), s.input.cloud, s.input.viewpoint, tested_to_observer, visibility_);
    return {e.visible, e.contradicting};
  }

  const StationRangeImages& images(std::size_t i) {
    if (!images_[i])
      images_[i] = std::make_unique<StationRangeImages>(stations_[i].input.cloud, stations_[i].input.viewpoint,
                                                        visibility_);
    return *images_[i];
  }

  const std::vector<Station>& stations_;
  FreeSpaceJudgeParams params_;
  VisibilityParams visibility_;
  std::vector<std::unique_ptr<StationRangeImages>> images_;
  std::vector<Bounds> boxes_;
  std::map<std::tuple<std::size_t, std::size_t, int>, FreeSpaceTally> cache_;
};

/// Station j is where `poses` puts it relative to i as in `adopted`: the hypothesis moved them
/// together, so their pair says nothing about it.
bool movedTogether(std::size_t i, std::size_t j, const std::vector<std::optional<RigidTransform>>& poses,
                   const std::vector<std::optional<RigidTransform>>& adopted, const PoseGraphParams& graph) {
  if (!adopted[i] || !adopted[j]) return false;
  return samePlacement(poses[i]->inverse() * *poses[j], adopted[i]->inverse() * *adopted[j], graph);
}

std::string percent(const FreeSpaceTally& t) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2f%% of %zu visible points in the free space", 100.0 * t.ratio(), t.visible);
  return buf;
}

struct Judge {
  const std::vector<std::optional<RigidTransform>>& poses;
  const std::vector<PlacementHypothesis>& hypotheses;
  const FreeSpaceJudgeParams& params;
  const PoseGraphParams& graph;
  FreeSpaceTester& tester;

  /// Station i placed by `at` against the observers, each where `at` puts it, but those the
  /// hypothesis moved together with i (`moved`: the stations it places differently from the
  /// adopted solution).
  FreeSpaceTally tallyOf(std::size_t i, const std::vector<std::optional<RigidTransform>>& at,
                         const std::vector<std::size_t>& moved, const std::set<std::size_t>& observers,
                         int key) const {
    FreeSpaceTally t;
    for (std::size_t j : observers) {
      if (j == i || !at[j]) continue;
      const bool moved_j = std::find(moved.begin(), moved.end(), j) != moved.end();
      if (moved_j && movedTogether(i, j, at, poses, graph)) continue;
      t.add(tester.pair(i, *at[i], j, *at[j], key));
    }
    return t;
  }

  JudgedPlacement placement(std::string source, std::optional<std::size_t> h, const RigidTransform& pose,
                            FreeSpaceTally t) const {
    JudgedPlacement p{std::move(source), h, pose, t};
    p.judged = t.visible >= std::size_t(params.min_visible);
    p.clean = p.judged && t.ratio() <= params.clean_ratio;
    return p;
  }

  bool refutes(const JudgedPlacement& clean, const JudgedPlacement& other) const {
    return other.judged && other.tally.ratio() >= params.refute_ratio &&
           other.tally.ratio() >= params.decisive_factor * clean.tally.ratio();
  }

  StationJudgement station(std::size_t i, const std::set<std::size_t>& observers, int round) const {
    StationJudgement j;
    j.station = i;
    j.round = round;
    j.placements.push_back(
        placement("adopted", std::nullopt, *poses[i], tallyOf(i, poses, {i}, observers, -1)));
    for (std::size_t h = 0; h < hypotheses.size(); ++h) {
      const PlacementHypothesis& hyp = hypotheses[h];
      if (std::find(hyp.moved.begin(), hyp.moved.end(), i) != hyp.moved.end() && hyp.poses[i])
        j.placements.push_back(placement(hyp.source, h, *hyp.poses[i],
                                         tallyOf(i, hyp.poses, hyp.moved, observers, int(h))));
    }
    decide(j);
    return j;
  }

  /// Among the clean placements putting the station where p[best] does, the one whose
  /// hypothesis moves the fewest stations. Several dropped links taken as true, and a copy of
  /// the BIM, often place the judged station alike while moving others differently, and only
  /// the judged station was judged: taking the first one as true forced a doorway's half turn
  /// onto another station (office-floor with its BIM, seed 7).
  std::size_t leastMoving(const std::vector<JudgedPlacement>& p, std::size_t best) const {
    const auto moves = [&](std::size_t k) { return hypotheses[*p[k].hypothesis].moved.size(); };
    std::size_t pick = best;
    for (std::size_t k = 1; k < p.size(); ++k)
      if (p[k].clean && samePlacement(p[k].pose, p[best].pose, graph) && moves(k) < moves(pick)) pick = k;
    return pick;
  }

  /// The clean placement refuting every other, if any (the least contradicted first).
  void decide(StationJudgement& j) const {
    const auto& p = j.placements;
    std::size_t best = 0;
    for (std::size_t k = 1; k < p.size(); ++k)
      if (p[k].judged && (!p[best].judged || p[k].tally.ratio() < p[best].tally.ratio())) best = k;
    if (!p[best].clean) {
      j.why = !p[0].judged ? "the placed stations see too little of it (" + std::to_string(p[0].tally.visible) +
                                 " points)"
                           : "no placement of it is clean (adopted: " + percent(p[0].tally) + ")";
      return;
    }
    std::size_t refuted = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (k == best || samePlacement(p[k].pose, p[best].pose, graph)) continue;
      if (!refutes(p[best], p[k])) {
        j.why = "the free space does not tell " + p[best].source + " (" + percent(p[best].tally) + ") from " +
                p[k].source + " (" + (p[k].judged ? percent(p[k].tally) : "not seen enough") + ")";
        return;
      }
      ++refuted;
    }
    if (samePlacement(p[best].pose, p[0].pose, graph)) best = 0;  // the adopted placement, offered again
    else best = leastMoving(p, best);
    j.decided = best;
    j.settled = best == 0;
    j.why = (best == 0 ? "settled by the free space: its placement is clean (" : "placed by the free space at " +
                                                                                    p[best].source + " (") +
            percent(p[best].tally) + ") and refutes " + std::to_string(refuted) + " placement(s) elsewhere";
  }
};

}  // namespace

FreeSpaceJudgement judgeByFreeSpace(const std::vector<Station>& stations,
                                    const std::vector<std::optional<RigidTransform>>& poses,
                                    const std::vector<std::size_t>& ambiguous,
                                    const std::vector<std::size_t>& confirmed,
                                    const std::vector<PlacementHypothesis>& hypotheses,
                                    const FreeSpaceJudgeParams& params, const PoseGraphParams& graph,
                                    const VisibilityParams& visibility) {
  FreeSpaceJudgement out;
  if (!params.enabled || ambiguous.empty()) return out;
  const auto t0 = std::chrono::steady_clock::now();
  out.ran = true;
  FreeSpaceTester tester(stations, params, visibility);
  const Judge judge{poses, hypotheses, params, graph, tester};
  std::set<std::size_t> observers, pending;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    if (stations[i].is_model || !poses[i]) continue;
    if (std::binary_search(ambiguous.begin(), ambiguous.end(), i)) pending.insert(i);
    else if (std::binary_search(confirmed.begin(), confirmed.end(), i)) observers.insert(i);
  }
  std::map<std::size_t, StationJudgement> last;
  for (int round = 1; !pending.empty(); ++round) {
    std::vector<std::size_t> settled, chosen;
    for (std::size_t i : pending) {
      last[i] = judge.station(i, observers, round);
      if (last[i].settled) settled.push_back(i);
      else if (last[i].decided) chosen.push_back(i);
    }
    for (std::size_t i : chosen) {  // placed elsewhere: not an observer until adjusted there
      pending.erase(i);
      out.chosen.push_back({i, hypotheses[*last[i].placements[*last[i].decided].hypothesis]});
    }
    if (settled.empty()) break;
    for (std::size_t i : settled) {
      pending.erase(i);
      observers.insert(i);
      out.settled.push_back(i);
    }
  }
  std::sort(out.settled.begin(), out.settled.end());
  out.observers.assign(observers.begin(), observers.end());
  for (auto& [i, j] : last) out.stations.push_back(std::move(j));
  out.seconds = secondsSince(t0);
  return out;
}

}  // namespace plumb
