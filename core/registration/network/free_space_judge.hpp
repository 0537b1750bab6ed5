#pragma once
// The free space of the placed stations judges ambiguous stations (docs/NETWORK.md "The free
// space judges ambiguous stations").
//
// A station is ambiguous when the links offer two placements that each agree with some of them
// (competing_placements.hpp), when one loop cannot tell which of its links was wrong
// (one_loop_drops.hpp), or when the BIM fits it in several copies and only unchecked links
// chose (copiesUnchecked). The links cannot settle these: identical offices and a building
// symmetric under a half turn give wrong links that agree with each other. What the links do
// not use is what every station saw through. A scanner that measured a wall 4 m away saw that
// nothing stands in front of it; a station placed in the twin of its room puts its furniture
// where the stations of that room saw through, and the twin's furniture where it saw through.
//
// The judge tests each placement of an ambiguous station, the adopted one and every hypothesis
// that moves it (a dropped link taken as true, a copy the BIM offered, an unchecked station's
// ambiguous link at one of its placements), against the observers,
// in both directions. Observers are stations whose placement evidence from outside the links
// confirms (the reference station, a kept link to the BIM, three control points): stations
// placed only by links can be wrong together (office-floor without a BIM places its east half
// by the half turn, and its wrong stations agree with a wrong placement). The test is with the free-space
// test of a registration's verdict (visibility_evidence.hpp) on range images built once per
// station. Each observer is where the hypothesis puts it; one the hypothesis moves together
// with the judged station (their relative pose unchanged) says nothing about it and is left
// out. A placement is:
//  - judged when at least `min_visible` of the tested points are visible to the other side;
//  - clean when at most `clean_ratio` of them lie in the other side's free space;
//  - refuted by another placement when at least `refute_ratio` of its points, and at least
//    `decisive_factor` times that placement's share, lie in the free space.
// The station is decided when one placement is clean and refutes every other (all judged) that
// places it elsewhere (beyond the drop thresholds, samePlacement: a dropped link taken as true
// and a copy of the BIM often place it alike):
//  - the adopted one: the station is settled, no longer ambiguous;
//  - a copy the BIM offered: the station is to be placed there (its link to the BIM is taken
//    as true and the network adjusted again, network_registration.cpp).
// Settled stations become observers and the judge runs again, until none settles. A station
// whose placements the free space cannot tell apart stays ambiguous: not placed.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/rigid_transform.hpp"
#include "quality/visibility_evidence.hpp"
#include "registration/network/network_params.hpp"
#include "registration/network/station.hpp"

namespace plumb {

/// Tested points visible to the other side, and those of them in its free space.
struct FreeSpaceTally {
  std::size_t visible = 0;
  std::size_t contradicting = 0;
  double ratio() const { return visible ? double(contradicting) / double(visible) : 0.0; }
  void add(const FreeSpaceTally& t) {
    visible += t.visible;
    contradicting += t.contradicting;
  }
};

/// One way the links or the BIM could place an ambiguous station instead of the adopted one.
struct PlacementHypothesis {
  std::string source;  ///< "the link A - B taken as true" or "the BIM's placement N of A"
  std::vector<std::optional<RigidTransform>> poses;  ///< every station under the hypothesis
  std::vector<std::size_t> moved;  ///< stations it places differently from the adopted solution
  /// What the network takes as true to place the stations so: a dropped link (index into
  /// NetworkResult::links), or a copy the BIM offered for moved[0] alone (the index of that
  /// placement among its model link's candidates, Link::model_candidates).
  std::optional<std::size_t> link;
  std::optional<std::size_t> bim_candidate;
  /// The link's transform under the hypothesis (b's frame -> a's frame), when it is not the
  /// link's own: a competing placement of an ambiguous link (unchecked_stations.hpp).
  std::optional<RigidTransform> link_transform;
};

/// A placement of the judged station against the observers.
struct JudgedPlacement {
  std::string source;          ///< "adopted", or the hypothesis' source
  std::optional<std::size_t> hypothesis;  ///< index into the hypotheses; absent: the adopted placement
  RigidTransform pose;         ///< the station's pose under it
  FreeSpaceTally tally;
  bool judged = false;         ///< at least min_visible visible points
  bool clean = false;
};

struct StationJudgement {
  std::size_t station = 0;
  std::vector<JudgedPlacement> placements;  ///< the adopted one first, then every hypothesis moving it
  /// Index into placements of the clean one refuting every other; absent: undecided.
  std::optional<std::size_t> decided;
  bool settled = false;    ///< decided on the adopted placement
  int round = 0;           ///< judge round of this judgement (observers grow each round)
  std::string why;         ///< plain language: what the free space decided, or why nothing
};

struct FreeSpaceJudgement {
  bool ran = false;
  std::vector<StationJudgement> stations;  ///< one per ambiguous station, in station order
  std::vector<std::size_t> settled;        ///< sorted
  /// Stations the free space places elsewhere than adopted: the hypothesis to take as true.
  std::vector<std::pair<std::size_t, PlacementHypothesis>> chosen;
  /// The observers of the last round: the confirmed stations and the settled ones, sorted.
  std::vector<std::size_t> observers;
  double seconds = 0.0;
};

/// Judges the `ambiguous` stations (sorted; with the unchecked ones, unchecked_stations.hpp) of
/// the adopted `poses` against the `hypotheses`, observed by the `confirmed` stations (sorted;
/// the placed ones not judged are used). Two poses within `graph`'s drop thresholds are one
/// placement. The model node, if any, is neither judged nor an observer.
FreeSpaceJudgement judgeByFreeSpace(const std::vector<Station>& stations,
                                    const std::vector<std::optional<RigidTransform>>& poses,
                                    const std::vector<std::size_t>& ambiguous,
                                    const std::vector<std::size_t>& confirmed,
                                    const std::vector<PlacementHypothesis>& hypotheses,
                                    const FreeSpaceJudgeParams& params, const PoseGraphParams& graph,
                                    const VisibilityParams& visibility);

}  // namespace plumb
