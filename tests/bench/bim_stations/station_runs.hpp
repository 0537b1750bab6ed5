#pragma once
// The registrations of bench_bim_stations: a TLS scan simulated at a catalogue station, put in
// its own scanner frame by random poses, registered onto the whole model with the product
// pipeline (orientation auto), and scored against the truth.
//   set yaw  levelled: yaw uniform in [-180, 180] deg, shift up to max_shift (randomPoses);
//   set 3d   rotation uniform on SO(3), the same shifts (randomPoses3d).
// Outcomes:
//   placed            reported success (usable or check visually), within max_rotation_deg
//                     and max_translation_m of the truth (translation error at the station);
//   ambiguous-repeat  "ambiguous", the truth among the reported placements (within 1 deg and
//                     0.3 m: candidates may be unrefined), and another reported placement at
//                     which the model genuinely repeats the room (placement_oracle.hpp, on the
//                     model without furniture), elsewhere: a wall or slab lies between the
//                     station and where the placement moves it (a room turned onto itself,
//                     symmetric but for its openings, is not a repeat): success;
//   failed            reported as a failure (any other failed or ambiguous outcome);
//   wrong             reported success outside the tolerance: a failure not reported as one.
#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

#include "registration/auto/registration_pipeline.hpp"
#include "station_catalogue.hpp"
#include "station_models.hpp"

namespace plumb::bimst {

enum class PoseSet { Yaw, Any3d };
/// "yaw", "3d".
const char* setName(PoseSet s);
/// Parses "yaw,3d". Throws std::invalid_argument naming a bad set.
std::vector<PoseSet> parseSets(const std::string& list);

enum class Outcome { Placed, AmbiguousRepeat, Failed, Wrong };
const char* outcomeName(Outcome o);
inline bool isSuccess(Outcome o) { return o == Outcome::Placed || o == Outcome::AmbiguousRepeat; }

struct RunParams {
  int poses = 20;                  ///< per station and set
  std::vector<PoseSet> sets = {PoseSet::Yaw, PoseSet::Any3d};
  double tls_step_deg = 0.5;       ///< azimuth and elevation step: ~100-300k points indoors
  double noise_mm = 3.0;           ///< range noise (sigma)
  double max_shift = 20.0;         ///< m, horizontal shift of the random poses
  double max_rotation_deg = 0.05;  ///< success: rotation error below this ...
  double max_translation_m = 0.01; ///< ... and translation error (at the station) below this
  double listed_rotation_deg = 1.0;   ///< "among the candidates": within this ...
  double listed_translation_m = 0.3;  ///< ... and this of the truth
  std::uint64_t seed = 14;         ///< poses and scan noise, mixed with the station
  PipelineParams pipeline;         ///< the product defaults (orientation auto)
  bool print_log = false;          ///< print the pipeline log of every run that is not a success
};

struct RunRecord {
  std::string model;
  StationType type = StationType::Other;
  Eigen::Vector3d station = Eigen::Vector3d::Zero();
  PoseSet set = PoseSet::Yaw;
  int pose = 0;
  std::size_t points = 0;
  std::string level, status, method;
  bool reported_success = false;
  double rotation_deg = -1.0, translation_m = -1.0;  ///< of the returned transform; -1: none
  bool truth_listed = false;
  /// A reported placement puts the room onto a copy of it elsewhere in the model: the oracle
  /// finds the room's shell there, and a surface (wall, slab) lies between the station and
  /// where that placement moves it.
  bool genuine_repeat = false;
  /// A reported placement turns the room onto itself (the oracle agrees, nothing lies between):
  /// a room symmetric but for its doors and windows, which the model does not repeat.
  bool self_symmetric = false;
  Outcome outcome = Outcome::Failed;
  double seconds = 0.0;  ///< registration, features of the scan included
  std::vector<std::string> log;  ///< the pipeline's log
};

/// Simulates the station's scan once and runs every pose of every set in p.sets.
std::vector<RunRecord> runStation(const StationModel& m, const CatalogueStation& s, const RunParams& p);

}  // namespace plumb::bimst
