#pragma once
// The quality report of a registration (docs/ALGORITHMS.md §8): the transform, RMS on matched
// features and on points, overlap ratio, inlier feature counts, the runner-up hypothesis and
// the score gap, the weakly constrained degrees of freedom (eigen-analysis of the refinement's
// normal matrix) and a plain-language verdict a surveyor can act on.
#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "common/params.hpp"
#include "quality/visibility_evidence.hpp"
#include "quality/placement_candidate.hpp"
#include "quality/verdict_level.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/common/refine_result.hpp"

namespace plumb {

struct QualityParams {
  /// A direction is weakly constrained when its eigenvalue is below this fraction of the
  /// largest one, [1e-6, 0.5].
  double weak_ratio = 0.02;
  /// Minimum overlap ratio of the refinement (fraction of source points matched), [0, 1].
  double min_overlap = 0.05;
  /// Point RMS above this is flagged, metres, [0.001, 1].
  double max_point_rms = 0.03;
  /// A runner-up within this relative score gap is flagged (not failed), [0, 1], when it was
  /// not refined and compared on points (refinement off): a refined runner-up is judged on
  /// its refined fit instead (candidate_refinement.hpp).
  double warn_relative_gap = 0.2;
  /// A direction is unconstrained (the registration fails as degenerate) when a slide of
  /// RefineResult::kSlideDistance along it pushes fewer than this fraction of the matched
  /// points off their surface, [0, 0.5]. Measured: single plane, two parallel planes, corridor
  /// without openings, single line: <= 0.005 along their free directions; the demo's
  /// indoor/outdoor pair 0.10 about its weakest axis, the real room pair >= 0.25 (docs/VERDICT.md).
  double min_resistance = 0.02;
  /// A direction weak by eigenvalue is still reported as a warning only when its slide
  /// resistance is below this, [0, 1]: above it real geometry holds the direction.
  double warn_resistance = 0.05;
  static const ParamSchema<QualityParams>& schema();
};

struct WeakDirection {
  bool translation = true;   ///< translation along `axis`, or rotation about `axis`
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  double relative_eigenvalue = 0.0;  ///< eigenvalue / largest eigenvalue
  double resistance = 0.0;           ///< RefineResult::direction_resistance of this direction
  bool unconstrained = false;        ///< resistance below QualityParams::min_resistance
  std::string description;
};

struct QualityReport {
  bool success = false;  ///< results may be written (level usable or check visually)
  VerdictLevel level = VerdictLevel::Failed;
  std::string verdict;  ///< one paragraph, plain language
  std::string method;
  std::string status;   ///< RegistrationStatus as text, or "refinement failed"
  RigidTransform transform;         ///< final (refined when refinement ran)
  RigidTransform global_transform;  ///< from the global method
  double global_score = 0.0;
  std::string score_unit;
  bool has_runner_up = false;
  RigidTransform runner_up_transform;
  double runner_up_score = 0.0;
  double relative_gap = 1.0;
  std::size_t hypotheses = 0;
  std::size_t source_features = 0, target_features = 0, inlier_features = 0;
  double feature_rms = 0.0;  ///< m
  bool refined = false;
  double point_rms = 0.0;    ///< m
  double overlap_ratio = 0.0;
  std::size_t point_inliers = 0;
  double length_scale = 0.0;           ///< m, RMS radius of the matched points (RefineResult)
  double refinement_shift = 0.0;       ///< m, |t_refined - t_global|
  double refinement_rotation = 0.0;    ///< deg
  std::array<double, 6> eigenvalues{};  ///< of the scaled normal matrix, ascending
  std::array<double, 6> direction_resistance{};  ///< RefineResult::direction_resistance
  std::vector<WeakDirection> weak_directions;
  std::vector<std::pair<std::string, double>> figures;
  std::vector<std::string> warnings;
  /// Free-space evidence of the final transform (VerdictEvidence; the rule: visibility_verdict.hpp).
  VisibilitySummary visibility;
  /// Every placement considered, the answer first (refined figures when refinement ran).
  std::vector<PlacementCandidate> candidates;
};

/// Evidence measured under the final transform before the report is composed (the pipeline's
/// free-space check); the rules that read it run inside assessRegistration, so the verdict is
/// written once.
struct VerdictEvidence {
  VisibilitySummary visibility;
  VisibilityParams visibility_params;
};

/// Builds the report. `refine` may be null (refinement off). `candidates`: the placements
/// considered (PipelineResult::candidates); when the runner-up among them was refined, the
/// refined comparison replaces the score-gap warning. `evidence` may be null (not measured).
QualityReport assessRegistration(const GlobalRegistrationResult& global,
                                 const RefineResult* refine, const QualityParams& params = {},
                                 const std::vector<PlacementCandidate>& candidates = {},
                                 const VerdictEvidence* evidence = nullptr);

/// Weak and unconstrained directions of a refinement's normal matrix (rotation first, scaled
/// by a length): weak by eigenvalue ratio (and not held by a slide resistance of at least
/// warn_resistance), or unconstrained by slide resistance.
std::vector<WeakDirection> weakDirections(const RefineResult& refine, const QualityParams& p,
                                          std::array<double, 6>* eigenvalues);

/// JSON text of the report (every figure above).
std::string qualityReportToJson(const QualityReport& report);
/// Human-readable multi-line summary.
std::string qualityReportToText(const QualityReport& report);

}  // namespace plumb
