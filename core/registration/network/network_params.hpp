#pragma once
// The parameters of a network registration (docs/NETWORK.md), each group with its schema so the
// CLI (--set GROUP.KEY=VALUE), JSON and UI come from one definition:
//   "pair-selection"  which station pairs are registered (pair_selection.hpp)
//   "link-weights"    how a link's quality figures become its weight in the adjustment
//   "pose-graph"      the robust global adjustment (pose_graph.hpp, robust_adjustment.hpp)
// and the registration pipeline's own groups for each link (pipeline_param_groups.hpp).
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "common/params.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

struct PairSelectionParams {
  /// Each station is paired with its this many most similar stations by layout descriptor
  /// (layout_descriptor.hpp), [0, 50].
  int nearest_layouts = 2;
  /// Each station is paired with the stations up to this many places after it in the input
  /// order (stations are usually shot in sequence), [0, 50].
  int sequence_neighbours = 1;
  /// While the accepted links leave the network split, at most this many further pairs per
  /// station are tried between the parts, most similar first, [0, 100].
  int expansion_per_station = 2;
  /// Once links place a part of the network, untried pairs of its stations whose footprints
  /// (plan cells holding their points) overlap by at least this share are registered too, so
  /// loops form inside the part (footprint_pairs.hpp), [0.01, 1].
  double footprint_overlap = 0.3;
  /// At most this many footprint pairs per station and round; 0: no footprint pairs, [0, 100].
  /// Off by default: on office-floor (symmetric under a half turn) they paired stations placed
  /// by the half turn with their twins, whose registration corroborates the wrong placement
  /// (docs/NETWORK.md "Candidate pairs").
  int footprint_per_station = 0;
  /// Plan cell of a footprint, m, [0.05, 10].
  double footprint_cell = 0.5;
  static const ParamSchema<PairSelectionParams>& schema();
};

struct LinkWeightParams {
  /// Floor of a link's translation standard deviation, m, [1e-5, 1]: no link is trusted to
  /// better than this (systematic errors of the refinement).
  double min_sigma = 0.0005;
  /// A link's translation sigma is the point RMS times this factor (before the strength
  /// factor), [0, 10].
  double rms_factor = 0.2;
  /// Slide resistance of the weakest direction (quality report) at and above which a link
  /// counts as fully held; weaker links get sigma / sqrt(resistance / this), [0.001, 1].
  double full_resistance = 0.2;
  /// Accept links whose verdict is check-visually (weighted as above); failed links are never
  /// accepted. Off: on l-shaped and office-floor every check-visually link measured was wrong
  /// (4 of 4), and one that is a bridge places stations wrongly with nothing to check it.
  bool accept_check_visually = false;
  static const ParamSchema<LinkWeightParams>& schema();
};

struct PoseGraphParams {
  /// Cauchy loss scale on each link's normalised residual (in standard deviations), [0.1, 100].
  double robust_scale = 3.0;
  /// A link is flagged (disagrees with the network) when its residual after the adjustment
  /// exceeds this translation, m, [1e-4, 10] ...
  double flag_translation = 0.005;
  /// ... or this rotation, deg, [1e-4, 10].
  double flag_rotation = 0.02;
  /// Flagged links whose residual exceeds this translation, m, [1e-4, 100] ...
  double drop_translation = 0.05;
  /// ... or this rotation, deg, [1e-4, 180], are dropped automatically (the worst one at a
  /// time, then the network is solved again).
  double drop_rotation = 0.2;
  bool auto_drop = true;
  /// Two links of a triangle of stations agree with the third when the triangle closes within
  /// this translation, m, [1e-4, 10] (and drop-rotation): used to order the links of the first
  /// spanning tree, which initialises the adjustment.
  double triangle_tolerance = 0.05;
  /// Solver iterations, [1, 10000].
  int max_iterations = 200;
  /// After the adjustment, re-solve the network once per dropped link with that link taken as
  /// true (competing_placements.hpp): stations a loop-checked alternative places differently
  /// (beyond the drop thresholds) are ambiguous, reported and not placed.
  bool check_competing = true;
  static const ParamSchema<PoseGraphParams>& schema();
};

struct FinalRefinementParams {
  /// After the adjustment, refine every pair of placed scan stations whose points overlap at
  /// their adjusted poses (registered as a link or not) on their points, then adjust once more
  /// with those refined pairs beside the links (final_refinement.hpp). Off by default.
  bool enabled = false;
  /// Largest correspondence distance of the first refinement stage, m, [0.005, 1]: the
  /// adjusted poses are already within millimetres.
  double start_distance = 0.05;
  /// Last-stage correspondence distance, m, [0.002, 0.5].
  double final_distance = 0.01;
  /// Fewest share of a station's points matched for a pair to count, [0.01, 1].
  double min_overlap = 0.1;
  static const ParamSchema<FinalRefinementParams>& schema();
};

