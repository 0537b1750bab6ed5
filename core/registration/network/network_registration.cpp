#include "registration/network/network_registration.hpp"

#include <algorithm>
#include <chrono>
#include <iterator>
#include <set>

#include "common/error.hpp"
#include "registration/network/control_parts.hpp"
#include "registration/network/footprint_pairs.hpp"
#include "registration/network/mms_windows.hpp"
#include "registration/network/unchecked_stations.hpp"

namespace plumb {
namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<GraphEdge> acceptedEdges(const std::vector<Link>& links) {
  std::vector<GraphEdge> edges;
  for (const auto& l : links)
    if (l.accepted) edges.push_back({l.a, l.b, l.transform});
  return edges;
}

/// Registers `pairs`, appending to out.links.
void registerPairs(const std::vector<Station>& stations, const std::vector<CandidatePair>& pairs,
                   const NetworkParams& params, NetworkResult& out, Progress* progress) {
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (progress) {
      progress->check();
      progress->report(double(k) / double(pairs.size()),
                       "link " + stations[pairs[k].a].name + " - " + stations[pairs[k].b].name);
    }
    out.links.push_back(registerLink(stations[pairs[k].a], stations[pairs[k].b], pairs[k], params));
  }
}

/// A static scan station: neither the model nor a window of an MMS pass.
bool isStatic(const Station& s) { return !s.is_model && s.mms_pass < 0; }

/// Layout similarity of every node pair; the model and MMS windows are similar to nothing (they
/// are paired with every static station anyway: firstPairs, mmsPairs).
std::vector<std::vector<double>> nodeSimilarity(const std::vector<Station>& stations) {
  std::vector<LayoutDescriptor> layouts;
  for (const auto& s : stations) layouts.push_back(s.layout);
  auto similarity = similarityMatrix(layouts);
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (!isStatic(stations[i]))
      for (std::size_t j = 0; j < stations.size(); ++j)
        if (j != i) similarity[i][j] = similarity[j][i] = 0.0;
  return similarity;
}

/// Layout and sequence pairs among the static stations, every static station with the model,
/// then the MMS windows' pairs (mmsPairs).
std::vector<CandidatePair> firstPairs(const std::vector<Station>& stations,
                                      const std::vector<std::vector<double>>& similarity, const NetworkParams& params) {
  std::vector<std::size_t> statics;
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (isStatic(stations[i])) statics.push_back(i);
  std::vector<std::vector<double>> scans(statics.size());
  for (std::size_t i = 0; i < statics.size(); ++i)
    for (std::size_t j : statics) scans[i].push_back(similarity[statics[i]][j]);
  std::vector<CandidatePair> pairs = initialPairs(scans, params.pairs);
  for (auto& p : pairs) p.a = statics[p.a], p.b = statics[p.b];
  if (stations.back().is_model)
    for (std::size_t i : statics) pairs.push_back({i, stations.size() - 1, 0.0, "model"});
  const auto mms = mmsPairs(stations, params.mms);
  pairs.insert(pairs.end(), mms.begin(), mms.end());
  return pairs;
}

/// The trajectory links of the MMS passes (mms_windows.hpp) `links` lacks, first.
void addTrajectoryLinks(const std::vector<Station>& stations, const NetworkParams& params, std::vector<Link>& links) {
  std::vector<Link> out;
  for (auto& t : trajectoryLinks(stations, params.mms))
    if (std::none_of(links.begin(), links.end(), [&](const Link& l) { return l.a == t.a && l.b == t.b; }))
      out.push_back(std::move(t));
  links.insert(links.begin(), out.begin(), out.end());
}

/// Pair rounds: the trajectory links, the initial pairs, then the next rounds (nextRound) until
/// none is left.
void registerLinks(const std::vector<Station>& stations, const NetworkParams& params, NetworkResult& out,
                   Progress* progress) {
  addTrajectoryLinks(stations, params, out.links);
  std::vector<CandidatePair> pairs = firstPairs(stations, nodeSimilarity(stations), params);
  while (!pairs.empty()) {
    ++out.rounds;
    registerPairs(stations, pairs, params, out, progress);
    pairs = nextRound(stations, out.links, params);
  }
}

}  // namespace

