#pragma once
// Indoor/outdoor registration with openings and planes (2023 §III-B, docs/ALGORITHMS.md §6).
// Hypotheses (all enumerated, or drawn at random with the seed beyond `max_hypotheses`):
//  - the paper's façade + corner pair: a source (indoor) opening's wall onto a target
//    (outdoor) opening's façade, rotated about the vertical (scans are Z-up) so the planes
//    coincide, and one bottom corner onto the other (fixes the 2 in-plane DOF). Openings are
//    oriented by their corner order (indoor ones face into the room, outdoor ones out of the
//    building), so one normal pairing and one corner pairing per side are tried, not all four;
//  - the third DOF (along the façade normal): the paper intersects two indoor planes
//    perpendicular to the façade with the wall (A) and the façade (B) and moves by AB. p3 ∩ p4
//    is a line along the façade normal, so AB is the offset between the two planes along it:
//    zero thickness. Beyond the paper, an opening on a PERPENDICULAR wall paired with a
//    facing outdoor opening at the same height and of the same width gives this DOF directly
//    (its in-plane horizontal position is along the first façade's normal); each candidate
//    must leave the indoor wall a plausible thickness behind the façade, [-d, max].
// Score: beyond the paper's eq. 8 on zero-thickness edges (which lets one façade match at a
// time, so a regular façade ties between shifts by one window spacing or one storey), every
// source opening is matched on every façade at once, through the wall (opening_match.hpp):
// a hypothesis must fit all façades, and the openings only one storey has (an entrance door)
// break the storey tie. The best is polished (yaw + translation, eqs. 11-14 with the façade
// normal free), the runner-up too, and the gap decides ambiguity honestly.
// Wall thickness: the median offset of the matched indoor openings behind their façades,
// measured when openings match on two non-parallel façades. With one façade only, candidate
// normal shifts come from planes parallel to it (indoor walls seen through the windows in the
// outdoor scan and their indoor counterparts), scored with the polygon overlap similarity
// (2021 eq. 10), for a thickness in [d, max]. Without either, the thickness is not measured:
// `assumed_wall_thickness` is used and the result says so (or fails, `require-thickness`).

#include <cstdint>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "common/seed.hpp"
#include "model/feature_set.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/planes/plane_registration.hpp"
#include "registration/segment_distance/segment_set_distance.hpp"

namespace plumb {

struct OpeningRegistrationParams {
  SegmentDistanceParams distance;  ///< d = 0.10 m on opening edges (nested in the schema)
  /// d_thr and polygon settings for the normal DOF score; the schema nests the ones used
  /// (plane-distance, oriented-normals, min-polygon-area, raster-cells, cluster-angle).
  PlaneRegistrationParams planes;
  /// Hypotheses enumerated when there are at most this many, else drawn at random, [10, 1e7].
  int max_hypotheses = 20000;
  /// Wall thickness search range, metres, [0, 3].
  double max_wall_thickness = 1.0;
  /// Used when no plane pair measures the thickness, metres, [0, 3]. 0 = the paper.
  double assumed_wall_thickness = 0.0;
  /// Fail (rather than assume) when no plane pair measures the thickness. The translation
  /// along the façade normal would otherwise be a guess.
  bool require_measured_thickness = true;
  /// Acceptance: matched opening edges (similarity of eq. 8), [1, 1e6].
  double min_matched_segments = 4.0;
  /// Ambiguity: runner-up must score at least this fraction below the best, [0, 1].
  double min_relative_gap = 0.05;
  /// Façade verticality tolerance, degrees, [0, 45].
  double vertical_tolerance_deg = 5.0;
  static const ParamSchema<OpeningRegistrationParams>& schema();
};

/// Source = indoor features (planes, openings with their wall index), target = outdoor
/// features (façades, openings, planes of interior points seen through windows). `seed` draws
/// the hypotheses when there are more than `max_hypotheses` (deterministic for a seed; the
/// pipeline passes PipelineParams::seed).
GlobalRegistrationResult registerOpenings(const FeatureSet& source, const FeatureSet& target,
                                          const OpeningRegistrationParams& params,
                                          std::uint64_t seed = kDefaultSeed,
                                          Progress* progress = nullptr);

}  // namespace plumb
