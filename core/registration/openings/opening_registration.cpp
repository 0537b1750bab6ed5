#include "registration/openings/opening_registration.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "registration/openings/opening_hypotheses.hpp"
#include "registration/openings/opening_match.hpp"

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
          .nested(&P::distance, SegmentDistanceParams::schema())
          // The plane settings of the wall-thickness score (planeSimilarity), not the others.
          .nested(&P::planes, PlaneRegistrationParams::schema(), "",
                  {"plane-distance", "oriented-normals", "min-polygon-area", "raster-cells",
                   "cluster-angle"});
  return s;
}

namespace openings_detail {

std::vector<Base> baseHypotheses(std::size_t n_source, std::size_t n_target, int max_hypotheses,
                                 std::uint64_t seed) {
  std::vector<Base> bases;
  for (std::size_t a = 0; a < n_source; ++a)
    for (std::size_t b = 0; b < n_target; ++b)
      for (int k : {0, 1}) bases.push_back({int(a), int(b), k});
  if (int(bases.size()) > max_hypotheses) {
    std::mt19937_64 rng(seed);
    std::shuffle(bases.begin(), bases.end(), rng);
    bases.resize(max_hypotheses);
  }
  return bases;
}

/// Unlike Quaternion::FromTwoVectors it never picks a tilted axis for opposite vectors
/// (docs/ALGORITHMS.md "Frames").
Eigen::Matrix3d yawBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  const double yaw = std::atan2(to.y(), to.x()) - std::atan2(from.y(), from.x());
  return Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

RigidTransform zeroThicknessPlacement(const OrientedOpening& s, const Opening& os,
                                      const OrientedOpening& t, const Opening& ot, int pairing) {
  const Eigen::Matrix3d R = yawBetween(s.normal, -t.normal);
  const int cs = pairing == 0 ? 0 : 1, ct = pairing == 0 ? 1 : 0;
  // Zero thickness (the paper's placement): the corners coincide.
  return RigidTransform(R, ot.corners[ct] - R * os.corners[cs]);
}

std::vector<double> thicknessCandidates(const std::vector<OrientedOpening>& src,
                                        const std::vector<OrientedOpening>& tgt,
                                        const RigidTransform& t0, const Eigen::Vector3d& n,
                                        const ThicknessSearch& search) {
  const double d = search.d;
  std::vector<double> thicknesses;
  for (const auto& k : src) {
    const Eigen::Vector3d nk = t0.rotation() * k.normal;
    if (std::abs(nk.dot(n)) > search.sin_tol * 2 + 0.02) continue;  // not perpendicular
    const Eigen::Vector3d ck = t0.apply(k.centre);
    for (const auto& m : tgt) {
      if (nk.dot(m.normal) > -search.cos_tol) continue;
      if (std::abs(ck.z() - m.centre.z()) > 2 * d || std::abs(k.width - m.width) > 2 * d) continue;
      const double th = n.dot(ck - m.centre);
      if (th >= -d && th <= search.max_thickness) thicknesses.push_back(th);
    }
  }
  std::sort(thicknesses.begin(), thicknesses.end());
  std::size_t kept = 0;
  for (double th : thicknesses) {
    if (kept > 0 && th - thicknesses[kept - 1] < 0.5 * d) continue;
    thicknesses[kept++] = th;
  }
  thicknesses.resize(kept);
  return thicknesses;
}

}  // namespace openings_detail

