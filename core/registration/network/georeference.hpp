#pragma once
// Georeferencing a network on control points (issue 15, docs/NETWORK.md "Control points"):
// after the robust adjustment (reference station fixed), the placed stations are moved into
// the survey's ground frame by the rigid fit of their control-point targets (Umeyama, no
// scale), then the pose graph is solved once more with the kept links and one constraint per
// control-target observation and no station fixed: the control points hold the frame. Check
// points stay out; every point's residual (adjusted minus given) is reported, in the ground
// frame and in grid units. The poses come out in the ground frame moved to the grid origin.
#include <string>
#include <vector>

#include "registration/network/control_points.hpp"
#include "registration/network/robust_adjustment.hpp"

namespace plumb {

struct PointResidual {
  std::string point;
  bool check = false;
  std::size_t observations = 0;  ///< by placed stations
  /// Adjusted minus given position (mean over the observations), ground frame, m; zero when no
  /// placed station saw the point.
  Eigen::Vector3d ground = Eigen::Vector3d::Zero();
  Eigen::Vector3d grid = Eigen::Vector3d::Zero();  ///< the same in grid units (E, N times k)
};

/// A check point a placed station sees farther than the drop translation from its coordinates:
/// the check contradicts the station's placement (or the target was misidentified).
struct CheckFailure {
  std::size_t station = 0;
  std::string point;
  double misfit = 0.0;  ///< m, ground frame
};

struct Georeference {
  bool done = false;
  std::string message;  ///< what was done, or why the network is not georeferenced
  GridFrame grid;
  std::vector<PointResidual> points;  ///< every control and check point, in file order
  std::size_t control_used = 0;       ///< control points seen by placed stations
  double control_rms = 0.0;           ///< m, 3D RMS of the control points' residuals
  double check_max = 0.0;             ///< m, largest 3D check-point residual (0: none seen)
  /// Stations that see 3 control points (not in a line) themselves, every one within the drop
  /// translation at the station's adjusted pose: their own resection confirms them, whatever the
  /// links said (sorted).
  std::vector<std::size_t> settled;
  /// Links the control points contradicted (dropped in the georeferenced solve), and stations
  /// that then lost every link to stations the control holds (left unplaced).
  std::size_t links_dropped = 0;
  std::vector<std::size_t> unplaced;
  /// Check points contradicting a station's placement: the station is not placed (in
  /// `unplaced`), nor are the stations that only it joined to the control.
  std::vector<CheckFailure> check_failures;
};

/// Checks that every observation names a station in `names` and a point of `survey`; throws
/// FileError naming the targets file and line otherwise.
void checkObservations(const ControlSurvey& survey, const std::vector<std::string>& names);

/// Georeferences `adjustment` (poses of the stations in the reference frame; links as given to
/// adjustNetwork, with its outcomes). Needs 3 control points, not in a line, seen by placed
/// stations; otherwise returns done = false with the reason and leaves the adjustment as it
/// was. On success, poses, sigmas, chain poses and link residuals are those of the ground
/// frame at the grid origin.
///
/// The control points are evidence the links cannot fake: a station that sees 3 of them starts
/// at its own resection when the links put it elsewhere; a kept link whose residual then exceeds
/// the drop thresholds is dropped (params.auto_drop, the worst first, solved again); stations
/// whose group of links no longer sees 3 control points are unplaced (their pose reset). Check
/// points stay out of the solve, but a station that sees one farther than the drop translation
/// from its coordinates is not placed: the check contradicts it (check_failures).
Georeference georeferenceNetwork(const ControlSurvey& survey, const std::vector<std::string>& station_names,
                                 const std::vector<AdjustmentLink>& links, const PoseGraphParams& params,
                                 NetworkAdjustment& adjustment);

/// `part`'s georeference (a part of the network placed by its own control points) merged into
/// `into`: each point's residual averaged over both sets of observations; counts, control RMS
/// and largest check residual computed again.
void mergeGeoreference(Georeference& into, const Georeference& part);

}  // namespace plumb
