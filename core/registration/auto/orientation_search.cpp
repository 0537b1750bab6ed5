#include "registration/auto/orientation_search.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <sstream>
#include <tuple>

#include "registration/orientation/levelling.hpp"
#include "registration/orientation/up_direction.hpp"

namespace plumb {

namespace {

void note(std::vector<std::string>* log, const std::string& s) {
  if (log) log->push_back(s);
}

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream o;
  o.precision(3);
  o << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return o.str();
}

/// One up direction tried: the levelling applied to the source and the global result,
/// composed back into the source's frame.
struct OrientedResult {
  Eigen::Vector3d up;
  RigidTransform levelling;
  GlobalRegistrationResult global;
};

bool hasAnswer(const GlobalRegistrationResult& g) {
  return g.ok() || g.status == RegistrationStatus::Ambiguous;
}

/// Whether the global step can use openings (re-detected on the levelled data only then): auto
/// tries them whenever the target carries openings, a scan's or a model's (its IfcWindow /
/// IfcDoor elements: registerFeatureSets' fallback after segments), so a tilted source reaches
/// the same methods as a levelled one.
bool usesOpenings(const FeatureSet& target, const PipelineParams& p) {
  if (p.method == RegistrationMethod::Openings) return true;
  return p.method == RegistrationMethod::Auto && !target.openings.empty();
}

/// The source's features moved by the levelling L; façades and openings detected again on the
/// levelled cloud (they depend on the vertical) when the global step can use them.
FeatureSet levelledFeatures(const RegistrationSide& source, const FeatureSet& f,
                            const RigidTransform& L, bool openings, const PipelineParams& p,
                            Progress* progress) {
  FeatureSet out;
  out.planes = f.planes;
  for (auto& pl : out.planes) levelPolygon(pl, L);
  out.segments = f.segments;
  for (auto& s : out.segments) s.transform(L);
  if (!openings || !source.cloud) return out;
  PointCloud levelled = *source.cloud;
  levelled.transform(L);
  auto op = detectOpenings(levelled, out.planes, p.opening_detection, progress);
  out.facades = std::move(op.facades);
  out.openings = std::move(op.openings);
  return out;
}

/// T = T_levelled * L for the answer and every hypothesis.
void composeLevelling(GlobalRegistrationResult& g, const RigidTransform& L) {
  g.transform = g.transform * L;
  if (g.runner_up) g.runner_up->transform = g.runner_up->transform * L;
  for (auto& a : g.alternatives) a.transform = a.transform * L;
}

/// The global step on the source levelled by L (results in the source's frame).
OrientedResult registerLevelledBy(const Eigen::Vector3d& up, const RigidTransform& L,
                                  const RegistrationSide& source, const FeatureSet& sf,
                                  const FeatureSet& tf, bool target_is_model,
                                  const PipelineParams& p, std::vector<std::string>* log,
                                  Progress* progress, const SegmentsOnDemand& segments_on_demand) {
  const FeatureSet levelled =
      levelledFeatures(source, sf, L, usesOpenings(tf, p), p, progress);
  SegmentsOnDemand levelled_segments;
  if (segments_on_demand)
    levelled_segments = [&]() {
      SegmentSets s = segments_on_demand();
      for (auto& seg : s.source) seg.transform(L);
      return s;
    };
  note(log, "orientation: up " + vec(up) + " levelled onto +Z");
  OrientedResult r{up, L,
                   registerFeatureSets(levelled, tf, target_is_model, p, log, progress,
                                       levelled_segments)};
  composeLevelling(r.global, L);
  return r;
}

double minGapOf(const std::string& method, const PipelineParams& p) {
  if (method == "segments") return p.segments.min_relative_gap;
  if (method == "openings") return p.openings.min_relative_gap;
  return p.planes.min_relative_gap;
}

/// Preference of a global result: a success, then an ambiguous one (the refinement may settle
/// it), then a failure.
int statusRank(const GlobalRegistrationResult& g) {
  return g.ok() ? 2 : g.status == RegistrationStatus::Ambiguous ? 1 : 0;
}

/// auto's preference among methods (scores of different methods do not compare): openings
/// (confirmed by or settling the planes), planes, segments (the last resort).
int methodRank(const std::string& method) {
  return method == "openings" ? 2 : method == "planes" ? 1 : 0;
}

/// Indices of the results, best first: by status, method, then score; ties keep the up
/// candidates' order of plausibility.
std::vector<std::size_t> rankResults(const std::vector<OrientedResult>& r) {
  std::vector<std::size_t> order(r.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&r](std::size_t i) {
    const auto& g = r[i].global;
    return std::make_tuple(statusRank(g), methodRank(g.method), g.score);
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key(a) > key(b); });
  return order;
}

/// Hypotheses of the answer's method first (their scores compare), then by score.
void sortForMethod(std::vector<Hypothesis>& pool, const std::vector<bool>& same_method) {
  std::vector<std::size_t> order(pool.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_pair(bool(same_method[a]), pool[a].score) >
           std::make_pair(bool(same_method[b]), pool[b].score);
  });
  std::vector<Hypothesis> sorted;
  for (std::size_t i : order) sorted.push_back(pool[i]);
  pool = std::move(sorted);
}

/// The runner-up of one up direction's answer when it scores within the method's gap of it
/// (that direction's own result is ambiguous): under a gable roof the right up direction can
/// come with the half-turned yaw first, and its runner-up is the truth.
std::optional<Hypothesis> closeRunnerUp(const GlobalRegistrationResult& g, const PipelineParams& p) {
  if (!g.runner_up || g.score <= 0) return std::nullopt;
  if ((g.score - g.runner_up->score) / g.score >= minGapOf(g.method, p)) return std::nullopt;
  return g.runner_up;
}

