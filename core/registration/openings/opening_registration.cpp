#include "registration/openings/opening_registration.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "registration/segments/segment_registration.hpp"

namespace plumb {

const ParamSchema<OpeningRegistrationParams>& OpeningRegistrationParams::schema() {
  using P = OpeningRegistrationParams;
  static const auto s =
      ParamSchema<P>("openings")
          .integer(&P::max_hypotheses, "max-hypotheses", "Max hypotheses", "", 10, 1e7,
                   "Enumerate up to this many, else sample at random", true)
          .real(&P::max_wall_thickness, "max-wall-thickness", "Max wall thickness", "m", 0.0, 3.0,
                "Wall thickness search range")
          .real(&P::assumed_wall_thickness, "assumed-wall-thickness", "Assumed wall thickness",
                "m", 0.0, 3.0, "Used when no plane pair measures the thickness")
          .boolean(&P::require_measured_thickness, "require-thickness", "Require measured thickness",
                   "Fail when the wall thickness cannot be measured instead of assuming it")
          .real(&P::min_matched_segments, "min-matched", "Min matched edges", "", 1, 1e6,
                "Acceptance threshold (matched opening edges)")
          .real(&P::min_relative_gap, "min-gap", "Min score gap", "", 0.0, 1.0,
                "Runner-up must score this fraction below the best, else ambiguous")
          .real(&P::vertical_tolerance_deg, "facade-vertical", "Façade verticality", "deg", 0.0,
                45.0, "Max tilt of a façade plane", true)
          .integer(&P::seed, "seed", "Seed", "", 0, 9.0e15, "Random seed", true);
  return s;
}

namespace {

std::vector<Segment3D> openingEdges(const std::vector<Opening>& openings) {
  std::vector<Segment3D> out;
  for (const auto& o : openings)
    for (const auto& e : o.edges()) out.push_back(e);
  return out;
}

struct Candidate {
  int so, to, sign, corner_s, corner_t;
};

}  // namespace

GlobalRegistrationResult registerOpenings(const FeatureSet& source, const FeatureSet& target,
                                          const OpeningRegistrationParams& p,
                                          Progress* progress) {
  GlobalRegistrationResult r;
  r.method = "openings";
  r.score_unit = "matched opening edges";
  r.source_features = source.openings.size();
  r.target_features = target.openings.size();
  auto usable = [&](const FeatureSet& f) {
    std::vector<int> idx;
    for (std::size_t i = 0; i < f.openings.size(); ++i) {
      const int w = f.openings[i].facade;
      if (w >= 0 && w < int(f.planes.size()) && f.planes[w].isVertical(p.vertical_tolerance_deg))
        idx.push_back(int(i));
    }
    return idx;
  };
  const auto so = usable(source), to = usable(target);
  if (so.empty() || to.empty()) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message = "openings: need openings on vertical walls in both datasets (source has " +
                std::to_string(so.size()) + ", target " + std::to_string(to.size()) + ")";
    return r;
  }
  const std::vector<Segment3D> src_edges = openingEdges(source.openings);
  const SegmentSetIndex tgt_index(openingEdges(target.openings), p.distance);

