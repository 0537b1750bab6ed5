#pragma once
// The parameter groups of the registration pipeline, listed once: each nested Params struct of
// PipelineParams with its key, label and schema. The UI's parameter panels, the project file's
// JSON and any CLI flag set come from this one list.
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

/// Calls f(key, label, schema, params_member) for every group, in pipeline order. `P` is
/// PipelineParams or const PipelineParams.
template <class P, class F>
void forEachParamGroup(P& p, F&& f) {
  f("orientation", "Source orientation", OrientationParams::schema(), p.orientation);
  f("plane-extraction", "Plane extraction", PlaneExtractionParams::schema(), p.plane_extraction);
  f("opening-detection", "Opening detection", OpeningDetectionParams::schema(), p.opening_detection);
  f("segment-detection", "Segment detection", SegmentDetectionParams::schema(), p.segment_detection);
  f("mesh-edges", "Model sharp edges", MeshEdgeParams::schema(), p.mesh_edges);
  f("bim-features", "Model planes and openings", BimFeatureParams::schema(), p.bim_features);
  f("planes", "Planes registration", PlaneRegistrationParams::schema(), p.planes);
  f("openings", "Openings registration", OpeningRegistrationParams::schema(), p.openings);
  f("segments", "Segments registration", SegmentRegistrationParams::schema(), p.segments);
  f("refinement", "Refinement (ICP)", RefineParams::schema(), p.refinement);
  f("candidates", "Candidate placements", CandidateParams::schema(), p.candidates);
  f("quality", "Quality checks", QualityParams::schema(), p.quality);
  f("visibility", "Free-space check", VisibilityParams::schema(), p.visibility);
  f("memory", "Memory budget", MemoryParams::schema(), p.memory);
}

/// Whether the group `key` takes part in a registration with `method` (auto: all). The
/// top-level parameters (key "registration") take part in every one.
bool paramGroupUsedBy(const std::string& key, RegistrationMethod method);

/// {"method": "auto", "refine": true, "seed": 1, "model-sample-spacing": 0.05,
///  "<group key>": {<param key>: value, ...}, ...}: the top level from PipelineParams::schema(),
/// each group from its own schema.
nlohmann::json pipelineParamsToJson(const PipelineParams& params);
/// Reads the keys present (others keep their value); throws InputError naming the key (and its
/// group) for unknown keys, values of the wrong type or out of range. A group "seed" (files
/// written before the groups lost their seeds) is accepted when it equals the top-level seed,
/// else it is an error naming "<group>"."seed".
void pipelineParamsFromJson(const nlohmann::json& j, PipelineParams& params);
/// Sets one parameter from text: "GROUP.KEY" for a group's parameter ("planes.max-tilt"),
/// "KEY" for a top-level one ("seed"). Throws InputError naming the group or the key when
/// unknown, or the value when it is invalid. `plumb-cli register --set GROUP.KEY=VALUE`.
void setPipelineParam(PipelineParams& params, const std::string& path, const std::string& text);
/// Range check of the top-level parameters and of every group; throws InputError naming the
/// group and the parameter. registerData calls it first.
void validatePipelineParams(const PipelineParams& params);

}  // namespace plumb
