#pragma once
// Beyond the papers: the global step's runner-up is refined like the winner before the two are
// compared (issue 13). An unrefined runner-up always looks worse than a refined winner, and a
// runner-up that converges onto the winner is the same answer, not a competitor. After both
// refinements:
//   - same placement (within same_rotation_deg / same_translation at the source centroid):
//     one answer, no warning;
//   - one clearly worse refined fit (fewer points explained, or a clearly higher fit cost):
//     the other stands, without a warning;
//   - otherwise two different placements fit about equally (a repeated room, mirrored units,
//     identical storeys): ambiguous, both listed as candidates.
// When the global step itself was ambiguous (features could not choose), a runner-up with a
// clearly better fit wins; when the global step chose, a runner-up fitting clearly better on
// points contradicts it and the answer is ambiguous too (never a confident pick against the
// features).
#include <Eigen/Core>

#include <string>
#include <vector>

#include "common/params.hpp"
#include "quality/placement_candidate.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/refine/icp_refinement.hpp"

namespace plumb {

struct CandidateParams {
  /// Refine the global step's runner-up with the same refinement parameters and compare the
  /// refined fits (needs refinement on). Off: an ambiguous global step fails.
  bool refine_runner_up = true;
  /// Two refined placements are the same when they differ by at most this rotation, deg,
  /// [0.01, 5] ...
  double same_rotation_deg = 0.2;
  /// ... and this displacement at the source data's centroid, m, [0.001, 1].
  double same_translation = 0.05;
  /// A placement is clearly worse when its refined overlap ratio is lower by at least this,
  /// [0, 1] (that fraction of the source points fits one placement and not the other); or:
  double min_overlap_gap = 0.008;
  /// its overlap is lower by at least this, [0, 1], ...
  double near_overlap_gap = 0.005;
  /// ... and it leaves at least this many times more source points unexplained (1 - overlap),
  /// [1, 100] (data overlapping almost wholly: a room in its model, a scan onto itself); or:
  double min_unexplained_ratio = 2.0;
  /// Near-whole fits: when the better placement explains at least this fraction of the
  /// source, [0, 1], the overlap gap alone (min_overlap_gap) counts only if the structure
  /// agrees (structure_overlap.hpp): the worse placement explains at least min_structure_gap
  /// less of the source's large-plane points (planes of at least the free-space check's
  /// VisibilityParams::structure_min_area), [0, 1], ...
  double near_whole_overlap = 0.8;
  double min_structure_gap = 0.0015;
  /// ... and leaves at least this many times more of them unexplained, [1, 100]. Measured
  /// (docs/VERDICT.md "Near-whole fits judged on structure"): furniture-only differences
  /// between copies of a room give 0.0009 and 1.01 times; a half turn or a storey copy of a
  /// house room, 0.0035-0.012 and 1.26-1.6 times on samples; refined on the model's triangles,
  /// the demo's four house stations against the half turn a storey up, 0.0019 and 1.15 times
  /// (the gap was 0.002 until then).
  double min_structure_ratio = 1.12;
  /// its refined fit cost (RefineResult::fit_cost) is higher by at least this, [0, 1], ...
  double min_cost_gap = 0.02;
  /// ... and at least this many times the other's, [1, 100].
  double min_cost_ratio = 1.5;
  /// A placement overrules the features' choice when, refined, it leaves at most 1 / this of
  /// the points the chosen one leaves unexplained, [1, 1000] ...
  double decisive_unexplained_ratio = 5.0;
  /// ... and its fit cost is at most 1 / this of the chosen one's, [1, 1000]: a room symmetric
  /// but for its door and window, turned onto itself by the plane matching, explains 93 % of
  /// the scan where the truth explains 99.9 % (fit cost 6 times lower); copies of a repeated
  /// room differ by their furniture only (docs/VERDICT.md "Decisive fits").
  double decisive_cost_ratio = 3.0;
  /// Beyond the runner-up, refine up to this many further distinct hypotheses, [0, 4] ...
  int max_alternatives = 2;
  /// ... whose feature score is at least this fraction of the best's, [0, 1]; the best
  /// placement elsewhere (below) too. Lower-scoring hypotheses lost on the features: a
  /// building's half turn matches fewer of its openings, however well its walls fit.
  double alternative_min_score = 0.9;
  /// Search again away from the chosen placement (elsewhere_search.hpp) when the target's
  /// features span at least this many times the source's volume, [1, 1000] ...
  double elsewhere_volume_ratio = 2.0;
  /// ... setting aside the target features within this distance of the placed source's box,
  /// m, [0, 5].
  double elsewhere_margin = 0.3;
  /// ... and examining this many times the translation peaks per rotation of the segments
  /// search, [1, 10]: the global search keeps the peaks with the most votes, and a copy whose
  /// model edges are split into short pieces (modelled differently from its twin) draws few.
  int elsewhere_peak_factor = 4;
  /// Search the target for copies of the placed source (copy_search.hpp: chamfer matching of
  /// the chosen placement turned by quarter turns and shifted by whole cells) and refine and
  /// compare each copy found, like the runner-up.
  bool copy_search = true;
  /// ... on a grid of this cell, m, [0.05, 2] (the shift step; the tolerance is one cell) ...
  double copy_cell = 0.25;
  /// ... counting as copies the shifts that explain at least this fraction of what the chosen
  /// placement explains, [0.5, 1] ...
  double copy_min_fraction = 0.9;
  /// ... at most this many, best first, [0, 8].
  int copy_max = 4;
  /// When the chosen placement is not the one the copies were searched around (the free space
  /// ruled that one out, or another fits better), search the chosen one's copies too, up to
  /// this many rounds, [0, 4]: the truth may be a copy of it and not of the first centre.
  int copy_rounds = 2;
  static const ParamSchema<CandidateParams>& schema();
};

/// A global hypothesis and its refinement.
struct RefinedHypothesis {
  Hypothesis hypothesis;
  RefineResult refined;
};

enum class CandidateRelation { Same, FirstClearlyBetter, SecondClearlyBetter, Close };
const char* toString(CandidateRelation r);

/// How the refined fit `b` relates to `a`; `centroid` is the source data's centre (source
/// frame), where the placements' displacements are compared.
CandidateRelation compareRefined(const RefineResult& a, const RefineResult& b,
                                 const Eigen::Vector3d& centroid, const CandidateParams& params);

struct CandidateSelection {
  std::size_t chosen = 0;   ///< index of the answer among the hypotheses
  bool ambiguous = false;   ///< two different placements fit about equally (or contradict)
  std::vector<PlacementCandidate> candidates;  ///< every hypothesis, the chosen first
  std::vector<std::size_t> hypothesis;  ///< index among the hypotheses of each candidate
  std::string message;      ///< plain language, for the log and the verdict
};

/// The role of a hypothesis that other evidence (the free space) ruled out.
extern const char* const kRuledOutRole;

/// Compares hypotheses[0] (the global step's answer, or its best when `global_chose` is false)
/// with every other refined hypothesis. `ruled_out[i]` marks hypotheses that other evidence
/// contradicts (the free space: a repeated room placed in the copy whose walls its rays cross):
/// they never make the answer ambiguous, and a ruled-out first hypothesis gives way to one
/// fitting about as well that is not ruled out.
CandidateSelection selectCandidate(const std::vector<RefinedHypothesis>& hypotheses,
                                   bool global_chose, const Eigen::Vector3d& centroid,
                                   const CandidateParams& params,
                                   const std::vector<bool>& ruled_out = {});

/// A candidate as the report lists it (refined figures when `refined` is non-null).
PlacementCandidate makeCandidate(const Hypothesis& h, const RefineResult* refined,
                                 std::string role);

}  // namespace plumb
