#include "registration/network/station.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>

#include "common/error.hpp"
#include "registration/network/mms_windows.hpp"

namespace plumb {

std::string stationName(const Scan& scan, std::size_t index) {
  return scan.name.empty() ? "scan-" + std::to_string(index) : scan.name;
}

std::vector<Station> stationsOf(const Dataset& data, const std::string& file, double mms_window, int first_pass) {
  std::vector<Station> out;
  for (std::size_t i = 0; i < data.scans.size(); ++i) {
    const Scan& scan = data.scans[i];
    if (mms_window > 0 && isMmsPass(scan)) {
      for (auto& w : mmsWindows(scan, i, file, first_pass++, mms_window)) out.push_back(std::move(w));
      continue;
    }
    Station s;
    s.name = stationName(scan, i);
    s.file = file;
    s.scan_index = i;
    s.file_pose = scan.pose;
    s.has_pose = scan.has_pose;
    Dataset one;
    one.source = data.source;
    one.format = data.format;
    one.scans.push_back(scan);
    one.scans[0].pose = RigidTransform();  // the station's own frame
    if (one.pointCount() == 0) throw FileError(file, "scan " + std::to_string(i) + " ('" + s.name + "') holds no points");
    s.input = makeRegistrationInput(one, RigidTransform());
    out.push_back(std::move(s));
  }
  return out;
}

Station modelStation(const BimModel& model, const std::string& file) {
  Station s;
  s.name = "model:" + std::filesystem::path(file).stem().string();
  s.file = file;
  s.is_model = true;
  s.input = makeRegistrationInput(model, RigidTransform());
  return s;
}

void makeStationNamesUnique(std::vector<Station>& stations) {
  std::map<std::string, int> count;
  for (const auto& s : stations) ++count[s.name];
  for (auto& s : stations)
    if (count[s.name] > 1) s.name = std::filesystem::path(s.file).stem().string() + "/" + s.name;
  std::map<std::string, int> seen;
  for (auto& s : stations)
    if (const int k = seen[s.name]++; k > 0) s.name += "#" + std::to_string(k + 1);
}

void detectStationFeatures(Station& station, const PipelineParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  station.input.features = extractFeatures(station.input.side(), params, false);
  station.layout = layoutDescriptor(*station.input.features);
  station.seconds_features = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<Station> stationsOfFiles(const std::vector<StationFile>& inputs, double mms_window) {
  std::vector<Station> stations;
  int passes = 0;
  for (const auto& in : inputs)
    for (auto& s : stationsOf(*in.data, in.file, mms_window, passes)) {
      passes = std::max(passes, s.mms_pass + 1);
      s.subsample_voxel = in.subsample_voxel;
      stations.push_back(std::move(s));
    }
  makeStationNamesUnique(stations);
  return stations;
}

void detectStationsFeatures(std::vector<Station>& stations, const PipelineParams& params, Progress& progress) {
  for (std::size_t i = 0; i < stations.size(); ++i) {
    progress.report(double(i) / double(stations.size()), "features of " + stations[i].name);
    progress.check();
    detectStationFeatures(stations[i], params);
  }
}

std::vector<std::string> stationNames(const std::vector<Station>& stations) {
  std::vector<std::string> names;
  for (const auto& st : stations) names.push_back(st.name);
  return names;
}

}  // namespace plumb