  // Enumerate (source opening, target opening, normal sign, bottom-corner pairing).
  std::vector<Candidate> cands;
  for (int a : so)
    for (int b : to)
      for (int s : {1, -1})
        for (int cs : {0, 1}) cands.push_back({a, b, s, 0, cs});
  if (int(cands.size()) > p.max_hypotheses) {
    std::mt19937_64 rng(p.seed);
    std::shuffle(cands.begin(), cands.end(), rng);
    cands.resize(p.max_hypotheses);
  }
  HypothesisRanking ranking(2.0, std::max(0.3, 3 * p.distance.robust_distance));
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (k % 256 == 0) {
      checkCanceled(progress);
      reportProgress(progress, 0.7 * double(k) / cands.size(), "openings: hypotheses");
    }
    const auto& c = cands[k];
    const Opening& o1 = source.openings[c.so];
    const Opening& o2 = target.openings[c.to];
    const Eigen::Vector3d n1 = source.planes[o1.facade].normal;
    const Eigen::Vector3d n2 = c.sign * target.planes[o2.facade].normal;
    // Rotation about the intersection line of the two planes: takes n1 onto n2.
    const Eigen::Matrix3d R = Eigen::Quaterniond::FromTwoVectors(n1, n2).toRotationMatrix();
    // Bottom corners (0, 1): source corner 0 with target corner 0 or 1.
    const Eigen::Vector3d c1 = R * o1.corners[c.corner_s];
    const Eigen::Vector3d c2 = o2.corners[c.corner_t];
    // In-plane DOF from the corners; along the normal: wall plane onto the façade plane
    // (zero thickness, the paper's placement).
    const Eigen::Vector3d nf = target.planes[o2.facade].normal;
    const double wall_offset = n2.dot(R * source.planes[o1.facade].centroid);
    Eigen::Vector3d t = c2 - c1;
    t -= nf.dot(t) * nf;
    t += (nf.dot(target.planes[o2.facade].centroid) - nf.dot(R * source.planes[o1.facade].centroid)) * nf;
    (void)wall_offset;
    const RigidTransform T(R, t);
    ranking.add({T, tgt_index.similarity(src_edges, T), ""});
  }
  finalizeFromRanking(ranking, p.min_matched_segments, p.min_relative_gap, r);
  if (!ranking.best()) return r;
  // Polish the 5-DOF placement on matched opening edges (eq. 14 generalised), then the
  // third DOF.
  RigidTransform T = polishOnSegments(src_edges, tgt_index, r.transform, 5, true).transform;
  // The façade of the best hypothesis: the target façade holding most matched openings.
  int facade = -1, wall = -1;
  {
    std::vector<int> votes(target.planes.size(), 0);
    for (std::size_t i = 0; i < src_edges.size(); ++i) {
      const auto m = tgt_index.match(T.apply(src_edges[i].a), T.apply(src_edges[i].b));
      if (m.target >= 0) {
        const int f = target.openings[m.target / 4].facade;
        if (f >= 0) ++votes[f];
        if (wall < 0) wall = source.openings[i / 4].facade;
      }
    }
    facade = int(std::max_element(votes.begin(), votes.end()) - votes.begin());
  }
  if (wall < 0) wall = source.openings[so[0]].facade;
  const Eigen::Vector3d nf = target.planes[facade].normal;
  // Inward direction: the side of the façade where the (transformed) indoor data lies.
  double side = 0.0;
  for (const auto& pl : source.planes) side += pl.area * nf.dot(T.apply(pl.centroid) - target.planes[facade].centroid);
  const Eigen::Vector3d inward = side >= 0 ? nf : Eigen::Vector3d(-nf);
  // Candidate shifts along the normal from plane pairs parallel to the façade, within the
  // thickness range; thickness = distance from the façade face to the shifted wall face.
  auto thicknessAfter = [&](double shift) {
    const Eigen::Vector3d wc = T.apply(source.planes[wall].centroid) + shift * inward;
    return inward.dot(wc - target.planes[facade].centroid);
  };
  std::vector<double> shifts;
  const double cos_tol = std::cos(p.planes.clustering.angle_tolerance_deg * M_PI / 180.0);
  for (std::size_t i = 0; i < source.planes.size(); ++i) {
    const auto& ps = source.planes[i];
    const Eigen::Vector3d n = T.rotation() * ps.normal;
    if (std::abs(n.dot(nf)) < cos_tol || int(i) == wall) continue;
    for (std::size_t j = 0; j < target.planes.size(); ++j) {
      if (int(j) == facade) continue;
      const auto& pt = target.planes[j];
      if (std::abs(pt.normal.dot(nf)) < cos_tol) continue;
      const double shift = inward.dot(pt.centroid - T.apply(ps.centroid));
      const double th = thicknessAfter(shift);
      if (th >= -0.02 && th <= p.max_wall_thickness) shifts.push_back(shift);
    }
  }
  const double assumed_shift = p.assumed_wall_thickness - thicknessAfter(0.0);
  double best_shift = assumed_shift, best_sim = -1.0, second_sim = -1.0;
  std::vector<PlanarPolygon> tgt_planes;
  for (std::size_t j = 0; j < target.planes.size(); ++j)
    if (int(j) != facade) tgt_planes.push_back(target.planes[j]);
  std::vector<PlanarPolygon> src_planes;
  for (std::size_t i = 0; i < source.planes.size(); ++i)
    if (int(i) != wall) src_planes.push_back(source.planes[i]);
  std::sort(shifts.begin(), shifts.end());
  for (double s : shifts) {
    const RigidTransform Ts(T.rotation(), T.translation() + s * inward);
    const double sim = planeSimilarity(src_planes, tgt_planes, Ts, p.planes);
    if (sim > best_sim) {
      second_sim = best_sim;
      best_sim = sim;
      best_shift = s;
    }
  }
  const bool measured = best_sim > 0.0;
  if (!measured) best_shift = assumed_shift;
  r.transform = RigidTransform(T.rotation(), T.translation() + best_shift * inward);
  r.score = tgt_index.similarity(src_edges, T);
  const auto fin = polishOnSegments(src_edges, tgt_index, T, 0, true);
  r.inlier_features = fin.matched / 4;
  r.feature_rms = fin.rms;
  r.figures.push_back({"wall thickness (m)", thicknessAfter(best_shift)});
  r.figures.push_back({"wall thickness measured", measured ? 1.0 : 0.0});
  r.figures.push_back({"normal-DOF plane similarity (m^2)", std::max(0.0, best_sim)});
  std::ostringstream msg;
  msg << "openings: " << r.message << "; wall thickness " << thicknessAfter(best_shift) << " m "
      << (measured ? "measured from planes seen through the openings"
                   : "ASSUMED (no plane parallel to the façade seen from both sides): the "
                     "translation along the façade normal is not measured");
  r.message = msg.str();
  if (!measured && p.require_measured_thickness && r.ok()) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message += ". Failing instead of guessing (require-thickness)";
  }
  (void)second_sim;
  reportProgress(progress, 1.0, "openings: done");
  return r;
}

}  // namespace plumb
