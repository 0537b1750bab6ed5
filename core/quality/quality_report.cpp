#include "quality/quality_report.hpp"

#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "quality/visibility_verdict.hpp"

namespace plumb {

const ParamSchema<QualityParams>& QualityParams::schema() {
  using P = QualityParams;
  static const auto s =
      ParamSchema<P>("quality")
          .real(&P::weak_ratio, "weak-ratio", "Weak DOF ratio", "", 1e-6, 0.5,
                "Eigenvalue fraction below which a direction is weakly constrained", true)
          .real(&P::min_overlap, "min-overlap", "Min overlap", "", 0.0, 1.0,
                "Minimum fraction of source points matched after refinement")
          .real(&P::max_point_rms, "max-rms", "Max point RMS", "m", 0.001, 1.0,
                "Point RMS above this is flagged")
          .real(&P::warn_relative_gap, "warn-gap", "Warn score gap", "", 0.0, 1.0,
                "Flag a runner-up within this relative score gap", true)
          .real(&P::min_resistance, "min-resistance", "Min slide resistance", "", 0.0, 0.5,
                "A direction along which a 0.2 m slide pushes fewer matched points than this "
                "fraction off their surface is unconstrained: the registration fails", true)
          .real(&P::warn_resistance, "warn-resistance", "Warn slide resistance", "", 0.0, 1.0,
                "A direction weak by eigenvalue is flagged only below this slide resistance", true);
  return s;
}

namespace {
std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(2) << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return o.str();
}
std::string axisName(const Eigen::Vector3d& a) {
  if (std::abs(a.z()) > 0.95) return "vertical " + vec(a);
  if (std::abs(a.z()) < 0.3) return "horizontal " + vec(a);
  return vec(a);
}
}  // namespace

namespace {
/// Eigen-direction i of the normal matrix as a translation or a rotation axis.
WeakDirection directionOf(const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>>& es,
                          int i) {
  const Eigen::Matrix<double, 6, 1> v = es.eigenvectors().col(i);
  WeakDirection w;
  w.translation = v.tail<3>().norm() >= v.head<3>().norm();
  w.axis = (w.translation ? v.tail<3>() : v.head<3>()).normalized();
  if (w.axis[2] < 0 || (std::abs(w.axis[2]) < 1e-9 && w.axis[0] < 0)) w.axis = -w.axis;
  w.relative_eigenvalue = es.eigenvalues()(5) > 0 ? es.eigenvalues()(i) / es.eigenvalues()(5) : 0.0;
  return w;
}

std::string describe(const WeakDirection& w) {
  const std::string what = w.translation ? "translation along " + axisName(w.axis)
                                         : "rotation about " + axisName(w.axis);
  if (w.unconstrained)
    return what + (w.translation ? " is unconstrained (the data slides along it freely)"
                                 : " is unconstrained (the data turns about it freely)");
  return what + (w.translation ? " is weakly constrained (the data slides along it)"
                               : " is weakly constrained");
}

Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> solve(
    const Eigen::Matrix<double, 6, 6>& h, std::array<double, 6>* eigenvalues) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(h);
  if (eigenvalues)
    for (int i = 0; i < 6; ++i) (*eigenvalues)[i] = es.eigenvalues()(i);
  return es;
}
}  // namespace

std::vector<WeakDirection> weakDirections(const RefineResult& r, const QualityParams& p,
                                          std::array<double, 6>* eigenvalues) {
  std::vector<WeakDirection> out;
  const auto es = solve(r.normal_matrix, eigenvalues);
  for (int i = 0; i < 6; ++i) {
    WeakDirection w = directionOf(es, i);
    w.resistance = r.direction_resistance[i];
    w.unconstrained = !(es.eigenvalues()(5) > 0) || w.resistance < p.min_resistance;
    const bool weak = w.relative_eigenvalue < p.weak_ratio && w.resistance < p.warn_resistance;
    if (!w.unconstrained && !weak) continue;
    w.description = describe(w);
    out.push_back(w);
  }
  return out;
}

