#pragma once
// Full-resolution detail of a dataset opened as a subsample (issue 16, out-of-core viewing): a
// child layer of the DatasetLayer that draws, in still frames, the nodes of the file's
// level-of-detail cache (io/lod) the view needs within a point budget, over the subsample. The
// nodes are chosen and read by the DetailController; while the camera moves only the
// subsample is drawn. Hiding the layer (tree) hides the detail.
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <memory>

#include "io/lod/lod_cache.hpp"
#include "model/rigid_transform.hpp"
#include "ui/layers/layer.hpp"
#include "ui/lod/detail_points.hpp"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace plumb::ui {

class DetailLayer : public ActorLayer {
 public:
  DetailLayer(std::shared_ptr<const LodCache> cache, const Eigen::Vector3d& origin);
  ~DetailLayer() override;

  const std::shared_ptr<const LodCache>& cache() const { return cache_; }
  /// Dataset frame -> world (the parent's shown transform).
  void setDatasetTransform(const RigidTransform& t);
  const RigidTransform& datasetTransform() const { return transform_; }
  /// Draws `points` from now on (replacing what was drawn).
  void show(DetailPoints points);
  /// What is drawn: its nodes and colouring (empty before the first show).
  const DetailPoints& drawn() const { return shown_; }
  /// Points drawn now (0 while moving or hidden).
  std::size_t drawnPointCount() const;
  /// drawn().positions -> world coordinates (the dataset transform after the anchor), for
  /// picking on the detail.
  Eigen::Matrix4d localToWorld() const;
  void setPointSize(double pixels);
  double pointSize() const;
  /// The VTK poly data drawn (tests read its colours).
  vtkPolyData* polyData() const { return poly_; }

  std::vector<vtkProp*> props() const override;
  Bounds bounds() const override;
  std::vector<PropertyRow> describe() const override;

 protected:
  void updateActors() override;

 private:
  std::shared_ptr<const LodCache> cache_;
  Eigen::Vector3d origin_;
  RigidTransform transform_;
  DetailPoints shown_;
  vtkSmartPointer<vtkPolyData> poly_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
};

}  // namespace plumb::ui