std::vector<std::size_t> copiesUnchecked(const std::vector<Station>& stations, const NetworkResult& r) {
  if (stations.empty() || !stations.back().is_model) return {};
  const std::size_t model = stations.size() - 1;
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < model; ++i) {
    if (!r.adjustment.poses[i]) continue;
    bool copies = false, checked = false;
    for (const auto& l : r.links)
      if (l.a == i && l.b == model) copies = l.status == "ambiguous" && !l.accepted;
    for (std::size_t k = 0; k < r.adjusted.size(); ++k) {
      const Link& l = r.links[r.adjusted[k]];
      const LinkOutcome& o = r.adjustment.links[k];
      if ((l.a == i || l.b == i) && !o.dropped && !o.bridge) checked = true;
    }
    if (copies && !checked) out.push_back(i);
  }
  return out;
}

namespace {

/// `settled` (sorted) taken off the three ambiguous lists.
void settle(NetworkResult& out, const std::vector<std::size_t>& settled) {
  for (auto* list : {&out.competing.ambiguous, &out.copies_unchecked, &out.one_loop}) {
    std::vector<std::size_t> kept;
    std::set_difference(list->begin(), list->end(), settled.begin(), settled.end(), std::back_inserter(kept));
    *list = std::move(kept);
  }
}

/// Stations the control points confirm (Georeference::settled) are not ambiguous: their own
/// resection decides between the placements the links offered.
void settleByControl(NetworkResult& out) {
  if (out.georeference && out.georeference->done) settle(out, out.georeference->settled);
}

/// The placements the ambiguous and unchecked stations could have instead of the adopted ones:
/// each dropped link taken as true (competing_placements.hpp), each copy the BIM offered a
/// station whose registration onto it was ambiguous or is its unchecked link, and each placement
/// an unchecked station's ambiguous links offer (uncheckedLinkHypotheses).
std::vector<PlacementHypothesis> ambiguityHypotheses(const std::vector<Station>& stations,
                                                     const std::vector<AdjustmentLink>& links,
                                                     const PoseGraphParams& graph, const NetworkResult& out) {
  std::vector<PlacementHypothesis> h;
  for (const auto& c : out.competing.alternatives)
    if (!c.stations.empty())
      h.push_back({"the link " + stations[links[c.link].a].name + " - " + stations[links[c.link].b].name +
                       " taken as true",
                   c.poses, c.stations, out.adjusted[c.link], std::nullopt});
  const auto unchecked_links = uncheckedLinkHypotheses(stations, out, out.unchecked, graph);
  h.insert(h.end(), unchecked_links.begin(), unchecked_links.end());
  const auto& poses = out.adjustment.poses;
  if (!stations.back().is_model || !poses.back()) return h;
  const std::size_t model = stations.size() - 1;
  for (const Link& l : out.links) {
    if (l.b != model || !poses[l.a]) continue;
    if (l.accepted && !std::binary_search(out.unchecked.begin(), out.unchecked.end(), l.a)) continue;
    for (std::size_t k = 0; k < l.model_candidates.size(); ++k) {
      const RigidTransform pose = *poses[model] * l.model_candidates[k];
      if (samePlacement(pose, *poses[l.a], graph)) continue;
      PlacementHypothesis copy{"the BIM's placement " + std::to_string(k + 1) + " of " + stations[l.a].name, poses,
                               {l.a}, std::nullopt, k};
      copy.poses[l.a] = pose;
      h.push_back(std::move(copy));
    }
  }
  return h;
}

/// Stations whose placement evidence from outside the links confirms: the reference station, a
/// kept link to the BIM that is not its only, unchecked link (out.unchecked), three control
/// points seen (Georeference::settled), or the judge's observers of the previous adjustment
/// still placed alike (`still_observing`); sorted.
std::vector<std::size_t> confirmedStations(const std::vector<AdjustmentLink>& links, const NetworkResult& out,
                                           const std::vector<std::size_t>& still_observing) {
  std::vector<std::size_t> confirmed{out.reference};
  for (std::size_t k = 0; k < links.size(); ++k)
    if (links[k].anchor && !out.adjustment.links[k].dropped) confirmed.push_back(std::min(links[k].a, links[k].b));
  std::sort(confirmed.begin(), confirmed.end());
  if (out.georeference && out.georeference->done) sortedUnion(confirmed, out.georeference->settled);
  confirmed.erase(std::unique(confirmed.begin(), confirmed.end()), confirmed.end());
  std::vector<std::size_t> out_confirmed;
  std::set_difference(confirmed.begin(), confirmed.end(), out.unchecked.begin(), out.unchecked.end(),
                      std::back_inserter(out_confirmed));
  sortedUnion(out_confirmed, still_observing);
  return out_confirmed;
}

/// Stations at their poses in an adjustment: the free-space judge's observers of the adjustment
/// before the current one (after it took a placement as true, or refined on points).
using PlacedObservers = std::vector<std::pair<std::size_t, RigidTransform>>;

/// The stations of `before` the adjustment of `out` still places alike: they observe again;
/// sorted.
std::vector<std::size_t> stillObserving(const NetworkResult& out, const PlacedObservers& before,
                                        const PoseGraphParams& graph) {
  std::vector<std::size_t> kept;
  for (const auto& [i, pose] : before)
    if (const auto& now = out.adjustment.poses[i]; now && samePlacement(*now, pose, graph)) kept.push_back(i);
  std::sort(kept.begin(), kept.end());
  return kept;
}

/// The judge's observers of `out` at their poses: what the next adjustment starts from.
PlacedObservers observersOf(const NetworkResult& out) {
  PlacedObservers o;
  for (const std::size_t i : out.free_space.observers)
    if (out.adjustment.poses[i]) o.emplace_back(i, *out.adjustment.poses[i]);
  return o;
}

/// Ambiguous and unchecked stations the free space of the confirmed ones settles or places
/// (free_space_judge.hpp); the unchecked ones whose placement it contests become ambiguous.
void settleByFreeSpace(const std::vector<Station>& stations, const std::vector<AdjustmentLink>& links,
                       const NetworkParams& params, const PlacedObservers& observed_before, NetworkResult& out) {
  const std::vector<std::size_t> before = stillObserving(out, observed_before, params.graph);
  out.unchecked.clear();
  if (params.free_space.enabled) {
    const auto unchecked = uncheckedStations(stations, out);
    std::set_difference(unchecked.begin(), unchecked.end(), before.begin(), before.end(),
                        std::back_inserter(out.unchecked));
  }
  std::vector<std::size_t> judged = out.ambiguous();
  sortedUnion(judged, out.unchecked);
  out.free_space = judgeByFreeSpace(stations, out.adjustment.poses, judged, confirmedStations(links, out, before),
                                    ambiguityHypotheses(stations, links, params.graph, out), params.free_space,
                                    params.graph, params.link.visibility);
  settle(out, out.free_space.settled);
  out.contested = contestedStations(out.free_space, out.unchecked, params.graph);
}

/// `out`'s accepted links adjusted, checked and judged; `observed_before`: the free-space judge's
/// observers of the previous adjustment, if any.
void adjust(const std::vector<Station>& stations, const NetworkParams& params, const ControlSurvey* control,
            NetworkResult& out, const LockedStations& locked = {}, const PlacedObservers& observed_before = {}) {
  std::vector<AdjustmentLink> links;
  std::vector<std::size_t> forced;  // the surveyor's accepted links, local indices
  for (std::size_t k = 0; k < out.links.size(); ++k) {
    const Link& l = out.links[k];
    if (!l.accepted) continue;
    if (l.decision == "accepted" || l.decision == kFreeSpaceDecision) forced.push_back(links.size());
    out.adjusted.push_back(k);
    links.push_back(adjustmentLink(l, stations));
  }
  const RigidTransform& reference_pose = stations[out.reference].file_pose;
  out.adjustment = adjustNetwork(stations.size(), links, out.reference, reference_pose, params.graph, forced, locked);
  for (const auto& [i, pose] : locked) out.locked.push_back(i);
  if (params.graph.check_competing)
    out.competing = findCompetingPlacements(stations.size(), links, out.reference, reference_pose, params.graph,
                                            out.adjustment);
  out.copies_unchecked = copiesUnchecked(stations, out);
  out.one_loop = decidedByOneLoop(stations.size(), links, out.adjustment, out.reference);
  if (control) {
    out.georeference = georeferenceNetwork(*control, stationNames(stations), links, params.graph, out.adjustment);
    placePartsByOwnControl(stations, links, params, *control, out);
    settleByControl(out);
  }
  settleByFreeSpace(stations, links, params, observed_before, out);
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (!out.adjustment.poses[i]) out.unplaced.push_back(i);
  std::vector<GraphEdge> kept;
  for (std::size_t k = 0; k < links.size(); ++k)
    if (!out.adjustment.links[k].dropped) kept.push_back({links[k].a, links[k].b, links[k].transform});
  const auto component = connectedComponents(stations.size(), kept);
  out.parts.assign(*std::max_element(component.begin(), component.end()) + 1, {});
  for (std::size_t i = 0; i < stations.size(); ++i) out.parts[component[i]].push_back(i);
}

/// `links` with what the free-space judge chose taken as true (decision kFreeSpaceDecision,
/// forced like the surveyor's accepted links): a dropped link, an ambiguous link at the
/// placement chosen, or a station's link to the BIM at the copy chosen.
void takeFreeSpaceChoices(const FreeSpaceJudgement& judged, std::size_t model, std::vector<Link>& links) {
  for (const auto& [station, h] : judged.chosen) {
    if (h.link) {
      Link& l = links[*h.link];
      l.decision = kFreeSpaceDecision;
      l.accepted = l.registered = true;
      if (h.link_transform) l.transform = *h.link_transform;
      continue;
    }
    for (Link& l : links) {
      if (l.a != station || l.b != model || !h.bim_candidate) continue;
      l.transform = l.model_candidates.at(*h.bim_candidate).inverse();
      l.registered = l.accepted = true;
      l.decision = kFreeSpaceDecision;
    }
  }
}

/// A result with what the registration of `r` measured (reference, pairs, rounds, times) and
/// no links or adjustment yet: what an adjustment of other links starts from.
NetworkResult registrationFacts(const NetworkResult& r) {
  NetworkResult out;
  out.reference = r.reference;
  out.all_pairs = r.all_pairs;
  out.rounds = r.rounds;
  out.seconds_features = r.seconds_features;
  out.seconds_links = r.seconds_links;
  return out;
}

/// The final refinement on points (final_refinement.hpp), when enabled: `out` adjusted again
/// with every overlapping pair refined at its poses.
void refineOnPoints(const std::vector<Station>& stations, const NetworkParams& params, const ControlSurvey* control,
                    NetworkResult& out, const LockedStations& locked) {
  if (!params.final_refinement.enabled) return;
  FinalRefinementSummary summary;
  const auto refined = refinedPairLinks(stations, out.adjustment.poses, out.ambiguous(), out.links, params, summary);
  if (!refined.empty()) {
    NetworkResult again = registrationFacts(out);
    again.links = withRefinedPairs(out.links, refined);
    adjust(stations, params, control, again, locked, observersOf(out));
    out = std::move(again);
  }
  out.final_refinement = summary;
}

/// out.links adjusted with the surveyor's locks, then refined on points when enabled; timed.
void adjustAndRefine(const std::vector<Station>& stations, const NetworkParams& params, const ControlSurvey* control,
                     NetworkResult& out, const LockedStations& locked) {
  const auto t0 = std::chrono::steady_clock::now();
  adjust(stations, params, control, out, locked);
  for (int round = 0; round < params.free_space.max_rounds && !out.free_space.chosen.empty(); ++round) {
    NetworkResult again = registrationFacts(out);
    again.links = out.links;
    takeFreeSpaceChoices(out.free_space, stations.size() - 1, again.links);
    adjust(stations, params, control, again, locked, observersOf(out));
    out = std::move(again);
  }
  refineOnPoints(stations, params, control, out, locked);
  out.seconds_adjustment = secondsSince(t0);
}

}  // namespace

