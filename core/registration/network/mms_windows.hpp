#pragma once
// MMS passes as time-windowed nodes of a network (issue 15, docs/NETWORK.md "MMS passes").
//
// A mobile-mapping pass is not rigid: its trajectory drifts by centimetres to decimetres where
// GNSS drops. Registered as one node, its drift would be spread over every link that touches it.
// So a pass (a scan with per-point times and sensor origins: a trajectory) is cut into windows
// of `window` seconds of point time, each a node with its own pose:
//  - consecutive windows of a pass are joined by a trajectory link: the identity (they share the
//    pass's frame), weighted by the pass's stated accuracy (`sigma_translation`,
//    `sigma_rotation_deg`): where the trajectory drifted, the adjustment bends it at that
//    weight, and a drift beyond the drop thresholds drops the link (the windows are then placed
//    by their own links);
//  - each window is registered onto the BIM (reason "model") and, with station_pairs, with each
//    static station (reason "mms": openings seen from inside and outside, the 2023 paper's
//    indoor/outdoor case);
//  - windows get no layout or sequence pairs among themselves.
#include <string>
#include <vector>

#include "model/dataset.hpp"
#include "registration/network/link.hpp"
#include "registration/network/network_params.hpp"
#include "registration/network/pair_selection.hpp"
#include "registration/network/station.hpp"

namespace plumb {


/// A scan with per-point times and sensor origins: an MMS pass read from a file.
bool isMmsPass(const Scan& scan);

/// One window of a pass: [start, end) seconds after its first point time, and its points.
struct MmsWindow {
  double start = 0.0, end = 0.0;
  std::vector<std::size_t> points;
};

/// The windows of `scan` (a pass) holding points, in time order; points without a finite time
/// belong to none. Throws InputError for a window of 0 s or less.
std::vector<MmsWindow> windowsOf(const Scan& scan, double window);

/// The pass cut into windows of `window` seconds (the first starts at its earliest point time);
/// each a station named "NAME@T0-T1s" of its points, in the pass's frame (file pose: the scan's
/// pose), with mms_pass = `pass`. Windows without points are left out.
std::vector<Station> mmsWindows(const Scan& scan, std::size_t scan_index, const std::string& file, int pass,
                                double window);

/// The trajectory links joining consecutive windows of each pass: accepted, identity,
/// weighted by the stated accuracy (reason "trajectory", status "trajectory").
std::vector<Link> trajectoryLinks(const std::vector<Station>& stations, const MmsWindowParams& params);

/// Each window with the model (reason "model", the window first) and, with station_pairs, with
/// each static scan station (reason "mms", the static station first).
std::vector<CandidatePair> mmsPairs(const std::vector<Station>& stations, const MmsWindowParams& params);

}  // namespace plumb
