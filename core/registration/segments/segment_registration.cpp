#include "registration/segments/segment_registration.hpp"

#include <algorithm>
#include <cmath>
#include <queue>
#include <sstream>

#include "registration/segments/line_alignment.hpp"
#include "registration/segments/translation_voting.hpp"

namespace plumb {

const ParamSchema<SegmentRegistrationParams>& SegmentRegistrationParams::schema() {
  using P = SegmentRegistrationParams;
  static const auto s =
      ParamSchema<P>("segments")
          .real(&P::vote_cell, "vote-cell", "Vote cell", "m", 0.05, 5.0,
                "Cell of the translation vote grid", true)
          .integer(&P::peaks_per_rotation, "peaks", "Peaks per rotation", "", 1, 100,
                   "Translation peaks examined per rotation", true)
          .real(&P::min_segment_length, "min-segment-length", "Min segment length", "m", 0.0,
                10.0, "Shorter segments are ignored")
          .integer(&P::max_vote_segments, "max-vote-segments", "Max voting segments", "", 10,
                   100000, "Longest segments of each set used for voting", true)
          .real(&P::min_matched_segments, "min-matched", "Min matched segments", "", 1, 1e6,
                "Acceptance threshold on the similarity (matched segments)")
          .real(&P::min_relative_gap, "min-gap", "Min score gap", "", 0.0, 1.0,
                "Runner-up must score this fraction below the best, else ambiguous")
          .integer(&P::refine_iterations, "polish-iterations", "Polish iterations", "", 0, 100,
                   "Joint rotation/translation polish on matched segments", true)
          .nested(&P::clustering, DirectionClusteringParams::schema())
          .nested(&P::distance, SegmentDistanceParams::schema())
          .nested(&P::rotations, RotationEnumerationParams::schema());
  return s;
}

SegmentPolishResult polishOnSegments(const std::vector<Segment3D>& source,
                                     const SegmentSetIndex& target, const RigidTransform& start,
                                     int iterations, bool rotation_too) {
  SegmentPolishResult out;
  out.transform = start;
  const double d2 = target.params().robust_distance * target.params().robust_distance;
  for (int it = 0; it <= iterations; ++it) {
    std::vector<PointLineConstraint> c;
    double sq = 0.0;
    std::size_t matched = 0;
    for (const auto& s : source) {
      const Eigen::Vector3d a = out.transform.apply(s.a), b = out.transform.apply(s.b);
      const SegmentMatch m = target.match(a, b);
      if (m.target < 0) continue;
      ++matched;
      sq += m.distance * m.distance;
      const auto& t = target.segments()[m.target];
      const Eigen::Vector3d d = (t.b - t.a).normalized();
      const double w = (1.0 - m.cost / d2) + 1e-6;
      if (rotation_too) {
        c.push_back({s.a, t.a, d, w});
        c.push_back({s.b, t.a, d, w});
      } else {
        c.push_back({out.transform.rotation() * s.a, t.a, d, w});
        c.push_back({out.transform.rotation() * s.b, t.a, d, w});
      }
    }
    out.matched = matched;
    out.rms = matched ? std::sqrt(sq / matched) : 0.0;
    if (it == iterations || c.size() < 4) break;
    if (rotation_too) {
      const auto step = alignToLines(c, out.transform);
      if (!step.ok) break;
      out.transform = step.transform;
    } else {
      const auto t = translationFromLines(c);
      if (!t) break;
      out.transform = RigidTransform(out.transform.rotation(), *t);
    }
  }
  return out;
}

namespace {

std::vector<Segment3D> longest(const std::vector<Segment3D>& in, double min_len, int max_count) {
  std::vector<Segment3D> out;
  for (const auto& s : in)
    if (s.length() >= min_len && s.a.allFinite() && s.b.allFinite()) out.push_back(s);
  std::stable_sort(out.begin(), out.end(),
                   [](const Segment3D& a, const Segment3D& b) { return a.length() > b.length(); });
  if (int(out.size()) > max_count) out.resize(max_count);
  return out;
}

}  // namespace

GlobalRegistrationResult registerSegments(const std::vector<Segment3D>& source_in,
                                          const std::vector<Segment3D>& target_in,
                                          const SegmentRegistrationParams& p,
                                          Progress* progress) {
  GlobalRegistrationResult r;
  r.method = "segments";
  r.score_unit = "matched segments";
  r.source_features = source_in.size();
  r.target_features = target_in.size();
  const std::vector<Segment3D> source = longest(source_in, p.min_segment_length, 1 << 30);
  const std::vector<Segment3D> target = longest(target_in, p.min_segment_length, 1 << 30);
  if (source.size() < 4 || target.size() < 4) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message = "segments: need at least 4 segments longer than " +
                std::to_string(p.min_segment_length) + " m in each dataset (source has " +
                std::to_string(source.size()) + ", target " + std::to_string(target.size()) + ")";
    return r;
  }
  reportProgress(progress, 0.0, "segments: clustering directions");
  const std::vector<Segment3D> vs = longest(source, 0, p.max_vote_segments);
  const std::vector<Segment3D> vt = longest(target, 0, p.max_vote_segments);
  const auto cs = clusterSegmentDirections(vs, p.clustering);
  const auto ct = clusterSegmentDirections(vt, p.clustering);
  if (cs.clusters.size() < 2 || ct.clusters.size() < 2) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message = "segments: the segments span fewer than two distinct directions, the rotation "
                "is undetermined";
    return r;
  }
  RotationEnumerationParams rp = p.rotations;
  rp.angle_tolerance_deg = p.clustering.angle_tolerance_deg;
  const auto rotations = enumerateRotations(cs.directions(), ct.directions(), rp);
  if (rotations.empty()) {
    r.status = RegistrationStatus::NoHypothesis;
    r.message = "segments: no rotation maps the source direction clusters onto the target's";
    return r;
  }
  const SegmentSetIndex fine(target, p.distance);
  SegmentDistanceParams coarse_params = p.distance;
  coarse_params.robust_distance = std::max(p.vote_cell, p.distance.robust_distance);
  coarse_params.max_angle_deg = std::max(p.distance.max_angle_deg, p.clustering.angle_tolerance_deg);
  const SegmentSetIndex coarse(target, coarse_params);

  HypothesisRanking ranking(2.0, std::max(0.5, 5 * p.distance.robust_distance));
  for (std::size_t ri = 0; ri < rotations.size(); ++ri) {
    checkCanceled(progress);
    reportProgress(progress, 0.05 + 0.85 * double(ri) / rotations.size(), "segments: voting");
    const auto& rot = rotations[ri];
    const auto peaks = voteTranslations(vs, cs, vt, ct, rot, p.vote_cell, p.peaks_per_rotation);
    for (const auto& peak : peaks) {
      RigidTransform t(rot.rotation, peak);
      // Translation only with eq. 14, coarse then fine matching distance.
      t = polishOnSegments(source, coarse, t, 3, false).transform;
      t = polishOnSegments(source, fine, t, 3, false).transform;
      Hypothesis h{t, fine.similarity(source, t), rot.label};
      ranking.add(h);
    }
  }
  finalizeFromRanking(ranking, p.min_matched_segments, p.min_relative_gap, r);
  if (ranking.best()) {
    // Joint polish of the best hypothesis (rotation from all matched pairs, not just the
    // cluster means).
    const auto pol = polishOnSegments(source, fine, r.transform, p.refine_iterations, true);
    const double s = fine.similarity(source, pol.transform);
    if (s >= r.score) {
      r.transform = pol.transform;
      r.score = s;
    }
    const auto fin = polishOnSegments(source, fine, r.transform, 0, true);
    r.inlier_features = fin.matched;
    r.feature_rms = fin.rms;
    if (r.runner_up && r.score > 0) r.relative_gap = (r.score - r.runner_up->score) / r.score;
  }
  r.message = "segments: " + r.message;
  reportProgress(progress, 1.0, "segments: done");
  return r;
}

}  // namespace plumb
