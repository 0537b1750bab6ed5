#include "registration/planes/plane_registration.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <sstream>

#include "registration/planes/plane_hypotheses.hpp"
#include "registration/planes/polygon_raster.hpp"

namespace plumb {

const ParamSchema<PlaneRegistrationParams>& PlaneRegistrationParams::schema() {
  using P = PlaneRegistrationParams;
  static const auto s =
      ParamSchema<P>("planes")
          .real(&P::distance_threshold, "plane-distance", "Plane distance threshold", "m", 0.005,
                5.0, "How far apart two matched planes may lie and still count as overlapping\n"
                "(d_thr of the polygon overlap similarity, 2021 eq. 10)")
          .boolean(&P::oriented_normals, "oriented-normals", "Oriented normals",
                   "Normals face the scanner in both datasets: match only same-facing planes")
          .integer(&P::modes_per_association, "offset-modes", "Offset modes", "", 1, 50,
                   "Candidate offsets kept per cluster association", true)
          .real(&P::min_conditioning, "min-conditioning", "Min conditioning", "", 0.0, 1.0,
                "Reject translations from nearly dependent plane normals", true)
          .real(&P::min_polygon_area, "min-polygon-area", "Min polygon area", "m^2", 0.0, 100.0,
                "Smaller polygons are ignored")
          .integer(&P::raster_cells, "raster-cells", "Raster cells", "", 16, 4096,
                   "Polygon raster resolution for overlap areas", true)
          .real(&P::min_score, "min-score", "Min score", "m^2", 0.0, 1e6,
                "Acceptance threshold on the overlap similarity")
          .real(&P::min_relative_gap, "min-gap", "Min score gap", "", 0.0, 1.0,
                "Runner-up must score this fraction below the best, else ambiguous")
          .integer(&P::rescored_hypotheses, "rescored", "Rescored hypotheses", "", 1, 100000,
                   "Best pre-scored hypotheses scored with full overlap accuracy", true)
          .integer(&P::polish_iterations, "polish-iterations", "Polish iterations", "", 0, 50,
                   "Least-squares polish on matched polygon pairs", true)
          .nested(&P::clustering, DirectionClusteringParams::schema())
          .nested(&P::rotations, RotationEnumerationParams::schema());
  return s;
}

namespace {

struct Prepared {
  std::vector<const PlanarPolygon*> polys;
  std::vector<std::unique_ptr<PolygonRaster>> rasters;
};

Prepared prepare(const std::vector<PlanarPolygon>& in, const PlaneRegistrationParams& p) {
  Prepared out;
  for (const auto& pl : in) {
    if (pl.rings.empty() || pl.area < p.min_polygon_area || !pl.normal.allFinite()) continue;
    out.polys.push_back(&pl);
    out.rasters.push_back(std::make_unique<PolygonRaster>(pl, p.raster_cells, 1500));
  }
  return out;
}

std::vector<PlanarPolygon> collect(const Prepared& pr) {
  std::vector<PlanarPolygon> v;
  for (auto* q : pr.polys) v.push_back(*q);
  return v;
}

/// Eq. 10 as a similarity, with the bisector-plane distance of eq. 7; also lists matches.
struct PairMatch {
  int s, t;
  double weight;  ///< overlap * (d^2 - D^2) / d^2
  int sign;       ///< sign of (R n_s)·n_t
};

double similarity(const Prepared& src, const Prepared& tgt, const RigidTransform& T,
                  double d_thr, double cos_tol, bool oriented, std::vector<PairMatch>* matches,
                  bool coarse = false) {
  const double d2 = d_thr * d_thr;
  double score = 0.0;
  for (std::size_t i = 0; i < src.polys.size(); ++i) {
    const auto& ps = *src.polys[i];
    const Eigen::Vector3d n1 = T.rotation() * ps.normal;
    const Eigen::Vector3d g1 = T.apply(ps.centroid);
    const double off1 = n1.dot(g1);
    const Eigen::Vector3d c1 = T.apply(src.rasters[i]->centre());
    for (std::size_t j = 0; j < tgt.polys.size(); ++j) {
      const auto& pt = *tgt.polys[j];
      const double dot = n1.dot(pt.normal);
      if ((oriented ? dot : std::abs(dot)) < cos_tol) continue;
      const double s = dot >= 0 ? 1.0 : -1.0;
      // Bisector plane through the intersection line: normal n1 + s n2 (eq. 7).
      Eigen::Vector3d nb = n1 + s * pt.normal;
      const double nn = nb.norm();
      nb /= nn;
      const double db = (off1 + s * pt.offset) / nn;
      const double dist = std::abs(nb.dot(g1) - db) + std::abs(nb.dot(pt.centroid) - db);
      if (dist >= d_thr) continue;
      if ((c1 - tgt.rasters[j]->centre()).norm() >
          src.rasters[i]->radius() + tgt.rasters[j]->radius())
        continue;
      const double overlap = overlapArea(*src.rasters[i], *tgt.rasters[j], T, coarse);
      if (overlap <= 0) continue;
      const double w = overlap * (d2 - dist * dist) / d2;  // eq. 10 term
      score += w;
      if (matches) matches->push_back({int(i), int(j), w, int(s)});
    }
  }
  return score;
}

struct OffsetMode {
  double offset;   ///< component of t along the association direction
  int s, t;        ///< representative pair
  double support;
};

/// Strongest offset modes of one association: each pair (i, j) asks n'·t = s d_j - d_i (eq. 21
/// with the sign from n' = R n, d' = d + n'·t), expressed along the cluster direction c.
std::vector<OffsetMode> offsetModes(const Prepared& src, const std::vector<int>& src_members,
                                    const Prepared& tgt, const std::vector<int>& tgt_members,
                                    const Eigen::Matrix3d& R, const Eigen::Vector3d& c,
                                    double d_thr, int max_modes, bool oriented) {
  struct Cand {
    double off, w;
    int s, t;
  };
  std::vector<Cand> cands;
  for (int i : src_members) {
    const auto& ps = *src.polys[i];
    const Eigen::Vector3d n1 = R * ps.normal;
    const double a = n1.dot(c) >= 0 ? 1.0 : -1.0;  // express along c
    for (int j : tgt_members) {
      const auto& pt = *tgt.polys[j];
      const double s = n1.dot(pt.normal) >= 0 ? 1.0 : -1.0;
      if (oriented && s < 0) continue;
      cands.push_back({a * (s * pt.offset - ps.offset), std::min(ps.area, pt.area), i, j});
    }
  }
  std::sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) {
    return x.off < y.off || (x.off == y.off && (x.s < y.s || (x.s == y.s && x.t < y.t)));
  });
  // Window support (sum of weights within d_thr), by a sliding window.
  std::vector<double> support(cands.size(), 0.0);
  std::size_t lo = 0, hi = 0;
  double sum = 0.0;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    while (hi < cands.size() && cands[hi].off <= cands[k].off + d_thr) sum += cands[hi++].w;
    while (cands[lo].off < cands[k].off - d_thr) sum -= cands[lo++].w;
    support[k] = sum;
  }
  std::vector<std::size_t> order(cands.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return support[x] > support[y] || (support[x] == support[y] && cands[x].w > cands[y].w);
  });
  std::vector<OffsetMode> modes;
  for (std::size_t k : order) {
    if (int(modes.size()) >= max_modes) break;
    bool near = false;
    for (const auto& m : modes)
      if (std::abs(m.offset - cands[k].off) < 2 * d_thr) near = true;
    if (near) continue;
    modes.push_back({cands[k].off, cands[k].s, cands[k].t, support[k]});
  }
  return modes;
}

