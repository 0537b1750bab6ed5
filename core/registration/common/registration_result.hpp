#pragma once
// What every global registration method returns (docs/ALGORITHMS.md §8): the chosen transform, its
// score, the runner-up hypothesis and the score gap (ambiguity), inlier counts and a status
// that makes failures explicit. A failed result never carries a transform to be trusted.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb {

enum class RegistrationStatus {
  Success,
  TooFewFeatures,  ///< inputs do not carry enough features for the method
  NoHypothesis,    ///< no hypothesis scored above the acceptance threshold
  Ambiguous,       ///< a clearly different hypothesis scored almost as well
  NotConverged,    ///< refinement diverged or lost its overlap
};
const char* toString(RegistrationStatus s);

/// One candidate transform and its score (higher is better; unit given by the method).
struct Hypothesis {
  RigidTransform transform;
  double score = 0.0;
  std::string label;  ///< how it was built, e.g. "clusters 0->+1, 1->-2"
};

struct GlobalRegistrationResult {
  RegistrationStatus status = RegistrationStatus::NoHypothesis;
  std::string method;      ///< "planes", "segments", "openings", "icp"
  std::string message;     ///< plain-language explanation (why it failed, what was used)
  RigidTransform transform;  ///< source -> target; meaningful only when ok()
  double score = 0.0;
  std::string score_unit;  ///< e.g. "m^2 of overlapping polygons", "matched segments"
  std::optional<Hypothesis> runner_up;  ///< best hypothesis clearly different from the chosen one
  double relative_gap = 1.0;  ///< (score - runner_up) / score, 1 when no runner-up
  /// Further hypotheses, each clearly different from the chosen one, the runner-up and each
  /// other, best first (at most HypothesisRanking::kAlternatives): a repeated room's other
  /// copy can score below an unrelated runner-up on features and still fit the points as well.
  std::vector<Hypothesis> alternatives;
  std::size_t hypotheses_evaluated = 0;
  std::size_t source_features = 0;
  std::size_t target_features = 0;
  std::size_t inlier_features = 0;  ///< source features matched under the chosen transform
  double feature_rms = 0.0;         ///< m, RMS residual on matched features
  /// m, openings method: the façade wall thickness between the indoor faces and the outdoor
  /// façade faces (measured, or assumed: see figures); the refinement must not bridge it.
  std::optional<double> wall_thickness;
  /// The thickness was measured (openings on non-parallel façades, or planes seen through
  /// them), not assumed.
  bool wall_thickness_measured = false;
  /// The source's up direction was chosen among estimated candidates (orientation any, or auto
  /// on data that does not look levelled): the answer may be upside down (copy_search.hpp).
  bool up_estimated = false;
  /// Then, the answer of every other up direction tried: each a plausible orientation of the
  /// source, refined and compared whatever its feature score (the true up direction's answer
  /// can score below a wrong one's: a wall matched as a floor).
  std::vector<Hypothesis> orientation_answers;
  /// Method-specific figures for the report, e.g. {"wall thickness (m)", 0.31}.
  std::vector<std::pair<std::string, double>> figures;

  bool ok() const { return status == RegistrationStatus::Success; }
};

/// Keeps the best hypothesis and the best one that is "clearly different" from it (rotation
/// differs by more than `min_rotation_deg` or translation by more than `min_translation`).
class HypothesisRanking {
 public:
  HypothesisRanking(double min_rotation_deg, double min_translation)
      : min_rot_(min_rotation_deg), min_trans_(min_translation) {}
  void add(const Hypothesis& h);
  const std::optional<Hypothesis>& best() const { return best_; }
  /// Runner-up among all hypotheses seen (computed lazily from the kept list).
  std::optional<Hypothesis> runnerUp() const;
  static constexpr std::size_t kAlternatives = 4;
  /// The kept hypotheses after the runner-up that differ from the best, best first (at most
  /// kAlternatives).
  std::vector<Hypothesis> alternatives() const;
  std::size_t count() const { return count_; }

 private:
  bool distinct(const Hypothesis& a, const Hypothesis& b) const;
  double min_rot_, min_trans_;
  std::optional<Hypothesis> best_;
  std::vector<Hypothesis> top_;  ///< a few best hypotheses, kept to find the runner-up
  std::size_t count_ = 0;
};

/// Fills status / runner_up / relative_gap from a ranking: NoHypothesis when the best score is
/// below `min_score`, Ambiguous when a distinct runner-up is within `min_relative_gap`.
void finalizeFromRanking(const HypothesisRanking& ranking, double min_score,
                         double min_relative_gap, GlobalRegistrationResult& result);

}  // namespace plumb
