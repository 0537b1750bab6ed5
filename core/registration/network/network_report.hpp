#pragma once
// The JSON report of a network registration (docs/NETWORK.md "Report"):
// {"format": "plumb-network-report", "version": 1, "complete": bool, "exit_code": n,
//  "reference": name,
//  "stations": [{"name", "file", "scan", "placed", "ambiguous", "ambiguous_why" (when ambiguous),
//                "model" (the BIM node, last), "unchecked" (placed by one link no loop checks,
//                unchecked_stations.hpp),
//                "pose": {"matrix"}, "transform": {"matrix"}
//                (file frame -> registered frame), "sigma_position_m": [x,y,z],
//                "sigma_rotation_deg": [x,y,z], "links": [link indices],
//                "free_space" (an ambiguous or unchecked station judged, free_space_judge.hpp): {"settled",
//                "why", "round", "decided" (the placement chosen), "placements": [{"source",
//                "tally": {"visible", "contradicting", "ratio"}, "judged", "clean"}]},
//                "mms_window_s" (a window of an MMS pass): {"pass", "start", "end"}}],
//  "links": [{"a", "b", "reason", "similarity", "method", "verdict_level", "verdict", "status",
//             "warnings", "overlap", "point_rms_m", "weakest_resistance", "sigma_translation_m",
//             "sigma_rotation_deg", "accepted", "residual_translation_m", "residual_rotation_deg",
//             "residual_sigma", "flagged", "dropped", "bridge" (a kept link no loop checks),
//             "triangles_closing", "triangles_failing", "decision" ("accepted" / "rejected" by
//             the surveyor, "free space": taken as true by the free-space judge),
//             "seconds", "transform" (b's frame -> a's frame), "alternatives": [{"role",
//             "overlap", "point_rms_m", "rotation_from_chosen_deg", "transform"}] (the other
//             placements the link's pipeline refined)}],
//  "network": {"stations", "pairs_all", "pairs_registered", "links_accepted", "links_dropped",
//              "links_flagged", "links_unchecked" (bridges), "rounds", "loop_closures": [{"link", "stations",
//              "translation_m", "rotation_deg"}], "loop_translation_mean_m",
//              "loop_translation_max_m", "loop_rotation_mean_deg", "loop_rotation_max_deg",
//              "residual_translation_mean_m", "residual_translation_max_m", "unplaced": [names],
//              "ambiguous": [names], "copies_unchecked": [names], "one_loop": [names], "unchecked":
//              [names] (placed by one link no loop checks), "contested": [names] (of those, the
//              ones the free space contests: ambiguous), "competing": [{"link",
//              "corroborated", "competes", "links_dropped", "sequence_links_dropped",
//              "model_links_dropped", "stations_moved": [names],
//              "max_translation_m", "max_rotation_deg"}] (one per dropped link taken as true),
//              "settled_by_free_space": [names], "seconds_free_space",
//              "parts": [[names]], "solves", "converged", "covariance", "solver",
//              "seconds_features", "seconds_links", "seconds_adjustment"},
//  "georeference" (with control points): {"done", "message", "crs", "scale_factor",
//              "origin_grid": [E,N,H], "coordinates", "control_used", "control_rms_m",
//              "check_max_m", "points": [{"name", "role" (control|check), "observations",
//              "residual_ground_m": [x,y,z], "residual_grid_m": [E,N,H], "residual_m"}]}}
#include <nlohmann/json_fwd.hpp>

#include <vector>

#include "registration/network/network_registration.hpp"

namespace plumb {

/// 0: every station placed and no kept link flagged; 3: placed, a kept link flagged (check
/// visually); 2: a station could not be placed or is ambiguous (competing_placements.hpp), or
/// control points were given and could not georeference the network.
int networkExitCode(const NetworkResult& result);

/// Station i's transform: file frame -> registered frame (pose x file_pose^-1), if placed.
std::optional<RigidTransform> stationTransform(const NetworkResult& result, const std::vector<Station>& stations,
                                               std::size_t i);

nlohmann::json networkReportToJson(const NetworkResult& result, const std::vector<Station>& stations);

/// One line per station and per link, then the network figures: what plumb-cli prints.
std::string networkReportToText(const NetworkResult& result, const std::vector<Station>& stations);

}  // namespace plumb
