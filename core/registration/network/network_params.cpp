#include "registration/network/network_params.hpp"

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/params_json.hpp"
#include "registration/auto/pipeline_param_groups.hpp"

namespace plumb {

const ParamSchema<PairSelectionParams>& PairSelectionParams::schema() {
  using P = PairSelectionParams;
  static const auto s =
      ParamSchema<P>("pair-selection")
          .integer(&P::nearest_layouts, "nearest-layouts", "Most similar layouts", "", 0, 50,
                   "Pairs each station with this many stations of the most similar plane layout")
          .integer(&P::sequence_neighbours, "sequence-neighbours", "Sequence neighbours", "", 0, 50,
                   "Pairs each station with the stations up to this many places after it in input order")
          .integer(&P::expansion_per_station, "expansion", "Expansion pairs per station", "", 0, 100,
                   "While the network is split, further pairs per station tried between its parts")
          .real(&P::footprint_overlap, "footprint-overlap", "Footprint overlap", "", 0.01, 1.0,
                "Placed stations of one part whose plan footprints overlap this much are paired too")
          .integer(&P::footprint_per_station, "footprint-pairs", "Footprint pairs per station", "", 0, 100,
                   "Footprint pairs per station and round (0: none)")
          .real(&P::footprint_cell, "footprint-cell", "Footprint cell", "m", 0.05, 10.0,
                "Plan cell of a station's footprint", true);
  return s;
}

const ParamSchema<LinkWeightParams>& LinkWeightParams::schema() {
  using P = LinkWeightParams;
  static const auto s =
      ParamSchema<P>("link-weights")
          .real(&P::min_sigma, "min-sigma", "Min link sigma", "m", 1e-5, 1.0,
                "Floor of a link's translation standard deviation")
          .real(&P::rms_factor, "rms-factor", "RMS factor", "", 0.0, 10.0,
                "A link's translation sigma is its point RMS times this", true)
          .real(&P::full_resistance, "full-resistance", "Full resistance", "", 0.001, 1.0,
                "Weakest-direction slide resistance at which a link counts as fully held", true)
          .boolean(&P::accept_check_visually, "accept-check-visually", "Accept check-visually links",
                   "Use links whose verdict is check-visually (failed links are never used)");
  return s;
}

const ParamSchema<PoseGraphParams>& PoseGraphParams::schema() {
  using P = PoseGraphParams;
  static const auto s =
      ParamSchema<P>("pose-graph")
          .real(&P::robust_scale, "robust-scale", "Cauchy scale", "sigma", 0.1, 100.0,
                "Cauchy loss scale on each link's normalised residual")
          .real(&P::flag_translation, "flag-translation", "Flag translation", "m", 1e-4, 10.0,
                "A link whose residual after adjustment exceeds this is flagged")
          .real(&P::flag_rotation, "flag-rotation", "Flag rotation", "deg", 1e-4, 10.0,
                "A link whose rotation residual after adjustment exceeds this is flagged")
          .real(&P::drop_translation, "drop-translation", "Drop translation", "m", 1e-4, 100.0,
                "A link whose residual exceeds this is dropped (auto-drop)")
          .real(&P::drop_rotation, "drop-rotation", "Drop rotation", "deg", 1e-4, 180.0,
                "A link whose rotation residual exceeds this is dropped (auto-drop)")
          .boolean(&P::auto_drop, "auto-drop", "Drop wrong links",
                   "Drop the worst link above the drop thresholds and solve again, until none is left")
          .real(&P::triangle_tolerance, "triangle-tolerance", "Triangle tolerance", "m", 1e-4, 10.0,
                "A triangle of links closes within this (orders the initial spanning tree)", true)
          .integer(&P::max_iterations, "max-iterations", "Max iterations", "", 1, 10000,
                   "Solver iterations", true)
          .boolean(&P::check_competing, "check-competing", "Check competing placements",
                   "Re-solve with each dropped link taken as true; stations a loop-checked alternative "
                   "places differently are ambiguous (not placed)");
  return s;
}

const ParamSchema<FinalRefinementParams>& FinalRefinementParams::schema() {
  using P = FinalRefinementParams;
  static const auto s =
      ParamSchema<P>("final-refinement")
          .boolean(&P::enabled, "enabled", "Refine on points",
                   "After the adjustment, refine every overlapping pair of placed stations on their points and "
                   "adjust once more")
          .real(&P::start_distance, "start-distance", "Start distance", "m", 0.005, 1.0,
                "Largest correspondence distance of the first stage", true)
          .real(&P::final_distance, "final-distance", "Final distance", "m", 0.002, 0.5,
                "Correspondence distance of the last stage", true)
          .real(&P::min_overlap, "min-overlap", "Min overlap", "", 0.01, 1.0,
                "Fewest share of a station's points matched for a pair to count", true);
  return s;
}

const ParamSchema<FreeSpaceJudgeParams>& FreeSpaceJudgeParams::schema() {
  using P = FreeSpaceJudgeParams;
  static const auto s =
      ParamSchema<P>("free-space-judge")
          .boolean(&P::enabled, "enabled", "Judge ambiguous stations by free space",
                   "Settle ambiguous stations whose placement the placed stations' free space confirms")
          .real(&P::clean_ratio, "clean-ratio", "Clean ratio", "", 0.0, 0.2,
                "A placement is clean when at most this share of its visible points lies in others' free space", true)
          .real(&P::refute_ratio, "refute-ratio", "Refute ratio", "", 0.0, 1.0,
                "An alternative placement is refuted when at least this share of its visible points contradicts", true)
          .real(&P::decisive_factor, "decisive-factor", "Decisive factor", "", 1.0, 1000.0,
                "... and at least this many times the adopted placement's share", true)
          .integer(&P::min_visible, "min-visible", "Min visible points", "", 1, 10'000'000,
                   "Fewer visible tested points: no evidence", true)
          .integer(&P::test_points, "test-points", "Test points", "", 100, 1'000'000,
                   "Points of each station tested against each other station", true)
          .real(&P::box_margin, "box-margin", "Box margin", "m", 0.0, 100.0,
                "Stations whose placed boxes come this close are tested against each other", true)
          .integer(&P::max_rounds, "max-rounds", "Max adjustments again", "", 0, 10,
                   "Adjustments again after the judge placed stations elsewhere, at most", true);
  return s;
}

const ParamSchema<MmsWindowParams>& MmsWindowParams::schema() {
  using P = MmsWindowParams;
  static const auto s =
      ParamSchema<P>("mms")
          .real(&P::window, "window", "MMS window", "s", 0.0, 3600.0,
                "Seconds of point time per node of an MMS pass (0: the pass is one rigid node)")
          .real(&P::sigma_translation, "sigma-translation", "Trajectory sigma", "m", 1e-4, 10.0,
                "Stated accuracy of the trajectory between consecutive windows")
          .real(&P::sigma_rotation_deg, "sigma-rotation", "Trajectory rotation sigma", "deg", 1e-4, 10.0,
                "Stated rotation accuracy of the trajectory between consecutive windows", true)
          .boolean(&P::station_pairs, "station-pairs", "Windows with stations",
                   "Register every MMS window with every static station (openings), not only with the BIM");
  return s;
}

nlohmann::json networkParamsToJson(const NetworkParams& p) {
  nlohmann::json j;
  forEachNetworkParamGroup(p, [&](const char* key, const char*, const auto& schema, const auto& group) {
    j[key] = paramsToJson(schema, group);
  });
  j["link"] = pipelineParamsToJson(p.link);
  return j;
}

bool isNetworkParamPath(const std::string& path) {
  const auto dot = path.find('.');
  if (dot == std::string::npos) return false;
  const std::string group = path.substr(0, dot);
  bool found = false;
  const NetworkParams defaults;
  forEachNetworkParamGroup(defaults, [&](const char* name, const char*, const auto&, const auto&) {
    found = found || group == name;
  });
  return found;
}

void setNetworkParam(NetworkParams& p, const std::string& path, const std::string& text) {
  if (!isNetworkParamPath(path)) return setPipelineParam(p.link, path, text);
  const auto dot = path.find('.');
  const std::string group = path.substr(0, dot), key = path.substr(dot + 1);
  bool set = false;
  forEachNetworkParamGroup(p, [&](const char* name, const char*, const auto& schema, auto& params) {
    if (group == name) set = setParam(schema, params, key, text);
  });
  if (!set) throw InputError("group '" + group + "' has no parameter '" + key + "'");
}

void validateNetworkParams(const NetworkParams& p) {
  forEachNetworkParamGroup(p, [&](const char* name, const char*, const auto& schema, const auto& params) {
    try {
      validateParams(schema, params);
    } catch (const InputError& e) {
      throw InputError(std::string("\"") + name + "\": " + e.what());
    }
  });
  validatePipelineParams(p.link);
}

}  // namespace plumb
