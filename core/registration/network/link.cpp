#include "registration/network/link.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/error.hpp"

namespace plumb {

AdjustmentLink adjustmentLink(const Link& l, const std::vector<Station>& stations) {
  return {l.a, l.b, l.transform, l.sigma_translation, l.sigma_rotation_deg, l.reason == "sequence",
          stations[l.a].is_model || stations[l.b].is_model};
}

void weighLink(Link& link, const LinkWeightParams& p) {
  const double held = std::clamp(link.weakest_resistance / p.full_resistance, 1e-3, 1.0);
  link.sigma_translation = std::max(p.min_sigma, p.rms_factor * link.point_rms) / std::sqrt(held);
  link.sigma_rotation_deg = link.sigma_translation / std::max(1.0, link.length_scale) * 180.0 / M_PI;
}

namespace {
RegistrationSide withoutFeatures(RegistrationSide side) {
  side.features = nullptr;
  return side;
}

/// A failed link's transform: the chosen candidate as refined when the pipeline refined it (an
/// ambiguous link's report.transform is the global step's, unrefined), else `fallback`. What the
/// free-space judge offers as that link's placement (unchecked_stations.hpp).
RigidTransform refinedChoice(const std::vector<PlacementCandidate>& candidates, const RigidTransform& fallback) {
  for (const auto& c : candidates)
    if (c.role == "chosen" && c.refined) return c.transform;
  return fallback;
}

/// The refined candidates other than the chosen one and those converging onto it or ruled out
/// by the free space.
std::vector<LinkAlternative> alternativesOf(const PipelineResult& r) {
  std::vector<LinkAlternative> out;
  for (const auto& c : r.report.candidates)
    if (c.refined && (c.role == "competing" || c.role == "worse"))
      out.push_back({c.transform, c.role, c.overlap, c.point_rms});
  return out;
}
}  // namespace

namespace {

/// A report's 4x4 array, read and checked as a transform file's "matrix".
RigidTransform matrixFrom(const nlohmann::json& m) { return transformFromJson(nlohmann::json{{"matrix", m}}.dump()); }

VerdictLevel levelFrom(const std::string& s) {
  for (const VerdictLevel l : {VerdictLevel::Usable, VerdictLevel::CheckVisually, VerdictLevel::Failed})
    if (s == verdictLevelName(l)) return l;
  throw InputError("unknown verdict_level '" + s + "'");
}

/// The report's "seconds ..." figures summed (features, global step, refinement).
double secondsOf(const nlohmann::json& j) {
  double s = 0.0;
  if (j.contains("figures"))
    for (const auto& [name, value] : j["figures"].items())
      if (name.rfind("seconds ", 0) == 0 && value.is_number()) s += value.get<double>();
  return s;
}

void acceptAndWeigh(Link& link, const NetworkParams& params) {
  link.accepted = link.registered && (link.level == VerdictLevel::Usable ||
                                      (link.level == VerdictLevel::CheckVisually && params.weights.accept_check_visually));
  weighLink(link, params.weights);
}

}  // namespace

Link linkFromReport(const nlohmann::json& j, const CandidatePair& pair, bool onto_model, const NetworkParams& params) {
  Link link;
  link.a = pair.a;
  link.b = pair.b;
  link.reason = pair.reason;
  link.similarity = pair.similarity;
  try {
    link.level = levelFrom(j.at("verdict_level").get<std::string>());
    link.verdict = j.at("verdict").get<std::string>();
    link.status = j.at("status").get<std::string>();
    link.method = j.at("method").get<std::string>();
    link.warnings = j.value("warnings", std::vector<std::string>{});
    link.registered = j.at("success").get<bool>();
    if (link.registered) {
      const RigidTransform t = matrixFrom(j.at("transform"));
      link.transform = onto_model ? t.inverse() : t;
    }
    if (j.value("refined", false)) {
      const auto& p = j.at("points");
      link.overlap = p.at("overlap_ratio").get<double>();
      link.point_rms = p.at("rms_m").get<double>();
      link.length_scale = p.value("length_scale_m", 0.0);
      const auto resistance = j.at("direction_resistance").get<std::vector<double>>();
      if (!resistance.empty()) link.weakest_resistance = *std::min_element(resistance.begin(), resistance.end());
    }
    link.seconds = secondsOf(j);
    if (!onto_model && !link.registered && j.contains("candidates"))  // as refinedChoice
      for (const auto& c : j["candidates"])
        if (c.value("refined", false) && c.value("role", "") == "chosen") link.transform = matrixFrom(c.at("transform"));
    if (!onto_model && j.contains("candidates"))
      for (const auto& c : j["candidates"])
        if (c.value("refined", false) && (c.value("role", "") == "competing" || c.value("role", "") == "worse"))
          link.alternatives.push_back({matrixFrom(c.at("transform")), c["role"].get<std::string>(),
                                       c.value("overlap_ratio", 0.0), c.value("rms_m", 0.0)});
    if (onto_model && j.contains("candidates"))
      for (const auto& c : j["candidates"])
        if (c.value("refined", false)) link.model_candidates.push_back(matrixFrom(c.at("transform")));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("not a plumb-cli register report: ") + e.what());
  }
  acceptAndWeigh(link, params);
  return link;
}

Link registerLink(const Station& a, const Station& b, const CandidatePair& pair, const NetworkParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  Link link;
  link.a = pair.a;
  link.b = pair.b;
  link.reason = pair.reason;
  link.similarity = pair.similarity;
  // A scan onto the BIM, never the BIM onto a scan: the pipeline's model target path (its
  // planes, openings, copy search) is the one calibrated (docs/VERDICT.md).
  // The station's features are detected again there, with the segments a model target needs
  // (its stored features have none), so the link is exactly plumb-cli register onto the model.
  const bool onto_model = b.is_model;
  const PipelineResult r = onto_model ? registerData(withoutFeatures(a.input.side()), b.input.side(), params.link)
                                      : registerData(b.input.side(), a.input.side(), params.link);
  link.level = r.report.level;
  link.verdict = r.report.verdict;
  link.status = r.report.status;
  link.method = r.method_used;
  link.warnings = r.report.warnings;
  link.registered = r.success();
  link.transform = onto_model ? r.transform().inverse() : r.transform();
  link.overlap = r.report.overlap_ratio;
  link.point_rms = r.report.point_rms;
  link.weakest_resistance = *std::min_element(r.report.direction_resistance.begin(), r.report.direction_resistance.end());
  link.length_scale = r.refinement ? r.refinement->length_scale : 0.0;
  if (!onto_model) link.alternatives = alternativesOf(r);
  if (!onto_model && !link.registered) link.transform = refinedChoice(r.report.candidates, link.transform);
  if (onto_model)
    for (const auto& c : r.report.candidates)
      if (c.refined) link.model_candidates.push_back(c.transform);
  acceptAndWeigh(link, params);
  link.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return link;
}

}  // namespace plumb
