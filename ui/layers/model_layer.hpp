#pragma once
// A BIM model (or any mesh) drawn shaded, coloured by IFC element type, with optional edges
// and transparency.
#include <vtkNew.h>

#include <memory>

#include "model/bim_model.hpp"
#include "ui/layers/layer.hpp"

class vtkActor;
class vtkPolyDataMapper;

namespace plumb::ui {

struct MeshStyle {
  bool edges = false;
  double opacity = 1.0;  ///< 0 (invisible) .. 1 (opaque)
};

class ModelLayer : public Layer {
 public:
  ModelLayer(std::shared_ptr<const BimModel> model, const Eigen::Vector3d& origin);
  ~ModelLayer() override;

  const BimModel& model() const { return *model_; }
  std::shared_ptr<const BimModel> sharedModel() const { return model_; }
  const MeshStyle& style() const { return style_; }
  void setStyle(const MeshStyle& style);
  const RigidTransform& transform() const { return transform_; }
  void setTransform(const RigidTransform& t);

  std::vector<vtkProp*> props() const override;
  Bounds bounds() const override;
  std::vector<PropertyRow> describe() const override;
  /// Each IFC type of the model with its colour (ifcTypeColor) and element count.
  std::vector<LegendEntry> legend() const override;

 protected:
  void applyVisibility(bool effective) override;

 private:
  std::shared_ptr<const BimModel> model_;
  Eigen::Vector3d origin_;
  RigidTransform transform_;
  MeshStyle style_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
};

}  // namespace plumb::ui