namespace {

/// Beyond the paper when no perpendicular opening fixed the façade-normal DOF: candidate
/// shifts along the façade normal from plane pairs parallel to the façade (indoor walls seen
/// through the windows in the outdoor scan and their indoor counterparts), scored with the
/// polygon overlap similarity (2021 eq. 10). Returns the shift along `inward` (or NaN).
double normalShiftFromPlanes(const FeatureSet& source, const FeatureSet& target,
                             const RigidTransform& T, const Eigen::Vector3d& inward,
                             double current_thickness, const OpeningRegistrationParams& p,
                             double* similarity) {
  const double cos_tol = std::cos(p.planes.clustering.angle_tolerance_deg * M_PI / 180.0);
  std::vector<double> shifts;
  std::vector<PlanarPolygon> src_planes, tgt_planes;
  for (const auto& pt : target.planes)
    if (std::abs(pt.normal.dot(inward)) >= cos_tol) tgt_planes.push_back(pt);
  for (const auto& ps : source.planes) {
    if (std::abs((T.rotation() * ps.normal).dot(inward)) < cos_tol) continue;
    src_planes.push_back(ps);
    for (const auto& pt : tgt_planes) {
      const double shift = inward.dot(pt.centroid - T.apply(ps.centroid));
      // A plausible positive thickness (at least d): excludes the indoor wall face on the
      // façade face itself, the zero-thickness placement this step replaces.
      const double th = current_thickness + shift;
      if (th >= p.distance.robust_distance && th <= p.max_wall_thickness) shifts.push_back(shift);
    }
  }
  std::sort(shifts.begin(), shifts.end());
  double best = std::nan(""), best_sim = 0.0;
  for (double s : shifts) {
    const RigidTransform Ts(T.rotation(), T.translation() + s * inward);
    const double sim = planeSimilarity(src_planes, tgt_planes, Ts, p.planes);
    if (sim > best_sim) {
      best_sim = sim;
      best = s;
    }
  }
  *similarity = best_sim;
  return best;
}

/// Distinct façade orientations among matched edges (normals more than 30° apart).
int matchedDirections(const ThickScore& s) {
  std::vector<Eigen::Vector3d> dirs;
  for (const auto& m : s.matches) {
    if (m.similarity < 0.5) continue;
    bool known = false;
    for (const auto& d : dirs)
      if (std::abs(d.dot(m.facade_normal)) > std::cos(M_PI / 6)) known = true;
    if (!known) dirs.push_back(m.facade_normal);
  }
  return int(dirs.size());
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

using openings_detail::Base;

/// The openings of both sides and what every step shares.
struct OpeningContext {
  const FeatureSet& source;
  const FeatureSet& target;
  const OpeningRegistrationParams& p;
  std::vector<OrientedOpening> src, tgt;
  const ThickOpeningMatcher& matcher;
};

/// Hypotheses of one base (2023 §III-B): its zero-thickness placement, moved along the
/// façade normal by each wall thickness candidate (or by the assumed thickness).
void addBaseHypotheses(const OpeningContext& c, const Base& base,
                       const openings_detail::ThicknessSearch& search, HypothesisRanking& ranking) {
  const OrientedOpening& s = c.src[base.s];
  const OrientedOpening& t = c.tgt[base.t];
  const Opening& os = c.source.openings[s.index];
  const Opening& ot = c.target.openings[t.index];
  if (std::abs(s.width - t.width) > 2 * search.d) return;  // not the same opening
  const RigidTransform T0 = openings_detail::zeroThicknessPlacement(s, os, t, ot, base.pairing);
  // The third DOF (along the façade normal n): the paper intersects two indoor planes
  // perpendicular to the façade with the wall and the façade (zero thickness). Here an
  // opening on a perpendicular wall and a facing target opening at the same height and of the
  // same width give the shift directly: its in-plane horizontal position is along n. The
  // source must end up behind the façade face: thickness in [-d, max_wall_thickness].
  const Eigen::Vector3d n = t.normal;
  std::vector<double> thicknesses = openings_detail::thicknessCandidates(c.src, c.tgt, T0, n, search);
  const bool measured = !thicknesses.empty();
  if (!measured) thicknesses.push_back(c.p.assumed_wall_thickness);
  for (double th : thicknesses) {
    const RigidTransform T(T0.rotation(), T0.translation() - th * n);
    const std::string label = "opening " + std::to_string(s.index) + " -> " +
                              std::to_string(t.index) + (measured ? ", normal DOF from a perpendicular opening"
                                                                   : ", normal DOF assumed");
    ranking.add({T, c.matcher.score(c.src, T).score, label});
  }
}

/// Scores every base hypothesis (all of them, or `max_hypotheses` drawn with `seed`).
HypothesisRanking rankHypotheses(const OpeningContext& c, std::uint64_t seed, Progress* progress) {
  const auto& p = c.p;
  const openings_detail::ThicknessSearch search{
      p.distance.robust_distance, std::cos(p.distance.max_angle_deg * M_PI / 180.0),
      std::sin(p.vertical_tolerance_deg * M_PI / 180.0), p.max_wall_thickness};
  // Base hypotheses (2023 §III-B): a source opening's wall onto a target opening's façade,
  // one bottom corner onto the other. Indoor openings face into the room, outdoor ones out
  // of the building, so the normals are paired opposite (one rotation, not both signs), and
  // the indoor bottom-left corner (seen from inside) is the outdoor bottom-right one.
  const std::vector<Base> bases =
      openings_detail::baseHypotheses(c.src.size(), c.tgt.size(), p.max_hypotheses, seed);
  HypothesisRanking ranking(2.0, std::max(0.3, 3 * search.d));
  for (std::size_t h = 0; h < bases.size(); ++h) {
    if (h % 128 == 0) {
      checkCanceled(progress);
      reportProgress(progress, 0.8 * double(h) / bases.size(), "openings: hypotheses");
    }
    addBaseHypotheses(c, bases[h], search, ranking);
  }
  return ranking;
}

/// Polishes the translation on every matched edge (thickness free), the runner-up too so
/// the gap compares like with like; the result turns ambiguous when the gap closes.
ThickScore polishBest(const OpeningContext& c, GlobalRegistrationResult& r) {
  double rms = 0.0;
  const RigidTransform T = c.matcher.polish(c.src, r.transform, 5, &rms);
  ThickScore fin = c.matcher.score(c.src, T, true);
  r.transform = T;
  r.score = fin.score;
  if (r.runner_up) {
    r.runner_up->transform = c.matcher.polish(c.src, r.runner_up->transform, 5);
    r.runner_up->score = c.matcher.score(c.src, r.runner_up->transform).score;
    r.relative_gap = r.score > 0 ? (r.score - r.runner_up->score) / r.score : 0.0;
    if (r.ok() && r.relative_gap < c.p.min_relative_gap) {
      r.status = RegistrationStatus::Ambiguous;
      std::ostringstream m;
      m << "two different transforms score almost the same after polishing (" << r.score
        << " vs " << r.runner_up->score << " " << r.score_unit << ", gap "
        << 100.0 * r.relative_gap << "%): the façades are too regular or openings are missing";
      r.message = m.str();
    }
  }
  r.inlier_features = std::size_t(fin.matched_openings);
  r.feature_rms = rms;
  return fin;
}

/// The façade-normal DOF is measured when matched openings lie on two non-parallel façades;
/// else planes parallel to the main façade (interior walls seen through windows) may measure
/// it, and move r.transform (rescoring `fin`). Returns whether it is measured.
bool measureNormalDof(const OpeningContext& c, GlobalRegistrationResult& r, ThickScore& fin,
                      double* plane_sim) {
  if (matchedDirections(fin) >= 2) return true;
  if (!r.ok() || fin.matches.empty()) return false;
  // Fall back to planes parallel to the main façade (interior walls seen through windows).
  const Eigen::Vector3d inward = -fin.matches.front().facade_normal;
  const RigidTransform& T = r.transform;
  const double shift =
      normalShiftFromPlanes(c.source, c.target, T, inward, median(fin.thickness), c.p, plane_sim);
  if (std::isnan(shift)) return false;
  r.transform = RigidTransform(T.rotation(), T.translation() + shift * inward);
  fin = c.matcher.score(c.src, r.transform, true);
  return true;
}

/// Wall thickness figures and the message saying whether it was measured (failing instead
/// of guessing when the parameters require it).
void reportThickness(const ThickScore& fin, bool measured, double plane_sim,
                     const OpeningRegistrationParams& p, GlobalRegistrationResult& r) {
  const double thickness = median(fin.thickness);
  r.wall_thickness = thickness;
  r.wall_thickness_measured = measured;
  r.figures.push_back({"wall thickness (m)", thickness});
  r.figures.push_back({"wall thickness measured", measured ? 1.0 : 0.0});
  r.figures.push_back({"matched openings", double(fin.matched_openings)});
  r.figures.push_back({"façade directions with matched openings", double(matchedDirections(fin))});
  if (plane_sim > 0) r.figures.push_back({"normal-DOF plane similarity (m^2)", plane_sim});
  std::ostringstream msg;
  msg << "openings: " << r.message << "; wall thickness " << thickness << " m "
      << (measured ? "measured (openings matched on non-parallel façades, or planes seen "
                     "through the openings)"
                   : "ASSUMED (openings matched on one façade only and no plane parallel to it "
                     "seen from both sides): the translation along the façade normal is not "
                     "measured");
  r.message = msg.str();
  if (!measured && p.require_measured_thickness && r.ok()) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message += ". Failing instead of guessing (require-thickness)";
  }
}

}  // namespace