bool NetworkResult::isAmbiguous(std::size_t i) const {
  return std::binary_search(competing.ambiguous.begin(), competing.ambiguous.end(), i) ||
         std::binary_search(copies_unchecked.begin(), copies_unchecked.end(), i) ||
         std::binary_search(one_loop.begin(), one_loop.end(), i) ||
         std::binary_search(contested.begin(), contested.end(), i);
}

std::vector<std::size_t> NetworkResult::ambiguous() const {
  std::vector<std::size_t> out = competing.ambiguous;
  sortedUnion(out, copies_unchecked);
  sortedUnion(out, one_loop);
  sortedUnion(out, contested);
  return out;
}

bool NetworkResult::placed(std::size_t i) const { return adjustment.poses.at(i).has_value() && !isAmbiguous(i); }

std::size_t findStation(const std::vector<Station>& stations, const std::string& name) {
  std::string names;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    if (stations[i].name == name) return i;
    names += (i ? ", " : "") + stations[i].name;
  }
  throw InputError("no station is named '" + name + "'; the stations are: " + names);
}

namespace {

/// Throws InputError for invalid parameters, fewer than two stations, a bad reference or a
/// model that is not the last node.
void checkNetwork(const std::vector<Station>& stations, std::size_t reference, const NetworkParams& params) {
  validateNetworkParams(params);
  if (stations.size() < 2) throw InputError("a network needs at least two stations, got " + std::to_string(stations.size()));
  if (reference >= stations.size()) throw InputError("the reference station index is out of range");
  for (std::size_t i = 0; i + 1 < stations.size(); ++i)
    if (stations[i].is_model) throw InputError("the model must be the last node of a network, and only one");
  if (stations.back().is_model && reference != stations.size() - 1)
    throw InputError("with a model, the model is the reference: its frame is the output frame");
}

}  // namespace

