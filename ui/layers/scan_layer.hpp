#pragma once
// One scan of a dataset drawn as points: a full-resolution actor (positions shared with the
// scan, no copy) and a level-of-detail actor (random subset) shown while the camera moves.
// The subset size follows the view's adaptive budget (LodBudget): the scan keeps a random
// order of up to kMaxLodPoints of its points, and any subset size is a prefix of that order.
#include <Eigen/Core>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "model/dataset.hpp"
#include "ui/layers/layer.hpp"
#include "ui/layers/point_coloring.hpp"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace plumb::ui {

class ScanLayer : public Layer {
 public:
  /// Largest subset kept for level of detail (bounds the memory of the random order).
  static constexpr std::size_t kMaxLodPoints = 5'000'000;

  /// `data` must hold scan `scan_index`; `lod_points` is the subset size for level of detail.
  ScanLayer(std::shared_ptr<const Dataset> data, std::size_t scan_index,
            const Eigen::Vector3d& origin, std::size_t lod_points);
  ~ScanLayer() override;

  const Scan& scan() const { return data_->scans[scan_index_]; }
  std::size_t scanIndex() const { return scan_index_; }
  std::size_t lodPointCount() const { return lod_indices_.size(); }
  /// Changes the subset size (clamped to [1, min(size, kMaxLodPoints)]); rebuilds the subset.
  void setLodPointCount(std::size_t points);
  /// Points drawn now (full cloud or subset, 0 when hidden).
  std::size_t drawnPointCount() const;

  /// Dataset frame -> world (a registration result; identity by default).
  void setDatasetTransform(const RigidTransform& t);
  /// Recolours both representations. z range is world elevation for the Elevation mode.
  void setStyle(const PointStyle& style, double z_min, double z_max);
  /// Per-point distances (Distance colour mode), ramp over [0, max_distance]; NaN drawn grey.
  void setDistances(std::vector<float> distances, double max_distance);
  const std::vector<float>& distances() const { return distances_; }
  /// Scan points -> world.
  Eigen::Matrix4d localToWorld() const;

  std::vector<vtkProp*> props() const override;
  Bounds bounds() const override;
  std::vector<PropertyRow> describe() const override;
  void setReducedDetail(bool reduced) override;

 protected:
  void applyVisibility(bool effective) override;

 private:
  void updateActors();
  bool usesLod() const;
  void copyLodColors();
  std::shared_ptr<const Dataset> data_;
  std::size_t scan_index_;
  Eigen::Vector3d origin_;
  RigidTransform dataset_transform_;
  std::vector<std::uint32_t> lod_order_;    ///< random order of a random subset
  std::vector<std::uint32_t> lod_indices_;  ///< the current subset, sorted (memory order)
  Bounds local_bounds_;  ///< of the scan's local (offset-relative) positions
  vtkSmartPointer<vtkPolyData> full_poly_;
  vtkSmartPointer<vtkPolyData> lod_poly_;
  vtkNew<vtkPolyDataMapper> full_mapper_;
  vtkNew<vtkPolyDataMapper> lod_mapper_;
  vtkNew<vtkActor> full_actor_;
  vtkNew<vtkActor> lod_actor_;
  std::vector<float> distances_;
  double distance_max_ = 1.0;
  bool reduced_ = false;
  bool shown_ = true;
};

}  // namespace plumb::ui