GlobalRegistrationResult registerOpenings(const FeatureSet& source, const FeatureSet& target,
                                          const OpeningRegistrationParams& p,
                                          std::uint64_t seed, Progress* progress) {
  GlobalRegistrationResult r;
  r.method = "openings";
  r.score_unit = "matched opening edges";
  r.source_features = source.openings.size();
  r.target_features = target.openings.size();
  auto src = orientedOpenings(source, p.vertical_tolerance_deg);
  auto tgt = orientedOpenings(target, p.vertical_tolerance_deg);
  if (src.empty() || tgt.empty()) {
    r.status = RegistrationStatus::TooFewFeatures;
    r.message = "openings: need openings on vertical walls in both datasets (source has " +
                std::to_string(src.size()) + ", target " + std::to_string(tgt.size()) + ")";
    return r;
  }
  const ThickOpeningMatcher matcher(tgt, p.distance, p.max_wall_thickness, p.distance.max_angle_deg);
  const OpeningContext c{source, target, p, std::move(src), std::move(tgt), matcher};
  const HypothesisRanking ranking = rankHypotheses(c, seed, progress);
  finalizeFromRanking(ranking, p.min_matched_segments, p.min_relative_gap, r);
  if (!ranking.best()) return r;
  ThickScore fin = polishBest(c, r);
  double plane_sim = 0.0;
  const bool measured = measureNormalDof(c, r, fin, &plane_sim);
  reportThickness(fin, measured, plane_sim, p, r);
  reportProgress(progress, 1.0, "openings: done");
  return r;
}

}  // namespace plumb