std::vector<CandidatePair> plannedPairs(const std::vector<Station>& stations, const NetworkParams& params) {
  checkNetwork(stations, stations.back().is_model ? stations.size() - 1 : 0, params);
  return firstPairs(stations, nodeSimilarity(stations), params);
}

bool acceptedLinksSplit(std::size_t stations, const std::vector<Link>& links) {
  const auto component = connectedComponents(stations, acceptedEdges(links));
  return *std::max_element(component.begin(), component.end()) > 0;
}

std::vector<CandidatePair> nextRound(const std::vector<Station>& stations, const std::vector<Link>& links,
                                     const NetworkParams& params) {
  std::set<std::pair<std::size_t, std::size_t>> tried;
  for (const auto& l : links) tried.insert({std::min(l.a, l.b), std::max(l.a, l.b)});
  std::vector<CandidatePair> pairs;
  if (acceptedLinksSplit(stations.size(), links))
    pairs = expansionPairs(nodeSimilarity(stations), connectedComponents(stations.size(), acceptedEdges(links)),
                           tried, params.pairs);
  if (params.pairs.footprint_per_station <= 0) return pairs;
  const auto footprint = footprintPairs(stations, placeParts(stations, links, params.graph), tried, params.pairs);
  pairs.insert(pairs.end(), footprint.begin(), footprint.end());
  return pairs;
}

