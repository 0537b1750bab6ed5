#include "registration/network/network_registration.hpp"

#include <chrono>
#include <set>

#include "common/error.hpp"

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

/// Registers `pairs`, appending to `out` and `tried`.
void registerPairs(const std::vector<Station>& stations, const std::vector<CandidatePair>& pairs,
                   const NetworkParams& params, NetworkResult& out,
                   std::set<std::pair<std::size_t, std::size_t>>& tried, Progress* progress) {
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (progress) {
      progress->check();
      progress->report(double(k) / double(pairs.size()),
                       "link " + stations[pairs[k].a].name + " - " + stations[pairs[k].b].name);
    }
    tried.insert({pairs[k].a, pairs[k].b});
    out.links.push_back(registerLink(stations[pairs[k].a], stations[pairs[k].b], pairs[k], params));
  }
}

/// Pair rounds: the initial pairs, then expansions while the accepted links leave parts apart.
void registerLinks(const std::vector<Station>& stations, const NetworkParams& params, NetworkResult& out,
                   Progress* progress) {
  std::vector<LayoutDescriptor> layouts;
  for (const auto& s : stations) layouts.push_back(s.layout);
  const auto similarity = similarityMatrix(layouts);
  std::set<std::pair<std::size_t, std::size_t>> tried;
  std::vector<CandidatePair> pairs = initialPairs(similarity, params.pairs);
  while (!pairs.empty()) {
    ++out.rounds;
    registerPairs(stations, pairs, params, out, tried, progress);
    const auto component = connectedComponents(stations.size(), acceptedEdges(out.links));
    if (*std::max_element(component.begin(), component.end()) == 0) break;
    pairs = expansionPairs(similarity, component, tried, params.pairs);
  }
}

void adjust(const std::vector<Station>& stations, const NetworkParams& params, NetworkResult& out) {
  std::vector<AdjustmentLink> links;
  for (std::size_t k = 0; k < out.links.size(); ++k) {
    const Link& l = out.links[k];
    if (!l.accepted) continue;
    out.adjusted.push_back(k);
    links.push_back({l.a, l.b, l.transform, l.sigma_translation, l.sigma_rotation_deg, l.reason == "sequence"});
  }
  out.adjustment = adjustNetwork(stations.size(), links, out.reference, stations[out.reference].file_pose, params.graph);
  for (std::size_t i = 0; i < stations.size(); ++i)
    if (!out.adjustment.poses[i]) out.unplaced.push_back(i);
  std::vector<GraphEdge> kept;
  for (std::size_t k = 0; k < links.size(); ++k)
    if (!out.adjustment.links[k].dropped) kept.push_back({links[k].a, links[k].b, links[k].transform});
  const auto component = connectedComponents(stations.size(), kept);
  out.parts.assign(*std::max_element(component.begin(), component.end()) + 1, {});
  for (std::size_t i = 0; i < stations.size(); ++i) out.parts[component[i]].push_back(i);
}

}  // namespace

std::size_t findStation(const std::vector<Station>& stations, const std::string& name) {
  std::string names;
  for (std::size_t i = 0; i < stations.size(); ++i) {
    if (stations[i].name == name) return i;
    names += (i ? ", " : "") + stations[i].name;
  }
  throw InputError("no station is named '" + name + "'; the stations are: " + names);
}

NetworkResult registerNetwork(const std::vector<Station>& stations, std::size_t reference,
                              const NetworkParams& params, Progress* progress) {
  validateNetworkParams(params);
  if (stations.size() < 2) throw InputError("a network needs at least two stations, got " + std::to_string(stations.size()));
  if (reference >= stations.size()) throw InputError("the reference station index is out of range");
  NetworkResult out;
  out.reference = reference;
  out.all_pairs = stations.size() * (stations.size() - 1) / 2;
  for (const auto& s : stations) out.seconds_features += s.seconds_features;
  auto t0 = std::chrono::steady_clock::now();
  registerLinks(stations, params, out, progress);
  out.seconds_links = secondsSince(t0);
  t0 = std::chrono::steady_clock::now();
  adjust(stations, params, out);
  out.seconds_adjustment = secondsSince(t0);
  return out;
}

}  // namespace plumb
