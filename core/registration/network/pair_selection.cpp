#include "registration/network/pair_selection.hpp"

#include <algorithm>
#include <map>

namespace plumb {

std::vector<std::vector<double>> similarityMatrix(const std::vector<LayoutDescriptor>& layouts) {
  const std::size_t n = layouts.size();
  std::vector<std::vector<double>> s(n, std::vector<double>(n, 1.0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) s[i][j] = s[j][i] = layoutSimilarity(layouts[i], layouts[j]);
  return s;
}

std::vector<CandidatePair> initialPairs(const std::vector<std::vector<double>>& similarity,
                                        const PairSelectionParams& params) {
  const std::size_t n = similarity.size();
  std::map<std::pair<std::size_t, std::size_t>, CandidatePair> pairs;
  auto add = [&](std::size_t i, std::size_t j, const char* reason) {
    const auto key = std::minmax(i, j);
    if (!pairs.count(key)) pairs[key] = {key.first, key.second, similarity[i][j], reason};
  };
  for (std::size_t i = 0; i < n; ++i)  // first: a pair both in sequence and alike is "sequence"
    for (std::size_t k = 1; k <= static_cast<std::size_t>(params.sequence_neighbours) && i + k < n; ++k)
      add(i, i + k, "sequence");
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::size_t> others;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) others.push_back(j);
    std::stable_sort(others.begin(), others.end(),
                     [&](std::size_t x, std::size_t y) { return similarity[i][x] > similarity[i][y]; });
    for (std::size_t k = 0; k < others.size() && k < static_cast<std::size_t>(params.nearest_layouts); ++k)
      add(i, others[k], "layout");
  }
  std::vector<CandidatePair> out;
  for (auto& [key, p] : pairs) out.push_back(p);
  return out;
}

std::vector<CandidatePair> expansionPairs(const std::vector<std::vector<double>>& similarity,
                                          const std::vector<std::size_t>& component,
                                          const std::set<std::pair<std::size_t, std::size_t>>& tried,
                                          const PairSelectionParams& params) {
  const std::size_t n = similarity.size();
  std::vector<CandidatePair> all;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (component[i] != component[j] && !tried.count({i, j})) all.push_back({i, j, similarity[i][j], "expansion"});
  return bestPerStation(std::move(all), params.expansion_per_station, n);
}

std::vector<CandidatePair> bestPerStation(std::vector<CandidatePair> all, int per_station, std::size_t stations) {
  std::stable_sort(all.begin(), all.end(),
                   [](const CandidatePair& x, const CandidatePair& y) { return x.similarity > y.similarity; });
  std::vector<int> used(stations, 0);
  std::vector<CandidatePair> out;
  for (const auto& p : all)
    if (used[p.a] < per_station && used[p.b] < per_station) {
      ++used[p.a], ++used[p.b];
      out.push_back(p);
    }
  return out;
}

}  // namespace plumb
