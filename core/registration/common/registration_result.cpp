#include "registration/common/registration_result.hpp"

#include <algorithm>
#include <sstream>

namespace plumb {

const char* toString(RegistrationStatus s) {
  switch (s) {
    case RegistrationStatus::Success: return "success";
    case RegistrationStatus::TooFewFeatures: return "too few features";
    case RegistrationStatus::NoHypothesis: return "no hypothesis above threshold";
    case RegistrationStatus::Ambiguous: return "ambiguous";
    case RegistrationStatus::NotConverged: return "refinement did not converge";
  }
  return "unknown";
}

bool HypothesisRanking::distinct(const Hypothesis& a, const Hypothesis& b) const {
  return RigidTransform::rotationErrorDeg(a.transform, b.transform) > min_rot_ ||
         RigidTransform::translationError(a.transform, b.transform) > min_trans_;
}

void HypothesisRanking::add(const Hypothesis& h) {
  ++count_;
  if (!best_ || h.score > best_->score) best_ = h;
  // Keep a short list of the best hypotheses, one per "distinct" transform.
  for (auto& k : top_) {
    if (!distinct(k, h)) {
      if (h.score > k.score) k = h;
      return;
    }
  }
  top_.push_back(h);
  std::sort(top_.begin(), top_.end(),
            [](const Hypothesis& a, const Hypothesis& b) { return a.score > b.score; });
  if (top_.size() > 16) top_.resize(16);
}

std::optional<Hypothesis> HypothesisRanking::runnerUp() const {
  if (!best_) return std::nullopt;
  for (const auto& k : top_)
    if (distinct(k, *best_)) return k;
  return std::nullopt;
}

std::vector<Hypothesis> HypothesisRanking::alternatives() const {
  std::vector<Hypothesis> out;
  if (!best_) return out;
  bool runner_up_seen = false;
  for (const auto& k : top_) {
    if (!distinct(k, *best_)) continue;
    if (!runner_up_seen) {
      runner_up_seen = true;
      continue;
    }
    out.push_back(k);
    if (out.size() == kAlternatives) break;
  }
  return out;
}

void finalizeFromRanking(const HypothesisRanking& ranking, double min_score,
                         double min_relative_gap, GlobalRegistrationResult& r) {
  r.hypotheses_evaluated = ranking.count();
  const auto& best = ranking.best();
  if (!best) {
    r.status = RegistrationStatus::NoHypothesis;
    r.message = "no transform hypothesis could be built from the features";
    return;
  }
  r.transform = best->transform;
  r.score = best->score;
  r.runner_up = ranking.runnerUp();
  r.alternatives = ranking.alternatives();
  r.relative_gap = r.runner_up && best->score > 0
                       ? (best->score - r.runner_up->score) / best->score
                       : 1.0;
  std::ostringstream msg;
  if (best->score < min_score) {
    r.status = RegistrationStatus::NoHypothesis;
    msg << "best hypothesis scores " << best->score << " " << r.score_unit
        << ", below the acceptance threshold " << min_score;
  } else if (r.runner_up && r.relative_gap < min_relative_gap) {
    r.status = RegistrationStatus::Ambiguous;
    msg << "two different transforms score almost the same (" << best->score << " vs "
        << r.runner_up->score << " " << r.score_unit << ", gap "
        << 100.0 * r.relative_gap << "%): the scene is too symmetric or features are missing";
  } else {
    r.status = RegistrationStatus::Success;
    msg << "best of " << ranking.count() << " hypotheses (" << best->label << "), score "
        << best->score << " " << r.score_unit;
  }
  r.message = msg.str();
}

}  // namespace plumb
