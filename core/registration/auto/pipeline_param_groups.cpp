#include "registration/auto/pipeline_param_groups.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

#include "common/params_json.hpp"

namespace plumb {

bool paramGroupUsedBy(const std::string& key, RegistrationMethod method) {
  auto in = [&key](std::initializer_list<const char*> keys) {
    return std::any_of(keys.begin(), keys.end(), [&key](const char* k) { return key == k; });
  };
  switch (method) {
    case RegistrationMethod::Auto: return true;
    case RegistrationMethod::Planes:
      return in({"plane-extraction", "planes", "refinement", "candidates", "quality", "visibility"});
    case RegistrationMethod::Openings:
      return in({"plane-extraction", "opening-detection", "openings", "refinement", "candidates",
                 "quality", "visibility"});
    case RegistrationMethod::Segments:
      return in({"segment-detection", "mesh-edges", "segments", "refinement", "candidates",
                 "quality", "visibility"});
    case RegistrationMethod::Icp: return in({"refinement", "quality", "visibility"});
  }
  return true;
}

nlohmann::json pipelineParamsToJson(const PipelineParams& p) {
  nlohmann::json j;
  j["method"] = methodName(p.method);
  j["refine"] = p.refine;
  j["seed"] = p.seed;
  j["model-sample-spacing"] = p.model_sample_spacing;
  forEachParamGroup(p, [&j, &p](const char* key, const char*, const auto& schema,
                                 const auto& group) {
    j[key] = paramsToJson(schema, group);
    // The pipeline runs every step with the top-level seed: show that one, not the group's.
    if (j[key].contains("seed")) j[key]["seed"] = p.seed;
  });
  return j;
}

void pipelineParamsFromJson(const nlohmann::json& j, PipelineParams& p) {
  if (!j.is_object()) throw InputError("registration parameters must be a JSON object");
  std::vector<std::string> known{"method", "refine", "seed", "model-sample-spacing"};
  if (j.contains("method")) p.method = methodFromName(j.at("method").get<std::string>());
  if (j.contains("refine")) p.refine = j.at("refine").get<bool>();
  if (j.contains("seed")) p.seed = j.at("seed").get<std::uint64_t>();
  if (j.contains("model-sample-spacing")) {
    const double v = j.at("model-sample-spacing").get<double>();
    if (!(v >= 0.005 && v <= 1.0))
      throw InputError("model-sample-spacing must be in [0.005, 1] m, got " + std::to_string(v));
    p.model_sample_spacing = v;
  }
  forEachParamGroup(p, [&j, &known](const char* key, const char*, const auto& schema, auto& group) {
    known.push_back(key);
    if (j.contains(key)) paramsFromJson(schema, j.at(key), group);
  });
  for (const auto& [key, value] : j.items())
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw InputError("unknown registration parameter group '" + key + "'");
}

}  // namespace plumb