/// The free-space judge of ambiguous stations (free_space_judge.hpp).
struct FreeSpaceJudgeParams {
  /// Judge ambiguous stations by the free space of the placed stations.
  bool enabled = true;
  /// A placement is clean when at most this share of its visible tested points lies in the
  /// other stations' free space, [0, 0.2]. Measured on office-floor with its BIM (docs/NETWORK.md):
  /// right placements 0.0000, wrong ones (a doorway station turned onto its twin across the
  /// corridor) 0.0096 to 0.0205; 0.004 is 2.4 times below the least wrong one. Real right pairs
  /// reach 0.010-0.016 (docs/VERDICT_SUITES.md): there the judge decides nothing, and the
  /// stations stay ambiguous.
  double clean_ratio = 0.004;
  /// Another placement is refuted when at least this share of its visible points contradicts
  /// the observers, [0, 1] ...
  double refute_ratio = 0.005;
  /// ... and at least this many times the clean placement's share, [1, 1000].
  double decisive_factor = 3.0;
  /// Fewer visible tested points than this: the placement is not judged, [1, 1e7].
  int min_visible = 2000;
  /// Points of each station tested against each other station (regular sample), [100, 1e6].
  int test_points = 8000;
  /// Stations whose placed boxes come within this distance are tested against each other, m,
  /// [0, 100].
  double box_margin = 0.5;
  /// Adjustments again after the judge placed stations elsewhere (a link or a BIM copy taken as
  /// true), at most, [0, 10].
  int max_rounds = 3;
  static const ParamSchema<FreeSpaceJudgeParams>& schema();
};

/// MMS passes as time-windowed nodes (mms_windows.hpp).
struct MmsWindowParams {
  /// Seconds of point time per window; 0: a pass is one rigid node (the default, and the
  /// desktop's only mode: it maps one station to one scan of a layer), [0, 3600].
  double window = 0.0;
  /// Stated accuracy of the trajectory between consecutive windows (1 sigma), m, [1e-4, 10] ...
  double sigma_translation = 0.02;
  /// ... and deg, [1e-4, 10].
  double sigma_rotation_deg = 0.02;
  /// Register every window with every static station (openings); off: with the BIM only.
  /// Off by default: on office-floor (docs/NETWORK.md "MMS passes") 58 such pairs took 550 s
  /// and none registered (a station sees one or two windows of a façade).
  bool station_pairs = false;
  static const ParamSchema<MmsWindowParams>& schema();
};

struct NetworkParams {
  PairSelectionParams pairs;
  LinkWeightParams weights;
  PoseGraphParams graph;
  FinalRefinementParams final_refinement;
  FreeSpaceJudgeParams free_space;  ///< free_space_judge.hpp
  MmsWindowParams mms;              ///< mms_windows.hpp
  PipelineParams link;  ///< the pipeline of each link
};

/// Calls f(key, label, schema, member) for the network's own groups.
template <class P, class F>
void forEachNetworkParamGroup(P& p, F&& f) {
  f("pair-selection", "Candidate pairs", PairSelectionParams::schema(), p.pairs);
  f("link-weights", "Link weights", LinkWeightParams::schema(), p.weights);
  f("pose-graph", "Global adjustment", PoseGraphParams::schema(), p.graph);
  f("final-refinement", "Final refinement on points", FinalRefinementParams::schema(), p.final_refinement);
  f("free-space-judge", "Free-space judge of ambiguous stations", FreeSpaceJudgeParams::schema(), p.free_space);
  f("mms", "MMS passes", MmsWindowParams::schema(), p.mms);
}

/// {"pair-selection": {...}, "link-weights": {...}, "pose-graph": {...}, "link": {pipeline}}.
nlohmann::json networkParamsToJson(const NetworkParams& p);
/// "GROUP.KEY" names a parameter of a network group (pair-selection, link-weights, pose-graph),
/// not of the link pipeline.
bool isNetworkParamPath(const std::string& path);
/// Sets "GROUP.KEY" of a network group, or of the link pipeline (any other path, as
/// setPipelineParam). Throws InputError naming the group or key.
void setNetworkParam(NetworkParams& p, const std::string& path, const std::string& text);
/// Range check of every group; throws InputError naming the group and parameter.
void validateNetworkParams(const NetworkParams& p);

}  // namespace plumb
