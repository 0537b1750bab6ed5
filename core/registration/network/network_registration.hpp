#pragma once
// Registers the stations of a campaign as one network (docs/NETWORK.md): candidate pairs
// (pair_selection.hpp), each registered with the pipeline (link.hpp), more pairs while the
// accepted links leave the network split, then the robust adjustment (robust_adjustment.hpp)
// with the reference station fixed at its pose in its file. Stations the links cannot join to
// the reference are reported as not placed, never forced.
#include <optional>
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "registration/network/competing_placements.hpp"
#include "registration/network/final_refinement.hpp"
#include "registration/network/free_space_judge.hpp"
#include "registration/network/georeference.hpp"
#include "registration/network/link.hpp"
#include "registration/network/one_loop_drops.hpp"
#include "registration/network/robust_adjustment.hpp"
#include "registration/network/station.hpp"

namespace plumb {

/// The surveyor's decisions on a registered network (the project view's accept, reject and
/// lock; `network --accept/--reject/--lock`, docs/NETWORK.md "Decisions"): applied to the
/// links, then the network is adjusted again.
struct NetworkDecisions {
  /// Station pairs whose registered link is taken as true whatever its verdict: first in the
  /// initial tree, never dropped (the surveyor checked it visually).
  std::vector<std::pair<std::size_t, std::size_t>> accepted;
  /// Station pairs whose link is left out of the adjustment.
  std::vector<std::pair<std::size_t, std::size_t>> rejected;
  /// Stations held at these poses (station -> registered frame) once the links place them.
  LockedStations locked;
  bool empty() const { return accepted.empty() && rejected.empty() && locked.empty(); }
};

/// Applies the accepted and rejected pairs to `links` (Link::decision, Link::accepted). Throws
/// InputError naming the stations for a pair no link joins, a pair both accepted and rejected,
/// or an accepted link the pipeline gave no transform.
void applyDecisions(std::vector<Link>& links, const NetworkDecisions& decisions,
                    const std::vector<Station>& stations);

struct NetworkResult {
  std::vector<Link> links;             ///< every pair registered, in the order tried
  std::vector<std::size_t> adjusted;   ///< indices into links of the accepted ones
  NetworkAdjustment adjustment;        ///< adjustment.links[k] is links[adjusted[k]]
  std::size_t reference = 0;
  std::size_t all_pairs = 0;           ///< N (N - 1) / 2
  int rounds = 0;                      ///< pair-selection rounds (1 + expansions)
  double seconds_features = 0.0, seconds_links = 0.0, seconds_adjustment = 0.0;
  std::vector<std::size_t> unplaced;   ///< stations not joined to the reference
  std::vector<std::vector<std::size_t>> parts;  ///< the accepted links' connected parts
  /// Alternatives with each dropped link taken as true; its `ambiguous` stations have two
  /// loop-checked placements (competing_placements.hpp).
  CompetingPlacements competing;
  /// Stations the BIM places in several copies (their registration onto it was ambiguous)
  /// that only links no loop checks (bridges) place: one unchecked link chose the copy.
  std::vector<std::size_t> copies_unchecked;
  /// Stations placed through a bridge that a dropped link contradicted in a single loop: which
  /// link of that loop was wrong, nothing tells (one_loop_drops.hpp).
  std::vector<std::size_t> one_loop;
  /// With control points: the network moved into the survey's grid, and each control and check
  /// point's residual (georeference.hpp).
  std::optional<Georeference> georeference;
  /// With control points: stations no kept link joins to the reference, placed in the grid by
  /// the control points their own part of the network sees (docs/NETWORK.md "Parts placed by
  /// their own control"), sorted.
  std::vector<std::size_t> placed_by_own_control;
  /// Stations the surveyor locked (NetworkDecisions::locked), sorted.
  std::vector<std::size_t> locked;
  /// The final refinement on points (final-refinement.enabled): its refined pairs are links
  /// (reason "final refinement") of the last adjustment.
  FinalRefinementSummary final_refinement;
  /// The free space of the placed stations judging the ambiguous ones (free_space_judge.hpp):
  /// its settled stations are no longer in the three ambiguous lists.
  FreeSpaceJudgement free_space;
  /// Stations one link nothing checks places (a bridge), judged by the free space with the
  /// ambiguous ones (unchecked_stations.hpp), sorted; and those of them whose placement the free
  /// space contests: ambiguous, not placed.
  std::vector<std::size_t> unchecked, contested;
  /// In competing.ambiguous, copies_unchecked, one_loop or contested: adjusted, but not placed.
  bool isAmbiguous(std::size_t i) const;
  /// The ambiguous stations, sorted (the union of the four lists).
  std::vector<std::size_t> ambiguous() const;
  bool placed(std::size_t i) const;  ///< adjusted and not ambiguous
  /// Every station placed, none ambiguous, and georeferenced when control points were given.
  bool complete() const {
    return unplaced.empty() && competing.ambiguous.empty() && copies_unchecked.empty() && one_loop.empty() &&
           contested.empty() && (!georeference || georeference->done);
  }
};

/// Placed stations whose registration onto the BIM (the last station, when it is a model)
/// failed as ambiguous and whose kept links are all bridges (NetworkResult::copies_unchecked).
std::vector<std::size_t> copiesUnchecked(const std::vector<Station>& stations, const NetworkResult& result);

/// Index of the station named `name`; throws InputError listing the names when none is.
std::size_t findStation(const std::vector<Station>& stations, const std::string& name);

/// `stations` carry their features (detectStationFeatures). With `control`, the adjusted network
/// is then georeferenced on its control points (georeferenceNetwork). Throws InputError for
/// invalid parameters or fewer than two stations, FileError for a target observation naming an
/// unknown station or point.
NetworkResult registerNetwork(const std::vector<Station>& stations, std::size_t reference,
                              const NetworkParams& params, Progress* progress = nullptr,
                              const ControlSurvey* control = nullptr);

/// The first round of candidate pairs registerNetwork would register (layout neighbours,
/// sequence neighbours, every scan station with the model): the link jobs of `network --plan`.
/// `stations` carry their features. Throws InputError as registerNetwork.
std::vector<CandidatePair> plannedPairs(const std::vector<Station>& stations, const NetworkParams& params);

/// The accepted `links` leave the network of `stations` nodes in several parts.
bool acceptedLinksSplit(std::size_t stations, const std::vector<Link>& links);

/// The next round of pairs after `links` (docs/NETWORK.md "Candidate pairs"), as registerNetwork
/// registers them: while the accepted links leave the network split, pairs between its parts
/// (expansionPairs, not yet tried, most similar first; `stations` then need their features), and
/// the untried pairs of placed stations whose footprints overlap within each part
/// (footprintPairs). Empty when neither is left.
std::vector<CandidatePair> nextRound(const std::vector<Station>& stations, const std::vector<Link>& links,
                                     const NetworkParams& params);

/// The adjustment of links registered elsewhere (`network --links-from`, linkFromReport), as
/// registerNetwork adjusts its own; no pair is added while the network is split (the parts are
/// reported). Stations need no features. `decisions` are applied first (applyDecisions); the
/// same call re-runs the adjustment of a registered network with the surveyor's decisions.
NetworkResult adjustRegisteredLinks(const std::vector<Station>& stations, std::vector<Link> links,
                                    std::size_t reference, const NetworkParams& params,
                                    const ControlSurvey* control = nullptr, const NetworkDecisions& decisions = {});

/// The network `registered` (registerNetwork or adjustRegisteredLinks) adjusted again on its
/// links as first registered, with the surveyor's `decisions`: what the project view's re-run
/// and `network --accept/--reject/--lock` do. Rounds and the feature and link times are those
/// of the registration. Throws InputError as applyDecisions.
NetworkResult readjustNetwork(const std::vector<Station>& stations, const NetworkResult& registered,
                              const NetworkParams& params, const ControlSurvey* control,
                              const NetworkDecisions& decisions);

}  // namespace plumb
