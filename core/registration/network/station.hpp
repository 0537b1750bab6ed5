#pragma once
// A station of a network: one scan (an E57 data3D, or a single-scan file) in its own frame,
// with its features and layout descriptor, and where it came from. Its pose in the file is
// kept only to write the result (the network finds every pose from the links).
#include <string>
#include <vector>

#include "common/progress.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "registration/auto/registration_input.hpp"
#include "registration/network/layout_descriptor.hpp"

namespace plumb {

struct Station {
  std::string name;             ///< unique in the network
  std::string file;             ///< the input it came from
  std::size_t scan_index = 0;   ///< data3D index in that file
  RigidTransform file_pose;     ///< station frame -> file frame, as read
  bool has_pose = false;        ///< the file gave a pose (a static scanner at its origin)
  RegistrationInput input;      ///< points (station frame) and, once detected, features
  LayoutDescriptor layout;
  double seconds_features = 0.0;
  /// Voxel edge of the subsample the station is registered on when its file exceeded the
  /// memory budget (registration/bounded/bounded_datasets.hpp), metres; 0: every point.
  double subsample_voxel = 0.0;
  /// The BIM (modelStation): a fixed node whose frame is the output frame; every scan station
  /// is registered onto it. At most one, last in the station list.
  bool is_model = false;
  /// A window of an MMS pass (mms_windows.hpp): its points of [window_start, window_end) seconds
  /// after the pass's first point time, in the pass's frame; the pass's number among the
  /// network's passes, -1 for a static station or the model.
  int mms_pass = -1;
  double window_start = 0.0, window_end = 0.0;
};

/// The BIM as a network node: its own frame is the model frame (file pose identity).
/// Throws FileError when the model has no triangles.
Station modelStation(const BimModel& model, const std::string& file);

/// The station name of scan `index`: its own name, or "scan-INDEX" when it has none (before
/// makeStationNamesUnique).
std::string stationName(const Scan& scan, std::size_t index);

/// One station per scan of `data` (read from `file`): points in the scan's own frame; a scan
/// with a pose is a static station whose scanner sits at its frame's origin. Throws FileError
/// naming the file and scan when a scan holds no points.
/// With `mms_window` > 0, a scan with a trajectory (isMmsPass) is cut into windows of that many
/// seconds instead (mmsWindows), numbered from `first_pass`.
std::vector<Station> stationsOf(const Dataset& data, const std::string& file, double mms_window = 0.0,
                                int first_pass = 0);

/// One input of a network: a point dataset as read (whole, or its scans' voxel subsamples), the
/// file it came from, and the subsample voxel (0: every point).
struct StationFile {
  const Dataset* data = nullptr;
  std::string file;
  double subsample_voxel = 0.0;
};

/// Every scan of every input as a station (stationsOf), each with its file's subsample voxel,
/// names made unique (makeStationNamesUnique): the stations of `plumb-cli network` and of the
/// desktop's Network dock, before the model (modelStation, last). MMS passes are cut into
/// windows of `mms_window` seconds (0: one node each).
std::vector<Station> stationsOfFiles(const std::vector<StationFile>& inputs, double mms_window = 0.0);

/// Detects every station's features (detectStationFeatures), reporting each station to
/// `progress` and honouring its cancel.
void detectStationsFeatures(std::vector<Station>& stations, const PipelineParams& params, Progress& progress);

/// Station names made unique: a name used twice gets its file's stem as a prefix
/// ("indoor/tls-0"), then a number if still not unique.
void makeStationNamesUnique(std::vector<Station>& stations);

/// The stations' names, in order.
std::vector<std::string> stationNames(const std::vector<Station>& stations);

/// Detects the station's planes and openings (extractFeatures, as the pipeline does) and its
/// layout descriptor.
void detectStationFeatures(Station& station, const PipelineParams& params);

}  // namespace plumb
