#pragma once
// The end-to-end registration: data -> features -> global method -> refinement -> quality
// report. `auto` picks the method from what the inputs carry and says which it used (the same
// whether the caller passes features or not: segments are detected when needed):
//   - a model (BIM/mesh) on either side: segments (scan segments vs the model's sharp edges);
//     when they find no placement (a corridor with few edges), the BIM's own planes (and
//     openings, from its IfcWindow/IfcDoor elements) as for two scans below. Segments that
//     find two placements stay ambiguous (settled on refined points);
//   - two scans: planes; when both sides carry openings on façades, openings too: alone when
//     planes fail (indoor/outdoor: the planes score is ambiguous there, the indoor floor fitting
//     the street ground about as well as the few interior surfaces the outdoor scan sees through
//     windows), as a cross-check when planes succeed (agreement -> the openings result, which
//     carries the wall thickness; disagreement -> ambiguous); segments as the last resort.
// After openings, the refinement starts below half the measured wall thickness so the indoor
// wall faces cannot snap onto the façade faces.
// Each attempt and the reason a method was skipped or failed is logged in the result.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/memory_budget.hpp"
#include "common/params.hpp"
#include "common/progress.hpp"
#include "common/seed.hpp"
#include "features/bim/bim_features.hpp"
#include "features/facades/opening_detection.hpp"
#include "features/mesh_edges/mesh_edges.hpp"
#include "features/planes/plane_extraction.hpp"
#include "features/segments/segment_detection.hpp"
#include "model/bim_model.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "quality/quality_report.hpp"
#include "quality/visibility_evidence.hpp"
#include "registration/auto/candidate_refinement.hpp"
#include "registration/openings/opening_registration.hpp"
#include "registration/orientation/orientation_params.hpp"
#include "registration/planes/plane_registration.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "registration/segments/segment_registration.hpp"

namespace plumb {

enum class RegistrationMethod { Auto, Planes, Openings, Segments, Icp };
std::string methodName(RegistrationMethod m);
/// "auto", "planes", ... ; throws InputError listing the valid names.
RegistrationMethod methodFromName(const std::string& name);

/// One side of a registration: a point cloud (world coordinates) or a model.
struct RegistrationSide {
  const PointCloud* cloud = nullptr;
  const BimModel* model = nullptr;
  /// Scanner position of a static scan (world); plane normals are then oriented towards it.
  std::optional<Eigen::Vector3d> viewpoint;
  /// Precomputed features (skips extraction when set).
  const FeatureSet* features = nullptr;
  /// Model only: points already sampled on its surface (sampleMeshSurface) for a refinement
  /// on samples (refinement.model-surface = samples, or GICP), reused across registrations
  /// against the same model; sampled on demand when null.
  const PointCloud* model_samples = nullptr;
  /// Model only, when the registration rests on chosen elements (issue 14): the whole model,
  /// which the verdict's free-space evidence is measured against (a scan sees every element,
  /// chosen or not). Null: `model` itself.
  const BimModel* whole_model = nullptr;
  bool isModel() const { return model != nullptr; }
  /// The model the scan's visibility is judged against.
  const BimModel& evidenceModel() const { return whole_model ? *whole_model : *model; }
};

struct PipelineParams {
  RegistrationMethod method = RegistrationMethod::Auto;
  bool refine = true;
  /// The source's orientation: levelled (Z up), Y-up, any, or auto (orientation_search.hpp).
  OrientationParams orientation;
  PlaneExtractionParams plane_extraction;
  OpeningDetectionParams opening_detection;
  SegmentDetectionParams segment_detection;
  MeshEdgeParams mesh_edges;
  /// The model's own planes, façades and openings (a model side).
  BimFeatureParams bim_features;
  PlaneRegistrationParams planes;
  OpeningRegistrationParams openings;
  SegmentRegistrationParams segments;
  RefineParams refinement;
  QualityParams quality;
  /// Free-space (visibility) check of the final transform (registration/auto/visibility_check).
  VisibilityParams visibility;
  /// Memory budget: when an input is read whole or subsampled while streaming
  /// (registration/auto/bounded_input.hpp). Not used by registerData itself.
  MemoryParams memory;
  /// Spacing of the points sampled on a model for refinement, metres, [0.005, 1] (advanced);
  /// used with refinement.model-surface = samples or GICP only.
  double model_sample_spacing = 0.05;
  /// The runner-up refined and compared with the answer (candidate_refinement.hpp); settles
  /// an Ambiguous global step on refined points (beyond the papers).
  CandidateParams candidates;
  /// auto, both sides carrying openings: planes and openings agree (-> the openings result)
  /// when their transforms differ by at most this rotation, deg, [0.01, 45] ...
  double agreement_rotation_deg = 2.0;
  /// ... and this translation, m, [0.001, 10]; otherwise the answer is ambiguous.
  double agreement_translation = 0.3;
  /// The one random seed of every step that draws at random (plane detection samples,
  /// openings hypotheses beyond max-hypotheses, model surface samples), [0, 9e15]. Results are
  /// deterministic for a seed. No parameter group has a seed of its own.
  std::uint64_t seed = kDefaultSeed;
  /// The top-level parameters (method, refine, seed, model-sample-spacing, agreement-*); the
  /// groups are
  /// listed by forEachParamGroup (pipeline_param_groups.hpp).
  static const ParamSchema<PipelineParams>& schema();
};

struct PipelineResult {
  QualityReport report;
  GlobalRegistrationResult global;
  std::optional<RefineResult> refinement;  ///< of the answer
  /// Every placement considered (the answer first), refined when refinement ran; also in the
  /// report.
  std::vector<PlacementCandidate> candidates;
  FeatureSet source_features, target_features;
  std::string method_used;
  std::vector<std::string> log;  ///< attempts and reasons, in order
  double seconds_features = 0, seconds_global = 0, seconds_refine = 0;
  bool success() const { return report.success; }
  /// The transform to apply to the source; only meaningful when success().
  const RigidTransform& transform() const { return report.transform; }
};

/// The segments of both sides, for auto's last-resort segments step.
struct SegmentSets {
  std::vector<Segment3D> source, target;
};
/// Gives the segments of both sides when auto needs them and a side has none (registerData
/// detects them on the clouds then: the pipeline decides, not the caller).
using SegmentsOnDemand = std::function<SegmentSets()>;

/// Global step only, on features (no refinement). `target_is_model` steers auto. Two scans:
/// segments are the last resort when both sets carry segments, or when `segments_on_demand`
/// can give them (called at most once, only when that step is reached).
GlobalRegistrationResult registerFeatureSets(const FeatureSet& source, const FeatureSet& target,
                                             bool target_is_model, const PipelineParams& params,
                                             std::vector<std::string>* log = nullptr,
                                             Progress* progress = nullptr,
                                             const SegmentsOnDemand& segments_on_demand = {});

/// The whole pipeline. Never throws for "could not register": the report says so.
PipelineResult registerData(const RegistrationSide& source, const RegistrationSide& target,
                            const PipelineParams& params, Progress* progress = nullptr);

/// Features of one side: planes + openings (+ segments when `with_segments`) for a scan; for a
/// model its own planes, façades and openings (features/bim) and its sharp edges.
FeatureSet extractFeatures(const RegistrationSide& side, const PipelineParams& params,
                           bool with_segments, std::vector<std::string>* log = nullptr,
                           Progress* progress = nullptr);

}  // namespace plumb