void applyDecisions(std::vector<Link>& links, const NetworkDecisions& d, const std::vector<Station>& stations) {
  const auto linkOf = [&](std::pair<std::size_t, std::size_t> p) -> Link& {
    for (auto& l : links)
      if ((l.a == p.first && l.b == p.second) || (l.a == p.second && l.b == p.first)) return l;
    throw InputError("network: no link joins " + stations.at(p.first).name + " and " + stations.at(p.second).name +
                     " (only registered pairs can be accepted or rejected)");
  };
  for (const auto& p : d.rejected) {
    Link& l = linkOf(p);
    l.decision = "rejected";
    l.accepted = false;
  }
  for (const auto& p : d.accepted) {
    Link& l = linkOf(p);
    const std::string pair = stations[p.first].name + " - " + stations[p.second].name;
    if (l.decision == "rejected") throw InputError("network: the link " + pair + " is both accepted and rejected");
    if (!l.registered) throw InputError("network: the link " + pair + " failed (" + l.status + "): there is no transform to accept");
    l.decision = "accepted";
    l.accepted = true;
  }
}

NetworkResult adjustRegisteredLinks(const std::vector<Station>& stations, std::vector<Link> links,
                                    std::size_t reference, const NetworkParams& params, const ControlSurvey* control,
                                    const NetworkDecisions& decisions) {
  checkNetwork(stations, reference, params);
  addTrajectoryLinks(stations, params, links);
  applyDecisions(links, decisions, stations);
  NetworkResult out;
  out.reference = reference;
  out.all_pairs = stations.size() * (stations.size() - 1) / 2;
  out.links = std::move(links);
  out.rounds = 1;
  for (const auto& l : out.links) out.seconds_links += l.seconds;
  adjustAndRefine(stations, params, control, out, decisions.locked);
  return out;
}

NetworkResult readjustNetwork(const std::vector<Station>& stations, const NetworkResult& registered,
                              const NetworkParams& params, const ControlSurvey* control,
                              const NetworkDecisions& decisions) {
  checkNetwork(stations, registered.reference, params);
  NetworkResult out = registrationFacts(registered);
  out.links = registered.links;
  applyDecisions(out.links, decisions, stations);
  adjustAndRefine(stations, params, control, out, decisions.locked);
  return out;
}

NetworkResult registerNetwork(const std::vector<Station>& stations, std::size_t reference,
                              const NetworkParams& params, Progress* progress, const ControlSurvey* control) {
  checkNetwork(stations, reference, params);
  NetworkResult out;
  out.reference = reference;
  out.all_pairs = stations.size() * (stations.size() - 1) / 2;
  for (const auto& s : stations) out.seconds_features += s.seconds_features;
  const auto t0 = std::chrono::steady_clock::now();
  if (control) checkObservations(*control, stationNames(stations));  // before minutes of link registration
  registerLinks(stations, params, out, progress);
  out.seconds_links = secondsSince(t0);
  adjustAndRefine(stations, params, control, out, {});
  return out;
}

}  // namespace plumb