namespace {
/// Beyond the papers: a registration whose refinement leaves a degree of freedom free (a
/// single plane, parallel planes, a corridor without openings, a line) has no answer along it,
/// whatever the global method claimed: it fails as degenerate, with the free directions named.
bool failOnFreeDirections(QualityReport& q, std::ostringstream& verdict) {
  std::vector<std::string> free;
  for (const auto& w : q.weak_directions)
    if (w.unconstrained) free.push_back(w.description);
  if (free.empty()) return false;
  q.status = "degenerate";
  verdict << "Registration FAILED (degenerate): the data does not fix every degree of freedom: ";
  for (std::size_t i = 0; i < free.size(); ++i) verdict << (i ? "; " : "") << free[i];
  verdict << ". No transform is given: add data that constrains these directions (other walls, "
             "openings, a neighbouring station) or tie points.";
  return true;
}
}  // namespace

namespace {
bool runnerUpRefined(const std::vector<PlacementCandidate>& c) {
  return c.size() > 1 && c[1].refined;
}

const char* kUsableSentence =
    "All six degrees of freedom are well constrained and no competing placement fits as well: "
    "the result can be used.";

std::string checkVisuallySentence(std::size_t warnings) {
  return "CHECK VISUALLY: " + std::to_string(warnings) +
         " warning(s) below; the result is written but verify it before relying on it.";
}

/// The global step's figures, copied into the report.
QualityReport fromGlobal(const GlobalRegistrationResult& g,
                         const std::vector<PlacementCandidate>& candidates) {
  QualityReport q;
  q.candidates = candidates;
  q.method = g.method;
  q.status = toString(g.status);
  q.global_transform = g.transform;
  q.transform = g.transform;
  q.global_score = g.score;
  q.score_unit = g.score_unit;
  q.has_runner_up = g.runner_up.has_value();
  if (g.runner_up) {
    q.runner_up_transform = g.runner_up->transform;
    q.runner_up_score = g.runner_up->score;
  }
  q.relative_gap = g.relative_gap;
  q.hypotheses = g.hypotheses_evaluated;
  q.source_features = g.source_features;
  q.target_features = g.target_features;
  q.inlier_features = g.inlier_features;
  q.feature_rms = g.feature_rms;
  q.figures = g.figures;
  return q;
}

std::string globalFailureVerdict(const QualityReport& q, const std::string& message) {
  std::ostringstream verdict;
  verdict << "Registration FAILED (" << q.status << "): " << message
          << ". No transform is given; do not use this result. Check that the two datasets "
             "overlap, or try another method or manual tie points.";
  if (q.candidates.size() > 1)
    verdict << " " << q.candidates.size() << " candidate placements are listed in the report.";
  return verdict.str();
}

/// The refinement's figures and its hard rules (overlap, free directions); returns the
/// failure verdict, or "" when the refinement passed.
std::string assessRefinement(const GlobalRegistrationResult& g, const RefineResult& r,
                             const QualityParams& p, QualityReport& q) {
  q.refined = true;
  q.transform = r.transform;
  q.point_rms = r.rms;
  q.overlap_ratio = r.overlap;
  q.point_inliers = r.inliers;
  q.length_scale = r.length_scale;
  q.refinement_shift = RigidTransform::translationError(r.transform, g.transform);
  q.refinement_rotation = RigidTransform::rotationErrorDeg(r.transform, g.transform);
  q.weak_directions = weakDirections(r, p, &q.eigenvalues);
  q.direction_resistance = r.direction_resistance;
  if (q.point_rms > p.max_point_rms)
    q.warnings.push_back("point RMS " + std::to_string(q.point_rms) + " m is above " +
                         std::to_string(p.max_point_rms) +
                         " m: noisy data, moving objects or a partial misalignment");
  std::ostringstream verdict;
  if (r.inliers < 10 || q.overlap_ratio < p.min_overlap) {
    q.status = "refinement failed";
    verdict << "Registration FAILED: after refinement only " << std::setprecision(3)
            << 100.0 * q.overlap_ratio << "% of the source points lie within the inlier "
            << "distance of the target (minimum " << 100.0 * p.min_overlap
            << "%). The global alignment is probably wrong. " << r.message;
  } else {
    failOnFreeDirections(q, verdict);
  }
  return verdict.str();
}

/// Warnings that do not depend on the points' evidence: refinement off, a close unrefined
/// runner-up, weak directions.
void addStructuralWarnings(const GlobalRegistrationResult& g, const RefineResult* refine,
                           const QualityParams& p, QualityReport& q) {
  if (!refine)
    q.warnings.push_back("refinement was off: the degrees of freedom were not checked on the "
                         "points (run with refinement to know whether the data fixes all six)");
  if (g.runner_up && g.relative_gap < p.warn_relative_gap && !runnerUpRefined(q.candidates))
    q.warnings.push_back("a different transform scored only " +
                         std::to_string(100.0 * g.relative_gap) +
                         "% lower: the scene is nearly symmetric, check the result visually");
  for (const auto& w : q.weak_directions) q.warnings.push_back(w.description);
}

std::string successVerdict(const GlobalRegistrationResult& g, const QualityReport& q,
                           const std::string& evidence_sentence) {
  std::ostringstream verdict;
  verdict << std::setprecision(3) << "Registration succeeded with the " << g.method
          << " method: " << g.inlier_features << " of " << g.source_features
          << " source features matched";
  if (q.refined)
    verdict << ", point RMS " << 1000.0 * q.point_rms << " mm over " << 100.0 * q.overlap_ratio
            << "% overlap";
  verdict << ". "
          << (q.level == VerdictLevel::Usable ? std::string(kUsableSentence)
                                              : checkVisuallySentence(q.warnings.size()))
          << evidence_sentence;
  return verdict.str();
}

void setOutcome(QualityReport& q, bool success, std::string verdict) {
  q.success = success;
  q.level = verdictLevelOf(success, q.warnings);
  q.verdict = std::move(verdict);
}
}  // namespace

