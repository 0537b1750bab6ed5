#pragma once
// Beyond the papers (issue 13, symmetry): the copies of the placed source in the target.
//
// A room that the target repeats (the other unit of a mirrored duplex, an identical storey) is
// a second placement that fits about as well as the chosen one. The feature searches rank
// their hypotheses by feature votes, and a copy whose model is split into other pieces can draw
// too few votes to be examined at all: the truth is then never compared with the wrong copy.
// This search does not use features. It is chamfer matching on an occupancy grid:
//   1. the target's points mark the cells of a grid (cell `copy_cell`), dilated by one cell;
//   2. a fixed sample of source points (as many from the floors and ceilings as from each
//      wall direction: floors fit at any horizontal shift and must not outvote the walls) is
//      placed by the chosen transform and turned about the
//      target's vertical axis by 0, 90, 180 and 270 degrees (a building's copies are turned by
//      quarter turns: mirrored units by a half turn; other angles are not searched); when the
//      source's up direction was only estimated, also upside down and then by quarter turns;
//   3. every whole-cell shift that keeps the placed sample within the target's box is scored by
//      the number of sample points landing in occupied cells; a shift stops being counted as
//      soon as it cannot reach `copy_min_fraction` of the chosen placement's own score;
//   4. the shifts reaching it, one per metre (non-maximum suppression), are scored again on a
//      finer grid (`fine_cell`), each at its best fine shift within one coarse cell (half a
//      metre vertically: the suppression may have kept a shift half a storey off): the
//      coarse tolerance lets half-fitting placements reach the threshold, the fine one does not;
//   5. shifts whose fine score reaches `copy_min_fraction` of the chosen placement's fine score
//      are copies, kept best first, one per metre, at most `copy_max`, without the chosen
//      placement itself.
// The pipeline searches from the best-fitting refined placement so far (the global answer can be
// a poor one), then refines each copy and compares it like the runner-up
// (candidate_refinement.hpp): a copy fitting about as well makes the answer ambiguous.
#include <cstdint>
#include <string>
#include <vector>

#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"
#include "registration/common/registration_result.hpp"

namespace plumb {

struct CopySearchParams {
  double cell = 0.25;           ///< coarse grid cell and shift step, m
  double fine_cell = 0.05;      ///< fine grid cell and shift step, m
  int max_coarse = 2048;        ///< coarse shifts scored again on the fine grid at most
  double min_fraction = 0.9;    ///< a copy scores at least this fraction of the chosen placement
  int max_copies = 4;           ///< copies returned at most
  int sample_points = 512;      ///< source points scored per shift, drawn evenly from the
                                ///< direction classes (floors/ceilings, walls by azimuth)
  int class_pool = 20000;       ///< source points whose normals decide the classes
  double normal_radius = 0.25;  ///< neighbourhood of those normals, m
  double separation = 1.0;      ///< copies closer than this (m, same turn) are one copy
  std::int64_t max_cells = 32'000'000;   ///< grid cells at most (the cell grows beyond)
  std::int64_t max_shifts = 8'000'000;  ///< shifts x turns searched at most (else skipped)
  double min_explained = 0.5;   ///< no search when the chosen placement explains less of the
                                ///< sample (a partial overlap has no meaningful copies)
  /// Also search the chosen placement turned upside down (180 degrees about a horizontal axis,
  /// then by quarter turns): for a source whose up direction was chosen among candidates
  /// (orientation_search.hpp), where a room whose floor and ceiling look alike can be placed
  /// upside down and its upright copies are then never among the quarter turns. Upside-down
  /// copies are kept apart from upright ones, up to max_copies each.
  bool upside_down = false;
  std::uint64_t seed = 1;       ///< which source points are sampled
};

struct CopySearchResult {
  std::vector<Hypothesis> copies;  ///< best first; score = fraction of the sample explained
  double chosen_fraction = 0.0;    ///< the chosen placement's own score
  double cell = 0.0;               ///< the coarse cell actually used, m
  double fine_cell = 0.0;          ///< the fine cell actually used, m
  std::size_t coarse_candidates = 0;  ///< coarse shifts scored on the fine grid
  bool skipped = false;            ///< too large a search, or too little explained
  std::string message;             ///< what was searched and found, for the log
};

/// The copies of `source` placed by `chosen` in `target` (both in world coordinates).
CopySearchResult findCopies(const PointCloud& source, const PointCloud& target,
                            const RigidTransform& chosen, const CopySearchParams& params);

}  // namespace plumb
