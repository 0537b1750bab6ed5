#pragma once
// A quality report with every optional part filled (runner-up, refinement, weak directions,
// free space both ways, candidates, warnings, method figures), so tests see every JSON path.
#include "quality/quality_report.hpp"

namespace plumb::test {

inline QualityReport fullQualityReport() {
  QualityReport q;
  q.success = true;
  q.level = VerdictLevel::CheckVisually;
  q.verdict = "Registration succeeded <with> \"planes\" & a warning";
  q.method = "planes";
  q.status = "success";
  q.transform = RigidTransform::fromYaw(0.4, Eigen::Vector3d(651000.25, 6860000.5, 40.125));
  q.global_transform = RigidTransform::fromYaw(0.41, Eigen::Vector3d(651000.2, 6860000.4, 40.1));
  q.global_score = 46.1;
  q.score_unit = "m^2 of matched polygon overlap";
  q.has_runner_up = true;
  q.runner_up_transform = RigidTransform::fromYaw(2.0, Eigen::Vector3d(1, 2, 3));
  q.runner_up_score = 20.9;
  q.relative_gap = 0.55;
  q.hypotheses = 48;
  q.source_features = 54, q.target_features = 53, q.inlier_features = 6;
  q.feature_rms = 0.012;
  q.refined = true;
  q.point_rms = 0.0194;
  q.overlap_ratio = 0.716;
  q.point_inliers = 10929;
  q.refinement_shift = 0.0054;
  q.refinement_rotation = 0.22;
  q.eigenvalues = {1, 2, 3, 4, 5, 6};
  q.direction_resistance = {0.5, 0.4, 0.3, 0.2, 0.1, 0.05};
  WeakDirection w;
  w.relative_eigenvalue = 0.01;
  w.resistance = 0.04;
  w.description = "translation along horizontal (1.00, 0.00, 0.00) is weakly constrained";
  q.weak_directions.push_back(w);
  q.figures = {{"wall thickness (m)", 0.31}, {"seconds features", 4.2}};
  q.warnings = {"a direction is weakly constrained"};
  q.visibility.computed = true;
  q.visibility.source_in_target.available = true;
  q.visibility.source_in_target.tested = 22184;
  q.visibility.source_in_target.visible = 18318;
  q.visibility.source_in_target.contradicting = 183;
  q.visibility.source_in_target.consistent = 18135;
  q.visibility.target_in_source.available = false;
  q.visibility.target_in_source.missing_reason = "the target has no sensor origins";
  PlacementCandidate c;
  c.transform = q.transform;
  c.role = "chosen";
  c.label = "global answer";
  c.feature_score = 46.1;
  c.refined = true;
  c.overlap = 0.716;
  c.point_rms = 0.0194;
  c.inliers = 10929;
  c.fit_cost = 0.356;
  c.figures = {{"free-space contradiction ratio", 0.004}, {"unexplained structure", 0.02},
               {"structure overlap", 0.97}};
  q.candidates = {c, c};
  q.candidates[1].role = "worse";
  return q;
}

}  // namespace plumb::test
