#pragma once
// Detected features drawn over the data: plane polygons (filled, one colour each, with their
// rings as outlines), openings (rectangles) and 3D segments (lines). Each VTK cell records
// which feature it draws, so a pick maps back to the feature and its properties.
#include <vtkNew.h>

#include <memory>
#include <optional>

#include "model/feature_set.hpp"
#include "ui/layers/layer.hpp"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace plumb::ui {

enum class FeatureKind { Plane, Opening, Segment };

struct FeatureRef {
  FeatureKind kind = FeatureKind::Plane;
  std::size_t index = 0;
  bool operator==(const FeatureRef&) const = default;
};

class FeatureLayer : public Layer {
 public:
  FeatureLayer(QString name, std::shared_ptr<const FeatureSet> features,
               const Eigen::Vector3d& origin);
  ~FeatureLayer() override;

  const FeatureSet& features() const { return *features_; }
  std::shared_ptr<const FeatureSet> sharedFeatures() const { return features_; }
  void setTransform(const RigidTransform& t);

  /// The feature drawn by cell `cell` of the actor `prop`, if `prop` is this layer's.
  std::optional<FeatureRef> featureAt(const vtkProp* prop, long long cell) const;
  std::vector<PropertyRow> describeFeature(const FeatureRef& ref) const;
  /// Draws `ref`'s outline thick and white over everything of this layer (the picked feature);
  /// nullopt: none.
  void setHighlight(std::optional<FeatureRef> ref);
  const std::optional<FeatureRef>& highlight() const { return highlight_; }

  /// The outlines (plane rings, openings, segments): thin, drawn over the fills, so picked
  /// before them.
  vtkProp* outlineProp() const;
  std::vector<vtkProp*> props() const override;
  Bounds bounds() const override;
  std::vector<PropertyRow> describe() const override;

 protected:
  void applyVisibility(bool effective) override;

 private:
  std::shared_ptr<const FeatureSet> features_;
  Eigen::Vector3d origin_;
  RigidTransform transform_;
  std::vector<FeatureRef> fill_cells_;  ///< per cell of the filled polydata
  std::vector<FeatureRef> line_cells_;  ///< per cell of the line polydata
  vtkNew<vtkPolyDataMapper> fill_mapper_;
  vtkNew<vtkPolyDataMapper> line_mapper_;
  vtkNew<vtkActor> fill_actor_;
  vtkNew<vtkActor> line_actor_;
  std::optional<FeatureRef> highlight_;
  vtkNew<vtkPolyDataMapper> highlight_mapper_;
  vtkNew<vtkActor> highlight_actor_;
};

}  // namespace plumb::ui
