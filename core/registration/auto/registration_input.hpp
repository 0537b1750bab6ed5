#pragma once
// One side of a registration built from what a file holds (a dataset or a model) placed in
// world coordinates by `to_world` (identity for data as read; a previous registration
// otherwise). Used by the desktop app so it feeds registerData exactly like plumb-cli.
#include <optional>

#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/model_element_filter.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb {

struct RegistrationInput {
  PointCloud cloud;                  ///< scans merged, world (datasets)
  std::optional<BimModel> model;     ///< transformed copy (models)
  std::optional<Eigen::Vector3d> viewpoint;
  std::optional<FeatureSet> features;  ///< precomputed, world
  /// A model restricted to chosen elements: the filter and what it kept (issue 14).
  std::optional<ModelSelection> model_selection;
  /// With chosen elements: the whole model, moved like `model`; the verdict's free-space
  /// evidence and the distances of the visual check are measured against it.
  std::optional<BimModel> whole_model;
  /// Pointers into this object: do not move it while the side is in use.
  RegistrationSide side() const;
};

/// Merged scans (non-finite points removed), moved by `to_world`, with per-point sensor
/// origins when every scan has them (an MMS trajectory) or is a static station (a pose and no
/// per-point times: its origin is the pose translation); the openings need them. A single
/// static scan also gives its scanner position as the viewpoint (plane normals face it), and
/// so does a PCD file's VIEWPOINT when it lies among the points (the free-space check uses it).
/// Throws FileError when the dataset has no points.
RegistrationInput makeRegistrationInput(const Dataset& data, const RigidTransform& to_world);
/// Throws FileError when the model has no triangles.
RegistrationInput makeRegistrationInput(const BimModel& model, const RigidTransform& to_world);
/// The model restricted to the elements of `filter` (filterModelElements; its InputError when
/// nothing is kept), with the selection recorded and the whole model kept beside it for the
/// verdict's evidence; an empty filter keeps the whole model.
RegistrationInput makeRegistrationInput(const BimModel& model, const RigidTransform& to_world,
                                        const ModelElementFilter& filter);

/// What distances to this side are measured to: the model's triangles (the whole model's when
/// the registration rests on chosen elements: deviations from every element), else the merged
/// cloud (its sensor origins orient the signs). Points into `in`.
DistanceTarget distanceTarget(const RegistrationInput& in);

}  // namespace plumb
