#include "registration/auto/elsewhere_search.hpp"

#include <algorithm>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

namespace {
bool covered(const Eigen::Vector3d& x, const Bounds& box, const RigidTransform& inverse,
             double margin) {
  const Eigen::Vector3d q = inverse.apply(x);
  return (q.array() >= box.min.array() - margin).all() && (q.array() <= box.max.array() + margin).all();
}

Eigen::Vector3d centre(const Opening& o) {
  return 0.25 * (o.corners[0] + o.corners[1] + o.corners[2] + o.corners[3]);
}
}  // namespace

FeatureSet featuresOutside(const FeatureSet& target, const Bounds& source_box,
                           const RigidTransform& chosen, double margin) {
  const RigidTransform inverse = chosen.inverse();
  FeatureSet out;
  // Façades and openings refer to planes by index: renumbered, dropped with their plane.
  std::vector<int> plane_index(target.planes.size(), -1);
  for (std::size_t i = 0; i < target.planes.size(); ++i) {
    if (covered(target.planes[i].centroid, source_box, inverse, margin)) continue;
    plane_index[i] = static_cast<int>(out.planes.size());
    out.planes.push_back(target.planes[i]);
  }
  for (int f : target.facades)
    if (f >= 0 && plane_index[static_cast<std::size_t>(f)] >= 0)
      out.facades.push_back(plane_index[static_cast<std::size_t>(f)]);
  for (const auto& o : target.openings) {
    if (covered(centre(o), source_box, inverse, margin)) continue;
    if (o.facade >= 0 && plane_index[static_cast<std::size_t>(o.facade)] < 0) continue;
    Opening kept = o;
    kept.facade = o.facade >= 0 ? plane_index[static_cast<std::size_t>(o.facade)] : -1;
    out.openings.push_back(kept);
  }
  for (const auto& s : target.segments)
    if (!covered(s.midpoint(), source_box, inverse, margin)) out.segments.push_back(s);
  return out;
}

bool roomForAnotherCopy(const Bounds& s, const Bounds& t, double min_volume_ratio) {
  if (s.empty() || t.empty()) return false;
  const auto volume = [](const Bounds& b) {
    const Eigen::Vector3d d = (b.max - b.min).cwiseMax(1.0);  // flat data: at least 1 m a side
    return d.prod();
  };
  return volume(t) >= min_volume_ratio * volume(s);
}

std::optional<Hypothesis> searchElsewhere(const FeatureSet& source, const FeatureSet& target,
                                          const RigidTransform& chosen, double chosen_score,
                                          bool target_is_model, const PipelineParams& p) {
  const Bounds source_box = featureBounds(source);
  if (!roomForAnotherCopy(source_box, featureBounds(target), p.candidates.elsewhere_volume_ratio))
    return std::nullopt;
  const FeatureSet rest = featuresOutside(target, source_box, chosen, p.candidates.elsewhere_margin);
  PipelineParams wider = p;
  wider.segments.peaks_per_rotation =
      std::min(100, p.segments.peaks_per_rotation * p.candidates.elsewhere_peak_factor);
  GlobalRegistrationResult g = registerFeatureSets(source, rest, target_is_model, wider);
  if (g.hypotheses_evaluated == 0 || !(g.score > 0.0)) return std::nullopt;
  if (g.score < p.candidates.alternative_min_score * chosen_score) return std::nullopt;
  return Hypothesis{g.transform, g.score, "best elsewhere (" + g.method + ")"};
}

}  // namespace plumb
