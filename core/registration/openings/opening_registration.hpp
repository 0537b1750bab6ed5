#pragma once
// Indoor/outdoor registration with openings and planes (2023 §III-B, ALGORITHMS.md §6).
// Per hypothesis (all combinations enumerated, or drawn at random with the seed when there
// are more than `max_hypotheses`):
//  - a façade in each dataset: the wall plane of a source (indoor) opening and the façade of
//    a target (outdoor) opening; the source is rotated so the planes coincide, about their
//    intersection line (both normal signs tried);
//  - an opening corner in each (fixes the 2 in-plane DOF; bottom corners pair with bottom
//    corners, both left/right pairings tried);
//  - scored by the global robust segment distance (2023 eqs. 7-8) between opening edges with
//    the paper's zero-thickness placement, then polished on matched opening edges (eq. 14).
// The third DOF (along the façade normal): the paper intersects two indoor planes
// perpendicular to the façade with the indoor wall (A) and the outdoor façade (B) and moves by
// AB; p3 ∩ p4 is a line along the façade normal, so AB is the offset between the two planes
// along it, i.e. zero thickness. Beyond the paper, the wall thickness is estimated: candidate
// normal shifts come from pairs of planes parallel to the façade (indoor walls seen through
// the windows in the outdoor scan, and their indoor counterparts), each scored with the
// polygon overlap similarity (2021 eq. 10) of all planes; the chosen shift gives the
// thickness (distance between the indoor wall face and the outdoor façade face), reported.
// Without such planes the thickness is not measurable: `assumed_wall_thickness` is used and
// the report says the façade-normal translation is assumed, not measured.
#include <cstdint>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/planes/plane_registration.hpp"
#include "registration/segment_distance/segment_set_distance.hpp"

namespace plumb {

struct OpeningRegistrationParams {
  SegmentDistanceParams distance;  ///< d = 0.10 m on opening edges
  PlaneRegistrationParams planes;  ///< d_thr and polygon settings for the normal DOF score
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
  std::uint64_t seed = 1;
  static const ParamSchema<OpeningRegistrationParams>& schema();
};

/// Source = indoor features (planes, openings with their wall index), target = outdoor
/// features (façades, openings, planes of interior points seen through windows).
GlobalRegistrationResult registerOpenings(const FeatureSet& source, const FeatureSet& target,
                                          const OpeningRegistrationParams& params,
                                          Progress* progress = nullptr);

}  // namespace plumb
