#pragma once
// Which station pairs are registered (docs/NETWORK.md "Candidate pairs"), never all N(N-1)/2:
//   - each station with its `nearest-layouts` most similar stations (layout_descriptor.hpp);
//   - each station with the `sequence-neighbours` stations after it in input order;
//   - while the accepted links leave the network split: further pairs between its parts, most
//     similar first, at most `expansion` per station and round (expansionPairs).
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "registration/network/layout_descriptor.hpp"
#include "registration/network/network_params.hpp"

namespace plumb {

struct CandidatePair {
  std::size_t a = 0, b = 0;  ///< a < b
  double similarity = 0.0;   ///< layoutSimilarity
  std::string reason;        ///< "layout", "sequence", "expansion"
};

/// similarity[i][j] of every station pair (symmetric, 1 on the diagonal).
std::vector<std::vector<double>> similarityMatrix(const std::vector<LayoutDescriptor>& layouts);

/// The first round: layout neighbours and sequence neighbours, each pair once (the reason of
/// its first selection), ordered by (a, b).
std::vector<CandidatePair> initialPairs(const std::vector<std::vector<double>>& similarity,
                                        const PairSelectionParams& params);

/// `all` ordered by similarity (largest first, ties in their given order), each kept while
/// neither of its stations has `per_station` kept pairs yet.
std::vector<CandidatePair> bestPerStation(std::vector<CandidatePair> all, int per_station, std::size_t stations);

/// Pairs joining two different parts (`component` per station) not in `tried`, most similar
/// first, at most params.expansion_per_station per station.
std::vector<CandidatePair> expansionPairs(const std::vector<std::vector<double>>& similarity,
                                          const std::vector<std::size_t>& component,
                                          const std::set<std::pair<std::size_t, std::size_t>>& tried,
                                          const PairSelectionParams& params);

}  // namespace plumb