QualityReport assessRegistration(const GlobalRegistrationResult& g, const RefineResult* refine,
                                 const QualityParams& p,
                                 const std::vector<PlacementCandidate>& candidates,
                                 const VerdictEvidence* evidence) {
  QualityReport q = fromGlobal(g, candidates);
  if (!g.ok()) {
    setOutcome(q, false, globalFailureVerdict(q, g.message));
    return q;
  }
  const std::string refine_failure = refine ? assessRefinement(g, *refine, p, q) : "";
  addStructuralWarnings(g, refine, p, q);
  if (!refine_failure.empty()) {
    setOutcome(q, false, refine_failure);
    return q;
  }
  FreeSpaceFinding free_space;
  if (evidence) {
    q.visibility = evidence->visibility;
    free_space = judgeFreeSpace(q.visibility, evidence->visibility_params,
                                {q.refined, q.overlap_ratio, q.point_rms});
  }
  if (free_space.contradicted) {
    q.status = "contradicted";
    setOutcome(q, false, free_space.failure);
    return q;
  }
  q.warnings.insert(q.warnings.end(), free_space.warnings.begin(), free_space.warnings.end());
  q.level = verdictLevelOf(true, q.warnings);
  setOutcome(q, true, successVerdict(g, q, free_space.evidence));
  return q;
}

namespace {
nlohmann::json matrixJson(const RigidTransform& t) {
  nlohmann::json m = nlohmann::json::array();
  const Eigen::Matrix4d x = t.matrix();
  for (int r = 0; r < 4; ++r) m.push_back({x(r, 0), x(r, 1), x(r, 2), x(r, 3)});
  return m;
}

nlohmann::json figuresJson(const std::vector<std::pair<std::string, double>>& figures) {
  nlohmann::json f = nlohmann::json::object();
  for (const auto& [k, v] : figures) f[k] = v;
  return f;
}

nlohmann::json candidatesJson(const std::vector<PlacementCandidate>& candidates) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& c : candidates) {
    nlohmann::json j = {{"role", c.role},
                        {"label", c.label},
                        {"transform", matrixJson(c.transform)},
                        {"feature_score", c.feature_score},
                        {"refined", c.refined},
                        {"figures", figuresJson(c.figures)}};
    if (c.refined) {
      j["overlap_ratio"] = c.overlap;
      j["rms_m"] = c.point_rms;
      j["inliers"] = c.inliers;
      j["fit_cost"] = c.fit_cost;
    }
    out.push_back(j);
  }
  return out;
}
}  // namespace

