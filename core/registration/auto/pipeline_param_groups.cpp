#include "registration/auto/pipeline_param_groups.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

#include "common/params_json.hpp"

namespace plumb {

const ParamSchema<PipelineParams>& PipelineParams::schema() {
  using P = PipelineParams;
  static const auto s =
      ParamSchema<P>("registration")
          .choice(&P::method, "method", "Method",
                  {methodName(RegistrationMethod::Auto), methodName(RegistrationMethod::Planes),
                   methodName(RegistrationMethod::Openings), methodName(RegistrationMethod::Segments),
                   methodName(RegistrationMethod::Icp)},
                  "auto picks from the inputs: segments for a model (then its planes and openings), "
                  "planes for two scans")
          .boolean(&P::refine, "refine", "Refine (ICP)", "Refine the global answer with ICP")
          .integer(&P::seed, "seed", "Random seed", "", 0, kMaxSeed,
                   "Seed of every random step (plane detection, openings hypotheses, model "
                   "samples); the same seed gives the same result")
          .real(&P::model_sample_spacing, "model-sample-spacing", "Model sample spacing", "m",
                0.005, 1.0,
                "Spacing of the points sampled on a model for refinement "
                "(refinement.model-surface = samples, or GICP)",
                true)
          .real(&P::agreement_rotation_deg, "agreement-rotation", "Planes/openings agreement",
                "deg", 0.01, 45.0,
                "auto: planes and openings agree within this rotation (and translation), "
                "else the answer is ambiguous", true)
          .real(&P::agreement_translation, "agreement-translation",
                "Planes/openings agreement", "m", 0.001, 10.0,
                "auto: planes and openings agree within this translation (and rotation)", true);
  return s;
}

bool paramGroupUsedBy(const std::string& key, RegistrationMethod method) {
  auto in = [&key](std::initializer_list<const char*> keys) {
    return std::any_of(keys.begin(), keys.end(), [&key](const char* k) { return key == k; });
  };
  if (key == "registration" || key == "memory") return true;  // the top level: seed, refine, ...
  switch (method) {
    case RegistrationMethod::Auto: return true;
    case RegistrationMethod::Planes:
      return in({"orientation", "plane-extraction", "bim-features", "planes", "refinement",
                 "candidates", "quality", "visibility"});
    case RegistrationMethod::Openings:
      return in({"orientation", "plane-extraction", "opening-detection", "bim-features", "openings",
                 "refinement", "candidates", "quality", "visibility"});
    case RegistrationMethod::Segments:
      return in({"orientation", "segment-detection", "mesh-edges", "segments", "refinement", "candidates",
                 "quality", "visibility"});
    case RegistrationMethod::Icp: return in({"refinement", "quality", "visibility"});
  }
  return true;
}

nlohmann::json pipelineParamsToJson(const PipelineParams& p) {
  nlohmann::json j = paramsToJson(PipelineParams::schema(), p);
  forEachParamGroup(p, [&j](const char* key, const char*, const auto& schema, const auto& group) {
    j[key] = paramsToJson(schema, group);
  });
  return j;
}

namespace {

/// Runs f, prefixing an InputError with the group whose parameters it reads.
template <class F>
void inGroup(const char* key, F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    throw InputError(std::string("\"") + key + "\": " + e.what());
  }
}

/// Files written before issue 18 carry a "seed" in some groups. Every step takes the top-level
/// seed now: a group seed equal to it is dropped, any other is an error naming the key.
nlohmann::json withoutGroupSeed(const nlohmann::json& group, const char* key, std::uint64_t seed) {
  if (!group.is_object() || !group.contains("seed")) return group;
  const nlohmann::json& s = group.at("seed");
  if (!s.is_number() || s != seed)
    throw InputError(std::string("\"") + key + "\".\"seed\" = " + s.dump() +
                     " differs from the top-level \"seed\" (" + std::to_string(seed) +
                     "): groups have no seed of their own any more; every step uses the "
                     "top-level one. Remove the group's \"seed\" or set the top-level one.");
  nlohmann::json rest = group;
  rest.erase("seed");
  return rest;
}

}  // namespace

void pipelineParamsFromJson(const nlohmann::json& j, PipelineParams& p) {
  if (!j.is_object()) throw InputError("registration parameters must be a JSON object");
  std::vector<std::string> groups;
  forEachParamGroup(p, [&groups](const char* key, const char*, const auto&, auto&) { groups.push_back(key); });
  nlohmann::json top = nlohmann::json::object();
  for (const auto& [key, value] : j.items())
    if (std::find(groups.begin(), groups.end(), key) == groups.end()) top[key] = value;
  paramsFromJson(PipelineParams::schema(), top, p);  // first: the groups' old seeds compare with it
  forEachParamGroup(p, [&j, &p](const char* key, const char*, const auto& schema, auto& group) {
    if (j.contains(key))
      inGroup(key, [&] { paramsFromJson(schema, withoutGroupSeed(j.at(key), key, p.seed), group); });
  });
}

void setPipelineParam(PipelineParams& p, const std::string& path, const std::string& text) {
  const auto dot = path.find('.');
  if (dot == std::string::npos) {
    if (!setParam(PipelineParams::schema(), p, path, text))
      throw InputError("unknown registration parameter '" + path + "' (a group's parameter is GROUP.KEY)");
    return;
  }
  const std::string group_key = path.substr(0, dot), key = path.substr(dot + 1);
  bool group_found = false;
  forEachParamGroup(p, [&](const char* g, const char*, const auto& schema, auto& group) {
    if (group_key != g) return;
    group_found = true;
    inGroup(g, [&] {
      if (!setParam(schema, group, key, text))
        throw InputError("unknown parameter '" + key + "' for '" + schema.name() + "'");
    });
  });
  if (!group_found) throw InputError("unknown registration parameter group '" + group_key + "'");
}

void validatePipelineParams(const PipelineParams& p) {
  validateParams(PipelineParams::schema(), p);
  forEachParamGroup(p, [](const char* key, const char*, const auto& schema, const auto& group) {
    inGroup(key, [&] { validateParams(schema, group); });
  });
}

}  // namespace plumb