/// Least squares on matched pairs: rotation from the sign-aligned normals (weighted Kabsch),
/// then translation from every pair's eq. 21 row.
RigidTransform polish(const Prepared& src, const Prepared& tgt, const RigidTransform& T,
                      const std::vector<PairMatch>& m) {
  if (m.size() < 3) return T;
  std::vector<Eigen::Vector3d> a, b;
  std::vector<double> w;
  for (const auto& k : m) {
    a.push_back(src.polys[k.s]->normal);
    b.push_back(k.sign * tgt.polys[k.t]->normal);
    w.push_back(k.weight);
  }
  const Eigen::Matrix3d R = fitRotation(a, b, w);
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (const auto& k : m) {
    const auto& ps = *src.polys[k.s];
    const auto& pt = *tgt.polys[k.t];
    // Point-to-plane on the source centroid: n_t·(R g + t) = d_t  (uses the target normal so
    // a slightly tilted pair does not bias the offset).
    const Eigen::Vector3d n = pt.normal;
    const double rhs = pt.offset - n.dot(R * ps.centroid);
    ata += k.weight * n * n.transpose();
    atb += k.weight * n * rhs;
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(ata);
  if (svd.singularValues()(2) < 1e-6 * svd.singularValues()(0)) return T;
  return RigidTransform(R, ata.ldlt().solve(atb));
}

}  // namespace