/// The best up direction's result with every other up direction's answer as a runner-up or
/// further hypothesis; ambiguous when one of them scores within the method's gap.
GlobalRegistrationResult mergeOrientations(std::vector<OrientedResult> results,
                                           const PipelineParams& p) {
  const std::vector<std::size_t> order = rankResults(results);
  GlobalRegistrationResult best = results[order[0]].global;
  const std::string how = "orientation: source up " + vec(results[order[0]].up) +
                          " levelled onto +Z (" + std::to_string(results.size()) +
                          " up directions tried); ";
  if (!hasAnswer(best)) {
    best = results[0].global;  // the most plausible up direction's failure
    best.message = how + "none gave an answer; " + best.message;
    return best;
  }
  std::vector<Hypothesis> pool = best.alternatives;
  if (best.runner_up) pool.push_back(*best.runner_up);
  std::vector<bool> same_method(pool.size(), true);
  bool close = false;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const OrientedResult& o = results[order[k]];
    if (!hasAnswer(o.global)) continue;
    pool.push_back({o.global.transform, o.global.score, "up " + vec(o.up) + ": " + o.global.method});
    best.orientation_answers.push_back(pool.back());
    if (const auto second = closeRunnerUp(o.global, p))  // a symmetric building's other yaw
      best.orientation_answers.push_back({second->transform, second->score,
                                          "up " + vec(o.up) + ": " + o.global.method + " runner-up"});
    same_method.push_back(o.global.method == best.method);
    if (same_method.back() && statusRank(o.global) == statusRank(best) && best.score > 0 &&
        (best.score - o.global.score) / best.score < minGapOf(best.method, p))
      close = true;
  }
  sortForMethod(pool, same_method);
  best.runner_up.reset();
  best.alternatives.clear();
  for (const Hypothesis& h : pool) {
    if (!best.runner_up) best.runner_up = h;
    else if (best.alternatives.size() < HypothesisRanking::kAlternatives) best.alternatives.push_back(h);
  }
  if (best.runner_up && best.score > 0)
    best.relative_gap = (best.score - best.runner_up->score) / best.score;
  if (close) {
    best.status = RegistrationStatus::Ambiguous;
    best.message = how + "another up direction scores about as well: not choosing; " + best.message;
  } else {
    best.message = how + best.message;
  }
  return best;
}

/// Every up candidate levelled and searched, merged (results in the source's frame).
GlobalRegistrationResult searchUpCandidates(const std::vector<UpCandidate>& candidates,
                                            const RegistrationSide& source, const FeatureSet& sf,
                                            const FeatureSet& tf, bool target_is_model,
                                            const PipelineParams& p, std::vector<std::string>* log,
                                            Progress* progress,
                                            const SegmentsOnDemand& segments_on_demand) {
  const Eigen::Vector3d centre = featureBounds(sf).center();
  std::vector<OrientedResult> results;
  for (const UpCandidate& c : candidates) {
    checkCanceled(progress);
    results.push_back(registerLevelledBy(c.up, levellingTransform(c.up, centre), source, sf, tf,
                                         target_is_model, p, log, progress, segments_on_demand));
  }
  GlobalRegistrationResult merged = mergeOrientations(std::move(results), p);
  merged.up_estimated = true;
  return merged;
}

}  // namespace

GlobalRegistrationResult registerInAnyOrientation(const RegistrationSide& source,
                                                  const FeatureSet& sf, const FeatureSet& tf,
                                                  bool target_is_model, const PipelineParams& p,
                                                  std::vector<std::string>* log, Progress* progress,
                                                  const SegmentsOnDemand& segments_on_demand) {
  const SourceOrientation mode = p.orientation.source;
  if (mode == SourceOrientation::Levelled)
    return registerFeatureSets(sf, tf, target_is_model, p, log, progress, segments_on_demand);
  if (mode == SourceOrientation::YUp) {
    note(log, "orientation: the source is declared Y-up");
    const Eigen::Vector3d centre = featureBounds(sf).center();
    auto r = registerLevelledBy(Eigen::Vector3d::UnitY(), yUpLevelling(centre), source, sf, tf,
                                target_is_model, p, log, progress, segments_on_demand);
    r.global.message = "orientation: declared Y-up, levelled onto +Z; " + r.global.message;
    return r.global;
  }
  const UpEstimate est = estimateUpDirections(sf.planes, sf.segments, p.orientation, p.planes.clustering);
  note(log, est.message);
  if (est.candidates.empty())
    return registerFeatureSets(sf, tf, target_is_model, p, log, progress, segments_on_demand);
  if (mode == SourceOrientation::Auto && est.looks_levelled) {
    GlobalRegistrationResult g =
        registerFeatureSets(sf, tf, target_is_model, p, log, progress, segments_on_demand);
    if (hasAnswer(g) || est.axes < 2) return g;
    note(log, "orientation: the levelled search found no answer; trying the other up directions");
    const std::vector<UpCandidate> others(est.candidates.begin() + 1, est.candidates.end());
    GlobalRegistrationResult o = searchUpCandidates(others, source, sf, tf, target_is_model, p,
                                                    log, progress, segments_on_demand);
    return hasAnswer(o) ? o : g;
  }
  return searchUpCandidates(est.candidates, source, sf, tf, target_is_model, p, log, progress,
                            segments_on_demand);
}

}  // namespace plumb