std::string qualityReportToJson(const QualityReport& q) {
  using nlohmann::json;
  const auto mat = matrixJson;
  json j;
  j["success"] = q.success;
  j["verdict_level"] = verdictLevelName(q.level);
  j["exit_code"] = verdictExitCode(q.level);
  j["verdict"] = q.verdict;
  j["method"] = q.method;
  j["status"] = q.status;
  j["transform"] = mat(q.transform);
  j["global_transform"] = mat(q.global_transform);
  j["global_score"] = q.global_score;
  j["score_unit"] = q.score_unit;
  j["hypotheses_evaluated"] = q.hypotheses;
  if (q.has_runner_up) {
    j["runner_up"] = {{"transform", mat(q.runner_up_transform)},
                      {"score", q.runner_up_score},
                      {"relative_gap", q.relative_gap}};
  } else {
    j["runner_up"] = nullptr;
  }
  j["features"] = {{"source", q.source_features},
                   {"target", q.target_features},
                   {"inliers", q.inlier_features},
                   {"rms_m", q.feature_rms}};
  j["refined"] = q.refined;
  if (q.refined) {
    j["points"] = {{"rms_m", q.point_rms},
                   {"overlap_ratio", q.overlap_ratio},
                   {"inliers", q.point_inliers},
                   {"length_scale_m", q.length_scale},
                   {"refinement_shift_m", q.refinement_shift},
                   {"refinement_rotation_deg", q.refinement_rotation}};
    j["normal_matrix_eigenvalues"] = q.eigenvalues;
    j["direction_resistance"] = q.direction_resistance;
  }
  json weak = json::array();
  for (const auto& w : q.weak_directions)
    weak.push_back({{"kind", w.translation ? "translation" : "rotation"},
                    {"axis", {w.axis.x(), w.axis.y(), w.axis.z()}},
                    {"relative_eigenvalue", w.relative_eigenvalue},
                    {"slide_resistance", w.resistance},
                    {"unconstrained", w.unconstrained},
                    {"description", w.description}});
  j["weak_directions"] = weak;
  j["figures"] = figuresJson(q.figures);
  j["warnings"] = q.warnings;
  addVisibilityJson(j, q.visibility);
  j["candidates"] = candidatesJson(q.candidates);
  return j.dump(2) + "\n";
}

namespace {
void candidatesToText(std::ostream& o, const std::vector<PlacementCandidate>& candidates) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const auto& c = candidates[i];
    const Eigen::Vector3d t = c.transform.translation();
    o << "candidate " << i + 1 << " (" << c.role << "): rotation " << c.transform.rotationAngleDeg()
      << " deg, translation " << vec(t) << " m, feature score " << c.feature_score;
    if (c.refined)
      o << ", refined overlap " << c.overlap << ", point RMS " << c.point_rms << " m, "
        << c.inliers << " inliers, fit cost " << c.fit_cost;
    for (const auto& [k, v] : c.figures) o << ", " << k << " " << v;
    o << "\n";
  }
}
}  // namespace

std::string qualityReportToText(const QualityReport& q) {
  std::ostringstream o;
  o << "verdict: " << verdictLevelWords(q.level) << " (exit " << verdictExitCode(q.level) << ")\n";
  o << q.verdict << "\n";
  o << "method: " << q.method << ", status: " << q.status << "\n";
  if (q.success) o << "transform (source -> target):\n" << q.transform;
  o << "features: " << q.inlier_features << " matched of " << q.source_features
    << " (target " << q.target_features << "), feature RMS " << q.feature_rms << " m\n";
  if (q.refined)
    o << "points: RMS " << q.point_rms << " m, overlap " << q.overlap_ratio << "\n";
  if (q.has_runner_up)
    o << "runner-up score " << q.runner_up_score << " (gap " << 100 * q.relative_gap << "%)\n";
  o << visibilityToText(q.visibility);
  for (const auto& w : q.warnings) o << "warning: " << w << "\n";
  if (q.candidates.size() > 1 || !q.success) candidatesToText(o, q.candidates);
  return o.str();
}

}  // namespace plumb
