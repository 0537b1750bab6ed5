#include "registration/network/mms_windows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common/error.hpp"

namespace plumb {

bool isMmsPass(const Scan& scan) { return scan.cloud.hasTimestamps() && scan.cloud.hasSensorOrigins(); }

namespace {

std::string windowName(const std::string& pass, double t0, double t1) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "@%.0f-%.0fs", t0, t1);
  return pass + buf;
}

}  // namespace

std::vector<MmsWindow> windowsOf(const Scan& scan, double window) {
  if (!(window > 0)) throw InputError("an MMS window must last more than 0 s");
  const auto& t = scan.cloud.timestamps;
  double start = INFINITY;
  for (double v : t)
    if (std::isfinite(v)) start = std::min(start, v);
  std::map<long, std::vector<std::size_t>> by_window;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (std::isfinite(t[i])) by_window[long(std::floor((t[i] - start) / window))].push_back(i);
  std::vector<MmsWindow> out;
  for (auto& [k, idx] : by_window) out.push_back({double(k) * window, double(k + 1) * window, std::move(idx)});
  return out;
}

std::vector<Station> mmsWindows(const Scan& scan, std::size_t scan_index, const std::string& file, int pass,
                                double window) {
  std::vector<Station> out;
  const std::string name = scan.name.empty() ? "mms-" + std::to_string(scan_index) : scan.name;
  for (const auto& w : windowsOf(scan, window)) {
    Station s;
    s.window_start = w.start;
    s.window_end = w.end;
    s.name = windowName(name, w.start, w.end);
    s.file = file;
    s.scan_index = scan_index;
    s.file_pose = scan.pose;
    s.mms_pass = pass;
    Dataset one;
    Scan part;
    part.name = s.name;
    part.cloud = scan.cloud.subset(w.points);
    one.scans.push_back(std::move(part));
    s.input = makeRegistrationInput(one, RigidTransform());
    out.push_back(std::move(s));
  }
  if (out.empty()) throw FileError(file, "scan " + std::to_string(scan_index) + " has no finite point times");
  return out;
}

std::vector<Link> trajectoryLinks(const std::vector<Station>& stations, const MmsWindowParams& params) {
  std::vector<Link> out;
  for (std::size_t i = 0; i + 1 < stations.size(); ++i) {
    const Station &a = stations[i], &b = stations[i + 1];
    if (a.mms_pass < 0 || a.mms_pass != b.mms_pass) continue;
    Link l;
    l.a = i, l.b = i + 1;
    l.reason = l.status = l.method = "trajectory";
    l.registered = l.accepted = true;
    l.level = VerdictLevel::Usable;
    l.verdict = "the pass's trajectory joins consecutive windows, at its stated accuracy";
    l.sigma_translation = params.sigma_translation;
    l.sigma_rotation_deg = params.sigma_rotation_deg;
    out.push_back(std::move(l));
  }
  return out;
}

std::vector<CandidatePair> mmsPairs(const std::vector<Station>& stations, const MmsWindowParams& params) {
  std::vector<CandidatePair> out;
  const bool model = !stations.empty() && stations.back().is_model;
  for (std::size_t w = 0; w < stations.size(); ++w) {
    if (stations[w].mms_pass < 0) continue;
    if (model) out.push_back({w, stations.size() - 1, 0.0, "model"});
    if (!params.station_pairs) continue;
    for (std::size_t i = 0; i < stations.size(); ++i)
      if (!stations[i].is_model && stations[i].mms_pass < 0) out.push_back({std::min(i, w), std::max(i, w), 0.0, "mms"});
  }
  return out;
}

}  // namespace plumb
