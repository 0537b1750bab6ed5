#include "report/figure_meanings.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <regex>

namespace plumb::report {
namespace {

using Table = std::map<std::string, std::string>;

/// Meanings by the whole generic path.
const Table& byPath() {
  static const Table t = {
      {"success", "Whether results may be used: yes when the verdict is usable or check visually"},
      {"verdict_level", "usable: results can be used; check-visually: written, but look at the "
                        "warnings first; failed: no result (failed or ambiguous)"},
      {"exit_code", "plumb-cli's exit status for this verdict: 0 usable, 3 check visually, 2 failed"},
      {"verdict", "The verdict in plain language"},
      {"method", "Global registration method used (planes, openings, segments, icp)"},
      {"status", "Outcome of the global method and the refinement"},
      {"transform", "Final rigid transform, source to target (4 x 4, metres)"},
      {"global_transform", "Transform of the global method before refinement"},
      {"global_score", "Score of the chosen hypothesis (unit below)"},
      {"score_unit", "Unit of the feature scores"},
      {"hypotheses_evaluated", "Transform hypotheses the global method scored"},
      {"runner_up", "Best placement clearly different from the answer (none: no competitor)"},
      {"runner_up.transform", "Transform of the runner-up placement"},
      {"runner_up.score", "Feature score of the runner-up placement"},
      {"runner_up.relative_gap", "How much lower the runner-up scored: (best - runner-up) / best"},
      {"features.source", "Features (planes, openings, segments) found in the source"},
      {"features.target", "Features found in the target"},
      {"features.inliers", "Source features matched to a target feature under the transform"},
      {"features.rms_m", "Root mean square residual of the matched features"},
      {"refined", "Whether the point-level refinement (ICP) ran"},
      {"points.rms_m", "Root mean square point-to-surface distance of the matched source points "
                       "after refinement"},
      {"points.overlap_ratio", "Fraction of source points matched to the target after refinement"},
      {"points.inliers", "Source points matched to the target after refinement"},
      {"points.length_scale_m", "RMS radius of the matched points about their centroid: the lever "
                                "arm that turns a rotation error into a displacement"},
      {"points.refinement_shift_m", "How far the refinement moved the global result"},
      {"points.refinement_rotation_deg", "How far the refinement turned the global result"},
      {"normal_matrix_eigenvalues", "Eigenvalues of the refinement's normal matrix, ascending: "
                                    "small ones mark directions the data constrains weakly"},
      {"direction_resistance", "Per eigen-direction, the fraction of matched points a 0.2 m slide "
                               "pushes off their surface: near 0 means the data slides freely"},
      {"weak_directions", "Weakly constrained or unconstrained directions (empty: none)"},
      {"weak_directions[].kind", "Translation along, or rotation about, the axis"},
      {"weak_directions[].axis", "Axis of the weak direction (world frame)"},
      {"weak_directions[].relative_eigenvalue", "Its eigenvalue over the largest one"},
      {"weak_directions[].slide_resistance", "Fraction of matched points a slide pushes off their surface"},
      {"weak_directions[].unconstrained", "Whether the direction is free (the registration then fails)"},
      {"weak_directions[].description", "The weak direction in words"},
      {"warnings", "What a surveyor should check before using the result (empty: nothing)"},
      {"visibility.computed", "Whether free-space evidence was computed"},
      {"visibility.contradiction_ratio", "Worst direction: fraction of visible points lying in space "
                                         "the other data saw through (a wrong building scores high)"},
      {"visibility.expected_overlap", "Fraction of the source the target's sensors could see"},
      {"visibility.model_target", "Whether the target is a model (rays tested against its walls)"},
      {"visibility.unexplained_structure", "Worst direction: share of the judged structure the other "
                                           "data does not explain (none: not enough structure judged)"},
      {"candidates", "Every placement considered (the answer first)"},
      {"candidates[].feature_score", "Feature score of this placement"},
      {"candidates[].fit_cost", "Refined fit cost (lower is better)"},
      {"candidates[].figures.free-space contradiction ratio",
       "Share of visible points in the other side's seen-through space at this placement "
       "(judged when placements fit about equally; negative: not conclusive)"},
      {"candidates[].figures.unexplained structure",
       "Share of the large planes' area unexplained at this placement (negative: not "
       "conclusive)"},
      {"candidates[].figures.structure overlap",
       "Share of the source's large-plane points (walls, floors, ceilings) this refined "
       "placement explains; compared when the source fits nearly wholly"},
      {"candidates[].inliers", "Source points matched after refining this placement"},
      {"candidates[].label", "How this placement was built"},
      {"candidates[].overlap_ratio", "Fraction of source points matched after refining it"},
      {"candidates[].refined", "Whether this placement was refined before being compared"},
      {"candidates[].rms_m", "Point RMS after refining this placement"},
      {"candidates[].role",
       "chosen, competing (ambiguous), same placement, clearly worse, or ruled out by free space"},
      {"candidates[].transform", "Transform of this placement"},
  };
  return t;
}

/// Meanings by the last path component (the free-space directions share their fields).
const Table& byName() {
  static const Table t = {
      {"agreement_ratio", "Fraction of visible points consistent with the other data's free space"},
      {"available", "Whether this direction could be tested (sensor origins known)"},
      {"consistent", "Visible points consistent with the other data's free space"},
      {"contradicting", "Visible points lying in space the other data saw through"},
      {"contradiction_ratio", "Contradicting points over visible points"},
      {"expected_overlap", "Fraction of tested points the other data's sensors could see"},
      {"missing_reason", "Why this direction could not be tested (empty: it was)"},
      {"seconds", "Time spent on this test"},
      {"stations", "Sensor stations (or trajectory pseudo-stations) used"},
      {"tested", "Points tested"},
      {"visible", "Tested points inside the other data's field of view"},
      {"what", "What this direction tests"},
      {"large_planes", "Planes of this side large enough to judge (4 m2 by default)"},
      {"judged_planes", "Large planes with enough points the other data's sensors could see"},
      {"unexplained_planes", "Judged planes mostly lying where the other data saw through or has "
                             "nothing: walls the other data does not explain"},
      {"judged_area_m2", "Area of the judged planes"},
      {"unexplained_area_m2", "Area of the unexplained planes"},
      {"unexplained_area_ratio", "Unexplained area over judged area (a wrong building leaves whole "
                                 "walls unexplained)"},
      {"point_ratio", "Unexplained points over the sighted points of the judged planes"},
      {"worst_plane_fraction", "Unexplained fraction of the worst judged plane"},
      {"worst_plane_area_m2", "Area of the worst judged plane"},
  };
  return t;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string lastName(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string printf1(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string number(const std::string& name, const nlohmann::json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  const double x = v.get<double>();
  if (!std::isfinite(x)) return "not a number";
  if (endsWith(name, "_m")) return std::abs(x) < 1.0 ? printf1("%.1f mm", x * 1e3) : printf1("%.3f m", x);
  if (endsWith(name, "_deg")) return printf1("%.3f deg", x);
  if (endsWith(name, "_m2")) return printf1("%.2f m2", x);
  if (name.find("ratio") != std::string::npos || name == "expected_overlap" || name == "relative_gap")
    return printf1("%.1f %%", x * 100.0);
  if (name.rfind("seconds", 0) == 0) return printf1("%.2f s", x);
  return printf1("%.4g", x);
}

std::string numberList(const nlohmann::json& v) {
  std::string out;
  for (const auto& x : v) {
    if (!out.empty()) out += v.size() == 4 && x.is_array() ? "; " : ", ";
    if (x.is_array()) {
      std::string row;
      for (const auto& y : x) row += (row.empty() ? "" : " ") + printf1("%.6f", y.get<double>());
      out += row;
    } else {
      out += x.is_number() ? printf1("%.4g", x.get<double>()) : x.dump();
    }
  }
  return "[" + out + "]";
}

}  // namespace

std::string genericPath(const std::string& path) {
  static const std::regex index(R"(\[\d+\])");
  return std::regex_replace(path, index, "[]");
}

std::string figureMeaning(const std::string& path) {
  const std::string generic = genericPath(path);
  if (auto it = byPath().find(generic); it != byPath().end()) return it->second;
  if (generic.rfind("figures.", 0) == 0)
    return "Figure reported by the method: " + generic.substr(8);
  if (auto it = byName().find(lastName(generic)); it != byName().end()) return it->second;
  return "";
}

std::string displayValue(const std::string& path, const nlohmann::json& value) {
  if (value.is_null()) return "none";
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return number(lastName(path), value);
  if (value.is_array()) {
    if (value.empty()) return "none";
    if (value[0].is_string()) {
      std::string out;
      for (const auto& s : value) out += (out.empty() ? "" : "; ") + s.get<std::string>();
      return out;
    }
    return numberList(value);
  }
  return value.dump();
}

}  // namespace plumb::report
