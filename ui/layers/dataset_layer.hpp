#pragma once
// A loaded point dataset (one file): its scans are child ScanLayers. The dataset carries the
// registration transform (dataset frame -> world) and the point style of all its scans.
#include <QPointer>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/dataset.hpp"
#include "ui/layers/layer.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/point_style.hpp"
#include "ui/layers/prepared_dataset.hpp"

namespace plumb::ui {

class ScanLayer;
class Task;
class TaskManager;

struct DetailDistances;  // ui/lod/detail_points.hpp

/// A dataset opened as a voxel subsample because showing it whole would exceed the memory
/// budget (ui/tasks/load_budget.hpp): what the file holds and how it was thinned.
struct SubsampledFrom {
  std::uint64_t points_in_file = 0;  ///< points the file delivered
  double voxel = 0;                  ///< voxel edge of the subsample, metres
};

class DatasetLayer : public Layer {
 public:
  /// Points drawn per dataset while the camera moves (split among scans by size).
  static constexpr std::size_t kLodPointBudget = 1'500'000;

  /// Builds the display data on this thread (prepareDataset): for small data and tests.
  DatasetLayer(std::shared_ptr<const Dataset> data, const Eigen::Vector3d& origin,
               std::size_t lod_budget = kLodPointBudget);
  /// Wraps display data prepared off the UI thread (prepareDataset of `data`).
  DatasetLayer(std::shared_ptr<const Dataset> data, const Eigen::Vector3d& origin,
               PreparedDataset prepared, std::size_t lod_budget = kLodPointBudget);
  ~DatasetLayer() override;

  const Dataset& dataset() const { return *data_; }
  std::shared_ptr<const Dataset> sharedDataset() const { return data_; }
  std::vector<ScanLayer*> scans() const;

  /// The style last set or requested (the colours may still be computing: coloringPending).
  const PointStyle& style() const { return style_; }
  /// Recolours every scan now, on this thread. Supersedes a pending requestStyle.
  void setStyle(const PointStyle& style);
  /// Recolours in a background task of `tasks`: the point size and style() change now, the old
  /// colours stay shown until the new ones are swapped in on the UI thread, then `applied`
  /// runs (e.g. to render). A newer request (or setStyle) supersedes an older one: the older
  /// task is cancelled and its result never shown. Returns the task.
  Task* requestStyle(const PointStyle& style, TaskManager& tasks,
                     std::function<void()> applied = {});
  /// A requested style's colours are not shown yet.
  bool coloringPending() const { return coloring_pending_; }
  /// Names of the scalar fields present in any scan.
  std::vector<std::string> scalarFieldNames() const;

  /// Set when the layer holds a subsample of its file (opened above the memory budget):
  /// exports then stream the whole file, not these points.
  const std::optional<SubsampledFrom>& subsampledFrom() const { return subsampled_from_; }
  void setSubsampledFrom(const SubsampledFrom& s) { subsampled_from_ = s; }

  /// The registration transform applied to the whole dataset, and whether it is shown
  /// (before/after toggle). Elevation colours follow in the background once the scene is told
  /// (Scene::layerChanged).
  const RigidTransform& transform() const { return transform_; }
  void setTransform(const RigidTransform& t);
  bool showsTransform() const { return shows_transform_; }
  /// transform() when shown, else identity: what the scans are drawn with.
  RigidTransform shownTransform() const;
  void setShowsTransform(bool show);

