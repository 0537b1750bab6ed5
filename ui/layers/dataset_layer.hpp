#pragma once
// A loaded point dataset (one file): its scans are child ScanLayers. The dataset carries the
// registration transform (dataset frame -> world) and the point style of all its scans.
#include <memory>
#include <string>
#include <vector>

#include "model/dataset.hpp"
#include "ui/layers/layer.hpp"
#include "ui/layers/point_style.hpp"

namespace plumb::ui {

class ScanLayer;

class DatasetLayer : public Layer {
 public:
  /// Points drawn per dataset while the camera moves (split among scans by size).
  static constexpr std::size_t kLodPointBudget = 1'500'000;

  DatasetLayer(std::shared_ptr<const Dataset> data, const Eigen::Vector3d& origin,
               std::size_t lod_budget = kLodPointBudget);

  const Dataset& dataset() const { return *data_; }
  std::shared_ptr<const Dataset> sharedDataset() const { return data_; }
  std::vector<ScanLayer*> scans() const;

  const PointStyle& style() const { return style_; }
  void setStyle(const PointStyle& style);
  /// Names of the scalar fields present in any scan.
  std::vector<std::string> scalarFieldNames() const;

  /// The registration transform applied to the whole dataset, and whether it is shown
  /// (before/after toggle).
  const RigidTransform& transform() const { return transform_; }
  void setTransform(const RigidTransform& t);
  bool showsTransform() const { return shows_transform_; }
  void setShowsTransform(bool show);

  /// Distance to the registration target per point of each scan (NaN: no match), drawn by the
  /// Distance colour mode on a ramp over [0, max_distance]; switches the style to it.
  void setDistances(std::vector<std::vector<float>> per_scan, double max_distance);
  bool hasDistances() const { return has_distances_; }

  std::vector<PropertyRow> describe() const override;

 private:
  void applyTransform();
  std::shared_ptr<const Dataset> data_;
  PointStyle style_;
  RigidTransform transform_;
  bool shows_transform_ = true;
  bool has_distances_ = false;
};

}  // namespace plumb::ui
