#include "registration/auto/candidate_refinement.hpp"

#include <sstream>

namespace plumb {

const ParamSchema<CandidateParams>& CandidateParams::schema() {
  using P = CandidateParams;
  static const auto s =
      ParamSchema<P>("candidates")
          .boolean(&P::refine_runner_up, "refine-runner-up", "Refine the runner-up",
                   "Refine the global step's runner-up too and compare the refined fits "
                   "(off: an ambiguous global step fails)")
          .real(&P::same_rotation_deg, "same-rotation", "Same placement rotation", "deg", 0.01,
                5.0, "Refined placements closer than this (and the shift below) are one answer",
                true)
          .real(&P::same_translation, "same-shift", "Same placement shift", "m", 0.001, 1.0,
                "Displacement at the data centroid below which refined placements are one answer",
                true)
          .real(&P::min_overlap_gap, "overlap-gap", "Clear overlap gap", "", 0.0, 1.0,
                "A placement is clearly worse when its refined overlap is lower by this", true)
          .real(&P::near_overlap_gap, "near-overlap-gap", "Near-whole overlap gap", "", 0.0, 1.0,
                "Or lower by this ...", true)
          .real(&P::min_unexplained_ratio, "unexplained-ratio", "Clear unexplained ratio", "",
                1.0, 100.0, "... and it leaves this many times more points unexplained", true)
          .real(&P::near_whole_overlap, "near-whole", "Near-whole fit", "", 0.0, 1.0,
                "From this overlap of the better placement, the overlap gap counts only when "
                "the structure (points on large planes) agrees ...", true)
          .real(&P::min_structure_gap, "structure-gap", "Structure gap", "", 0.0, 1.0,
                "... explaining at least this much less of it ...", true)
          .real(&P::min_structure_ratio, "structure-ratio", "Structure unexplained ratio", "",
                1.0, 100.0, "... and leaving this many times more of it unexplained", true)
          .real(&P::min_cost_gap, "cost-gap", "Clear fit cost gap", "", 0.0, 1.0,
                "Or: its refined fit cost is higher by this ...", true)
          .real(&P::min_cost_ratio, "cost-ratio", "Clear fit cost ratio", "", 1.0, 100.0,
                "... and this many times the other's", true)
          .real(&P::decisive_unexplained_ratio, "decisive-unexplained-ratio",
                "Decisive unexplained ratio", "", 1.0, 1000.0,
                "A placement overrules the features when it leaves this many times fewer points "
                "unexplained than their choice ...", true)
          .real(&P::decisive_cost_ratio, "decisive-cost-ratio", "Decisive fit cost ratio", "",
                1.0, 1000.0, "... and its fit cost is this many times lower", true)
          .integer(&P::max_alternatives, "alternatives", "Further hypotheses refined", "", 0, 4,
                   "Distinct hypotheses beyond the runner-up refined and compared too (a "
                   "repeated room's other copy may score low on features)", true)
          .real(&P::alternative_min_score, "alternative-score", "Further hypothesis score", "",
                0.0, 1.0, "... when their feature score is at least this fraction of the best's",
                true)
          .real(&P::elsewhere_volume_ratio, "elsewhere-volume-ratio", "Search elsewhere from",
                "", 1.0, 1000.0,
                "Search again away from the chosen placement when the target spans this many "
                "times the source's volume (room for a repeated room or storey)", true)
          .real(&P::elsewhere_margin, "elsewhere-margin", "Set-aside margin", "m", 0.0, 5.0,
                "Target features this close to the placed source are set aside for that search",
                true)
          .integer(&P::elsewhere_peak_factor, "elsewhere-peak-factor", "Elsewhere peak factor",
                   "", 1, 10,
                   "That search examines this many times the translation peaks per rotation "
                   "(segments)", true)
          .boolean(&P::copy_search, "copy-search", "Search for copies",
                   "Search the target for copies of the placed source (a repeated room, the "
                   "other unit, an identical storey) and compare each with the chosen placement",
                   true)
          .real(&P::copy_cell, "copy-cell", "Copy search cell", "m", 0.05, 2.0,
                "Grid cell and shift step of that search", true)
          .real(&P::copy_min_fraction, "copy-fraction", "Copy fraction", "", 0.5, 1.0,
                "A shift is a copy when it explains this fraction of what the chosen "
                "placement explains", true)
          .integer(&P::copy_max, "copy-max", "Copies compared", "", 0, 8,
                   "Copies refined and compared at most, best first", true)
          .integer(&P::copy_rounds, "copy-rounds", "Copy search rounds", "", 0, 4,
                   "Search the copies of the chosen placement again when it is not the one "
                   "searched around, up to this many times", true);
  return s;
}

const char* const kRuledOutRole = "ruled out by free space";

const char* toString(CandidateRelation r) {
  switch (r) {
    case CandidateRelation::Same: return "same placement";
    case CandidateRelation::FirstClearlyBetter: return "first clearly better";
    case CandidateRelation::SecondClearlyBetter: return "second clearly better";
    case CandidateRelation::Close: return "close";
  }
  return "?";
}

namespace {
bool lostOverlap(const RefineResult& r) { return r.inliers < 10; }

/// `x` leaves clearly more of the source's structure unexplained than `y`; true when the
/// structure was not measured (nothing to contradict the overall overlap).
bool structureAgrees(const RefineResult& x, const RefineResult& y, const CandidateParams& p) {
  if (x.structure_overlap < 0 || y.structure_overlap < 0) return true;
  return y.structure_overlap - x.structure_overlap >= p.min_structure_gap &&
         (1.0 - x.structure_overlap) >= p.min_structure_ratio * (1.0 - y.structure_overlap);
}

/// `x` fits clearly worse than `y`: clearly fewer points explained, or a clearly higher cost.
/// A near-whole absolute gap counts only when the structure agrees (structure_overlap.hpp).
bool clearlyWorse(const RefineResult& x, const RefineResult& y, const CandidateParams& p) {
  if (lostOverlap(x) && !lostOverlap(y)) return true;
  const double gap = y.overlap - x.overlap;
  const bool near_whole = y.overlap >= p.near_whole_overlap;
  const bool by_gap = gap >= p.min_overlap_gap && (!near_whole || structureAgrees(x, y, p));
  const bool overlap = by_gap ||
                       (gap >= p.near_overlap_gap &&
                        (1.0 - x.overlap) >= p.min_unexplained_ratio * (1.0 - y.overlap));
  const bool cost = x.fit_cost - y.fit_cost >= p.min_cost_gap &&
                    x.fit_cost >= p.min_cost_ratio * y.fit_cost;
  return overlap || cost;
}
}  // namespace

CandidateRelation compareRefined(const RefineResult& a, const RefineResult& b,
                                 const Eigen::Vector3d& centroid, const CandidateParams& p) {
  const double rot = RigidTransform::rotationErrorDeg(a.transform, b.transform);
  const double shift = (a.transform.apply(centroid) - b.transform.apply(centroid)).norm();
  if (rot <= p.same_rotation_deg && shift <= p.same_translation) return CandidateRelation::Same;
  if (clearlyWorse(b, a, p)) return CandidateRelation::FirstClearlyBetter;
  if (clearlyWorse(a, b, p)) return CandidateRelation::SecondClearlyBetter;
  return CandidateRelation::Close;
}

PlacementCandidate makeCandidate(const Hypothesis& h, const RefineResult* r, std::string role) {
  PlacementCandidate c;
  c.role = std::move(role);
  c.label = h.label;
  c.transform = r ? r->transform : h.transform;
  c.feature_score = h.score;
  if (r) {
    c.refined = true;
    c.overlap = r->overlap;
    c.point_rms = r->rms;
    c.inliers = r->inliers;
    c.fit_cost = r->fit_cost;
    if (r->structure_overlap >= 0) c.figures.push_back({"structure overlap", r->structure_overlap});
  }
  return c;
}

namespace {
bool isRuledOut(const std::vector<bool>& ruled_out, std::size_t i) {
  return i < ruled_out.size() && ruled_out[i];
}

/// `x` fits decisively better than `y`: far fewer points unexplained and a far lower fit cost
/// (CandidateParams::decisive_*), enough to overrule the features' choice.
bool decisivelyBetter(const RefineResult& x, const RefineResult& y, const CandidateParams& p) {
  if (lostOverlap(x)) return false;
  return (1.0 - y.overlap) >= p.decisive_unexplained_ratio * (1.0 - x.overlap) &&
         y.fit_cost >= p.decisive_cost_ratio * x.fit_cost;
}

/// The hypothesis to answer with: the first, unless the global step could not choose and
/// another one fits clearly better, or it chose and another one fits decisively better (the
/// best overlap among those). A first hypothesis that other evidence ruled out gives way to
/// the best-fitting one that fits about as well or better and was not ruled out (none: it
/// stays, and the verdict will say why it fails).
std::size_t answerIndex(const std::vector<RefinedHypothesis>& h, bool global_chose,
                        const Eigen::Vector3d& centroid, const CandidateParams& p,
                        const std::vector<bool>& ruled_out) {
  std::size_t best = 0;
  const bool first_out = isRuledOut(ruled_out, 0);
  for (std::size_t i = 1; i < h.size(); ++i) {
    if (isRuledOut(ruled_out, i)) continue;
    const CandidateRelation rel = compareRefined(h[0].refined, h[i].refined, centroid, p);
    const bool eligible =
        (global_chose && !first_out)
            ? rel == CandidateRelation::SecondClearlyBetter &&
                  decisivelyBetter(h[i].refined, h[0].refined, p)
            : rel == CandidateRelation::SecondClearlyBetter ||
                  (first_out && rel == CandidateRelation::Close);
    if (eligible && (best == 0 || h[i].refined.overlap > h[best].refined.overlap)) best = i;
  }
  return best;
}

std::string roleOf(CandidateRelation r) {
  switch (r) {
    case CandidateRelation::Same: return "same placement";
    case CandidateRelation::FirstClearlyBetter: return "worse";
    default: return "competing";
  }
}
}  // namespace

CandidateSelection selectCandidate(const std::vector<RefinedHypothesis>& h, bool global_chose,
                                   const Eigen::Vector3d& centroid, const CandidateParams& p,
                                   const std::vector<bool>& ruled_out) {
  CandidateSelection s;
  if (h.empty()) return s;
  s.chosen = answerIndex(h, global_chose, centroid, p, ruled_out);
  const RefineResult& chosen = h[s.chosen].refined;
  s.candidates.push_back(makeCandidate(h[s.chosen].hypothesis, &chosen, "chosen"));
  s.hypothesis.push_back(s.chosen);
  std::ostringstream msg;
  msg << "candidates: chosen (" << h[s.chosen].hypothesis.label << ") overlap " << chosen.overlap
      << ", RMS " << chosen.rms << " m, fit cost " << chosen.fit_cost;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (i == s.chosen) continue;
    const RefineResult& other = h[i].refined;
    const CandidateRelation rel = compareRefined(chosen, other, centroid, p);
    const std::string role = isRuledOut(ruled_out, i) ? kRuledOutRole : roleOf(rel);
    if (role == "competing") s.ambiguous = true;
    s.candidates.push_back(makeCandidate(h[i].hypothesis, &other, role));
    s.hypothesis.push_back(i);
    msg << "; " << (i == 0 ? "global answer" : i == 1 ? "runner-up" : "alternative") << " (" << h[i].hypothesis.label
        << ") refined to " << RigidTransform::rotationErrorDeg(chosen.transform, other.transform)
        << " deg / " << (chosen.transform.apply(centroid) - other.transform.apply(centroid)).norm()
        << " m from it, overlap " << other.overlap << ", RMS " << other.rms << " m, fit cost "
        << other.fit_cost << ": " << role;
  }
  if (s.chosen != 0)
    msg << (isRuledOut(ruled_out, 0) ? "; the global answer was ruled out by the free space"
            : global_chose           ? "; the refined points overruled the features: the "
                                       "chosen placement fits decisively better than their answer"
                                     : "; the refined points chose the runner-up");
  s.message = msg.str();
  return s;
}

}  // namespace plumb