  /// Distance to the registration target per point of each scan (NaN: no match), drawn by the
  /// Distance colour mode on `scale`; switches the style to it. The colours follow in the
  /// background once the scene is told (Scene::layerChanged).
  void setDistances(std::vector<std::vector<float>> per_scan, const DistanceScale& scale);
  bool hasDistances() const { return has_distances_; }
  /// The distances of each scan (exported as the "distance" field); empty without distances.
  std::vector<std::shared_ptr<const std::vector<float>>> distances() const;
  /// Drops the distances; the colour mode goes back to the one before them.
  void clearDistances();
  /// What the distances shown were measured to (DistanceCheck): the detail of a subsampled file
  /// measures its own points to it. Cleared with the distances.
  void setDistanceReference(std::shared_ptr<const DetailDistances> reference) { distance_reference_ = std::move(reference); }
  const std::shared_ptr<const DetailDistances>& distanceReference() const { return distance_reference_; }
  /// The colour mode without the distances: style().mode, or the one before them.
  PointColorMode modeWithoutDistances() const {
    return style_.mode == PointColorMode::Distance ? mode_before_distances_ : style_.mode;
  }

  /// Swaps in `with_origins`, the same points with per-point sensor origins interpolated from
  /// the trajectory file `path` (startAttachTrajectory): feature detection, registration and
  /// export use them from now on. Throws std::invalid_argument if the points differ.
  void attachTrajectory(std::shared_ptr<const Dataset> with_origins, const QString& path);
  /// Gives scan i the pose poses[i] (scan frame -> dataset frame; has_pose set), e.g. a network
  /// adjustment's: the points stay in their scan frames, a copy of the dataset with the new poses
  /// replaces the shown one, and the bounds follow. Throws std::invalid_argument when the count
  /// differs from the scans'.
  void setScanPoses(const std::vector<RigidTransform>& poses);
  /// Each scan's pose (scan frame -> dataset frame).
  std::vector<RigidTransform> scanPoses() const;
  /// The trajectory file attached (empty: none).
  const QString& trajectoryPath() const { return trajectory_; }

  /// True once when the colours no longer match the style (new distances, or a transform
  /// change under Elevation colours); Scene::layerChanged then recolours in the background.
  bool takeStaleColours();

  /// The dataset's exact bounds (those `plumb-cli info` reports) under the shown transform.
  Bounds bounds() const override;
  /// Its robust bounds (outliers left out) under the shown transform.
  Bounds framingBounds() const override;
  std::vector<PropertyRow> describe() const override;
  /// In the Scan colour mode, each scan with its colour; in the Dataset mode, the dataset's.
  std::vector<LegendEntry> legend() const override;
  /// The Scan colour index of the first scan and the Dataset colour index: scans and datasets
  /// are numbered across the scene (Scene::addDataset), so two single-scan datasets get two
  /// colours in either mode.
  void setColourIndices(std::size_t first_scan, std::size_t dataset);
  /// The Dataset colour mode's colour of this dataset, and its index (categoryColor).
  Rgb8 datasetColour() const;
  std::size_t datasetColourIndex() const { return dataset_colour_index_; }
  /// Why `style` is not drawn as asked (the scans lacking its data are drawn by elevation):
  /// one message naming the layer, what is missing and the scans concerned; empty when every
  /// scan shows it.
  QString colourFallback(const PointStyle& style) const;
  /// Whether any scan has RGB colours / intensities (what the colour modes can show).
  bool hasColors() const;
  bool hasIntensity() const;

 private:
  void applyTransform();
  /// The style's point size on every scan and on the level-of-detail detail.
  void applyPointSize();
  std::shared_ptr<const Dataset> data_;
  Bounds exact_bounds_, framing_;  ///< dataset frame (PreparedDataset)
  PointStyle style_;
  RigidTransform transform_;
  bool shows_transform_ = true;
  bool has_distances_ = false;
  std::shared_ptr<const DetailDistances> distance_reference_;
  PointColorMode mode_before_distances_ = PointColorMode::Rgb;
  bool colours_stale_ = false;
  std::size_t dataset_colour_index_ = 0;
  QString trajectory_;
  std::uint64_t style_generation_ = 0;  ///< bumped by every setStyle / requestStyle
  bool coloring_pending_ = false;
  QPointer<Task> coloring_task_;
  std::optional<SubsampledFrom> subsampled_from_;
};

}  // namespace plumb::ui
