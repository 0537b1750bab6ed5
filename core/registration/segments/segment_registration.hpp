#pragma once
// Scan-to-BIM registration with 3D segments (2023 §IV, docs/ALGORITHMS.md §7).
//  1. Direction clustering of both sets (2023 Alg. 1, one angle tolerance).
//  2. Rotations from associated cluster directions (eq. 10), enumerating every association
//     and sign (any initial pose; not only the smallest-angle association of eq. 9).
//  3. For each rotation, translations from double segment pairs: each pair (s_i, s_j) of an
//     association constrains t to a line (eq. 11); pairs of two associations meet where the
//     closed form eq. 14 puts them. Rather than drawing the double pairs at random (the paper's
//     RANSAC needs ~|S1|^2|S2|^2 draws from any pose), every pair votes along its line in a
//     3D translation grid and the grid's peaks are the points where many double pairs agree.
//  4. Each peak is polished with eq. 14 on the segments it matches, scored with the global
//     robust distance (eqs. 7-8, spatial index), and the best is refined jointly (R, t).
#include <cstdint>
#include <vector>

#include "common/params.hpp"
#include "common/progress.hpp"
#include "model/feature_set.hpp"
#include "registration/clustering/direction_clustering.hpp"
#include "registration/common/registration_result.hpp"
#include "registration/common/rotation_from_directions.hpp"
#include "registration/segment_distance/segment_set_distance.hpp"

namespace plumb {

struct SegmentRegistrationParams {
  /// cluster-angle 10°, max-clusters 6; robust-distance 0.10 m, segment-angle 5°; Z-up, tilt
  /// <= 10°: each nested in the schema under its own keys.
  DirectionClusteringParams clustering;
  SegmentDistanceParams distance;
  RotationEnumerationParams rotations;
  /// Translation vote cell, metres, [0.05, 5]. Grown automatically to keep <= 16 M cells.
  double vote_cell = 0.25;
  /// Translation peaks examined per rotation, [1, 100].
  int peaks_per_rotation = 8;
  /// Segments shorter than this are ignored, metres, [0, 10].
  double min_segment_length = 0.3;
  /// Longest segments of each set kept for voting, [10, 100000].
  int max_vote_segments = 600;
  /// Acceptance: at least this many source segments' worth of matches (similarity of eq. 8
  /// expressed in matched segments), [1, 1e6].
  double min_matched_segments = 6.0;
  /// Ambiguity: the runner-up must score at least this fraction below the best, [0, 1].
  double min_relative_gap = 0.05;
  /// Gauss-Newton iterations of the final joint (R, t) polish on matched segments, [0, 100].
  int refine_iterations = 10;
  static const ParamSchema<SegmentRegistrationParams>& schema();
};

/// Registers `source` segments onto `target` segments (e.g. scan onto BIM edges).
GlobalRegistrationResult registerSegments(const std::vector<Segment3D>& source,
                                          const std::vector<Segment3D>& target,
                                          const SegmentRegistrationParams& params,
                                          Progress* progress = nullptr);

/// Polishes a transform on matched segments (eq. 14 generalised to R and t, point-to-line on
/// both endpoints of each matched source segment). Returns the polished transform and the
/// RMS of the matched-pair distances (eq. 4) and the number of matched source segments.
struct SegmentPolishResult {
  RigidTransform transform;
  double rms = 0.0;
  std::size_t matched = 0;
};
SegmentPolishResult polishOnSegments(const std::vector<Segment3D>& source,
                                     const SegmentSetIndex& target, const RigidTransform& start,
                                     int iterations, bool rotation_too);

}  // namespace plumb