void orientTowards(std::vector<PlanarPolygon>& planes, const Eigen::Vector3d& viewpoint) {
  for (auto& pl : planes) {
    if (pl.normal.dot(viewpoint - pl.centroid) >= 0) continue;
    // Flip n and d, and swap u/v so (u, v, n) stays right-handed; rings are mirrored.
    pl.normal = -pl.normal;
    pl.offset = -pl.offset;
    std::swap(pl.u_axis, pl.v_axis);
    for (auto& ring : pl.rings) {
      for (auto& q : ring) q = Eigen::Vector2d(q.y(), q.x());
      std::reverse(ring.begin(), ring.end());
    }
  }
}

double planeSimilarity(const std::vector<PlanarPolygon>& source,
                       const std::vector<PlanarPolygon>& target, const RigidTransform& t,
                       const PlaneRegistrationParams& p) {
  const Prepared src = prepare(source, p);
  const Prepared tgt = prepare(target, p);
  return similarity(src, tgt, t, p.distance_threshold,
                    std::cos(p.clustering.angle_tolerance_deg * M_PI / 180.0),
                    p.oriented_normals, nullptr);
}

namespace planes_registration_detail {

Associations independentAssociations(const DirectionClusteringResult& cs,
                                     const RotationCandidate& rot) {
  Associations out;
  std::vector<int>& chosen = out.clusters;
  std::vector<Eigen::Vector3d>& dirs = out.directions;
  for (std::size_t k = 0; k < cs.clusters.size(); ++k) {
    if (rot.target_of_source[k] < 0) continue;
    const Eigen::Vector3d c = rot.rotation * cs.clusters[k].direction;
    if (chosen.size() == 1 && std::abs(c.dot(dirs[0])) > std::cos(M_PI / 6)) continue;
    if (chosen.size() == 2 &&
        std::abs(c.dot(dirs[0].cross(dirs[1]).normalized())) < std::sin(M_PI / 6))
      continue;
    if (chosen.size() < 3) {
      chosen.push_back(int(k));
      dirs.push_back(c);
    }
  }
  return out;
}

std::optional<Eigen::Vector3d> solveTranslation(const Eigen::Matrix3d& N, const Eigen::Vector3d& rhs,
                                                double min_conditioning) {
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(N, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto sv = svd.singularValues();
  if (sv(2) < min_conditioning * sv(0)) return std::nullopt;
  return Eigen::Vector3d(svd.solve(rhs));
}

}  // namespace planes_registration_detail

namespace {

using planes_registration_detail::Associations;

/// Eq. 10 (similarity) between the prepared polygons of both sides under a transform.
struct Scorer {
  const Prepared& src;
  const Prepared& tgt;
  double d_thr, cos_tol;
  bool oriented;
  double operator()(const RigidTransform& T, std::vector<PairMatch>* matches = nullptr,
                    bool coarse = false) const {
    return similarity(src, tgt, T, d_thr, cos_tol, oriented, matches, coarse);
  }
};

/// Explains why the inputs cannot determine a transform (too few polygons or normal
/// directions); false then.
bool enoughPolygons(const Prepared& src, const Prepared& tgt, const PlaneRegistrationParams& p,
                    GlobalRegistrationResult& r) {
  if (src.polys.size() >= 3 && tgt.polys.size() >= 3) return true;
  r.status = RegistrationStatus::TooFewFeatures;
  r.message = "planes: need at least 3 polygons larger than " +
              std::to_string(p.min_polygon_area) + " m^2 in each dataset (source has " +
              std::to_string(src.polys.size()) + ", target " + std::to_string(tgt.polys.size()) +
              ")";
  return false;
}

bool enoughDirections(const DirectionClusteringResult& cs, const DirectionClusteringResult& ct,
                      GlobalRegistrationResult& r) {
  if (cs.clusters.size() >= 3 && ct.clusters.size() >= 3) return true;  // 3 independent normals
  r.status = RegistrationStatus::TooFewFeatures;
  r.message = "planes: the polygons span fewer than three normal directions (source " +
              std::to_string(cs.clusters.size()) + ", target " +
              std::to_string(ct.clusters.size()) +
              "), so the translation is not determined by planes";
  return false;
}

/// Eq. 22 from the three representative pairs of offset modes; nothing when ill-conditioned.
std::optional<Eigen::Vector3d> translationOf(const Prepared& src, const Prepared& tgt,
                                             const Eigen::Matrix3d& R,
                                             const std::array<const OffsetMode*, 3>& modes,
                                             double min_conditioning) {
  Eigen::Matrix3d N;
  Eigen::Vector3d rhs;
  int row = 0;
  for (const OffsetMode* m : modes) {
    const auto& ps = *src.polys[m->s];
    const auto& pt = *tgt.polys[m->t];
    const Eigen::Vector3d n1 = R * ps.normal;
    const double s = n1.dot(pt.normal) >= 0 ? 1.0 : -1.0;
    N.row(row) = n1.transpose();
    rhs(row) = s * pt.offset - ps.offset;  // eq. 21, sign-corrected
    ++row;
  }
  return planes_registration_detail::solveTranslation(N, rhs, min_conditioning);
}

/// The clusters of both sides and the parameters every hypothesis step shares.
struct HypothesisContext {
  const Scorer& score;
  const DirectionClusteringResult& cs;
  const DirectionClusteringResult& ct;
  const PlaneRegistrationParams& p;
};

/// Hypotheses of one rotation, pre-scored with coarse overlap samples (stage 1): offset
/// modes of three independent associations, every triple of modes solved by eq. 22.
void prescoreRotation(const HypothesisContext& c, const RotationCandidate& rot,
                      std::vector<Hypothesis>& prescored, std::size_t& ill_conditioned) {
  const Prepared& src = c.score.src;
  const Prepared& tgt = c.score.tgt;
  const auto& p = c.p;
  // Three associations with independent directions: the heaviest matched cluster, the
  // heaviest one at least 30° from it, and the heaviest one best out of their plane.
  const Associations a = planes_registration_detail::independentAssociations(c.cs, rot);
  std::vector<std::vector<OffsetMode>> modes;
  for (std::size_t q = 0; q < a.clusters.size(); ++q) {
    const int k = a.clusters[q];
    modes.push_back(offsetModes(src, c.cs.clusters[k].members, tgt,
                                c.ct.clusters[rot.target_of_source[k]].members, rot.rotation,
                                a.directions[q], p.distance_threshold, p.modes_per_association,
                                p.oriented_normals));
  }
  if (modes.size() < 3) return;
  for (const auto& m0 : modes[0])
    for (const auto& m1 : modes[1])
      for (const auto& m2 : modes[2]) {
        const auto t = translationOf(src, tgt, rot.rotation, {&m0, &m1, &m2}, p.min_conditioning);
        if (!t) {
          ++ill_conditioned;
          continue;
        }
        const RigidTransform T(rot.rotation, *t);
        // Stage 1: eq. 10 with coarse overlap samples.
        prescored.push_back({T, c.score(T, nullptr, true), rot.label});
      }
}

/// Stage 2: eq. 10 with full overlap samples on the best pre-scored hypotheses.
HypothesisRanking rescoreBest(const Scorer& score, std::vector<Hypothesis> prescored,
                              const PlaneRegistrationParams& p) {
  HypothesisRanking ranking(2.0, std::max(0.3, 5 * p.distance_threshold));
  std::stable_sort(prescored.begin(), prescored.end(),
                   [](const Hypothesis& a, const Hypothesis& b) { return a.score > b.score; });
  if (prescored.size() > std::size_t(p.rescored_hypotheses)) prescored.resize(p.rescored_hypotheses);
  for (auto& h : prescored) {
    h.score = score(h.transform);
    ranking.add(h);
  }
  return ranking;
}

/// Least-squares polish on the matched pairs while it keeps the score (within 0.1%).
RigidTransform polishOnMatches(const Scorer& score, RigidTransform T, int iterations,
                               double best_score) {
  for (int it = 0; it < iterations; ++it) {
    std::vector<PairMatch> m;
    score(T, &m);
    const RigidTransform U = polish(score.src, score.tgt, T, m);
    if (score(U) < best_score * 0.999) break;
    T = U;
  }
  return T;
}

/// Score, matched source polygons and plane RMS (eq. 21 residuals) of the final transform.
void measureFinal(const Scorer& score, const RigidTransform& T, GlobalRegistrationResult& r) {
  std::vector<PairMatch> m;
  r.score = score(T, &m);
  r.transform = T;
  std::vector<bool> matched(score.src.polys.size(), false);
  double sq = 0.0, wsum = 0.0;
  for (const auto& k : m) {
    matched[k.s] = true;
    const double e = score.tgt.polys[k.t]->normal.dot(T.apply(score.src.polys[k.s]->centroid)) -
                     score.tgt.polys[k.t]->offset;
    sq += k.weight * e * e;
    wsum += k.weight;
  }
  r.inlier_features = std::count(matched.begin(), matched.end(), true);
  r.feature_rms = wsum > 0 ? std::sqrt(sq / wsum) : 0.0;
  if (r.runner_up && r.score > 0) r.relative_gap = (r.score - r.runner_up->score) / r.score;
}

}  // namespace

GlobalRegistrationResult registerPlanes(const std::vector<PlanarPolygon>& source_in,
                                        const std::vector<PlanarPolygon>& target_in,
                                        const PlaneRegistrationParams& p, Progress* progress) {
  GlobalRegistrationResult r;
  r.method = "planes";
  r.score_unit = "m^2 of matched polygon overlap";
  r.source_features = source_in.size();
  r.target_features = target_in.size();
  reportProgress(progress, 0.0, "planes: rasterising polygons");
  const Prepared src = prepare(source_in, p);
  const Prepared tgt = prepare(target_in, p);
  if (!enoughPolygons(src, tgt, p, r)) return r;
  const auto cs = clusterPlaneNormals(collect(src), p.clustering);
  const auto ct = clusterPlaneNormals(collect(tgt), p.clustering);
  if (!enoughDirections(cs, ct, r)) return r;
  RotationEnumerationParams rp = p.rotations;
  rp.angle_tolerance_deg = p.clustering.angle_tolerance_deg;
  const auto rotations = enumerateRotations(cs.directions(), ct.directions(), rp);
  const Scorer score{src, tgt, p.distance_threshold,
                     std::cos(p.clustering.angle_tolerance_deg * M_PI / 180.0), p.oriented_normals};
  const HypothesisContext context{score, cs, ct, p};
  std::size_t ill_conditioned = 0;
  std::vector<Hypothesis> prescored;
  for (std::size_t ri = 0; ri < rotations.size(); ++ri) {
    checkCanceled(progress);
    reportProgress(progress, 0.05 + 0.85 * double(ri) / std::max<std::size_t>(1, rotations.size()),
                   "planes: scoring hypotheses");
    prescoreRotation(context, rotations[ri], prescored, ill_conditioned);
  }
  const HypothesisRanking ranking = rescoreBest(score, std::move(prescored), p);
  finalizeFromRanking(ranking, p.min_score, p.min_relative_gap, r);
  if (ranking.best())
    measureFinal(score, polishOnMatches(score, r.transform, p.polish_iterations, r.score), r);
  if (ill_conditioned) r.figures.push_back({"ill-conditioned triples rejected", double(ill_conditioned)});
  r.message = "planes: " + r.message;
  reportProgress(progress, 1.0, "planes: done");
  return r;
}

}  // namespace plumb
