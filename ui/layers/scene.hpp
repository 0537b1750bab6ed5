#pragma once
// The layers shown in one view: owns the root layers, puts their props into the renderer, and
// fixes the render origin (the first layer's centre) that keeps float precision.
#include <QObject>

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include <memory>
#include <optional>
#include <vector>

#include "model/clip_box.hpp"
#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "model/feature_set.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/layer.hpp"
#include "ui/layers/point_style.hpp"
#include "ui/layers/prepared_dataset.hpp"

class vtkRenderer;

namespace plumb::ui {

class DatasetLayer;
class ModelLayer;
class FeatureLayer;
class DetailLayer;
class TaskManager;

/// What a click in the view hit.
struct PickResult {
  Layer* layer = nullptr;  ///< the FeatureLayer drawing the feature
  FeatureRef feature;
  std::vector<PropertyRow> rows;
};

class Scene : public QObject {
  Q_OBJECT
 public:
  explicit Scene(vtkRenderer* renderer, QObject* parent = nullptr);
  ~Scene() override;

  const std::vector<std::unique_ptr<Layer>>& layers() const { return layers_; }
  /// World position of render (0,0,0); fixed by the first layer added.
  Eigen::Vector3d origin() const { return origin_.value_or(Eigen::Vector3d::Zero()); }

  /// Adds a dataset, building its display data on this thread (small data, tests).
  DatasetLayer& addDataset(std::shared_ptr<const Dataset> data);
  /// Adds a dataset whose display data was prepared off the UI thread (prepareDataset):
  /// only the VTK objects wrapping it are made here.
  DatasetLayer& addDataset(std::shared_ptr<const Dataset> data, PreparedDataset prepared);
  /// Background tasks for recolouring (requestStyle); null: recolour on the UI thread.
  void setTaskManager(TaskManager* tasks) { tasks_ = tasks; }
  TaskManager* taskManager() const { return tasks_; }
  /// Changes a dataset's style: in a background task of taskManager() when set (the view
  /// renders when the new colours are in), else now. Emits renderNeeded.
  void requestStyle(DatasetLayer& layer, const PointStyle& style);
  ModelLayer& addModel(std::shared_ptr<const BimModel> model);
  /// Adds features as a child of `parent` (a dataset or model layer) or at the root.
  FeatureLayer& addFeatures(QString name, std::shared_ptr<const FeatureSet> features,
                            Layer* parent = nullptr);
  /// Adds the full-resolution detail of `parent` (a dataset opened as a subsample) as its child.
  DetailLayer& addDetail(std::unique_ptr<DetailLayer> detail, DatasetLayer& parent);
  /// Removes a layer (root or child) and its children.
  void removeLayer(Layer* layer);
  /// Takes a root layer out of the scene without destroying it (undoable removal), with the
  /// signals of removeLayer; nullptr if `layer` is not a root layer.
  std::unique_ptr<Layer> takeLayer(Layer* layer);
  /// Puts a taken root layer back at `index` among the root layers (the end if beyond).
  void restoreLayer(std::unique_ptr<Layer> layer, std::size_t index);
  void clear();

  /// World bounds of the visible layers.
  Bounds visibleBounds() const;
  /// Union of the visible top-level layers' framing bounds (Layer::framingBounds): what the
  /// views frame, outliers left out.
  Bounds visibleFramingBounds() const;
  /// VTK bounds in render coordinates of a world box.
  void renderBounds(const Bounds& world, double out[6]) const;

  /// Moving detail on/off for every layer: the moving subsets (camera moving) or the still
  /// subsets (full detail unless a still budget is set). Switching only toggles visibility.
  void setMovingDetail(bool moving);
  bool movingDetail() const { return moving_; }
  /// Fewer points drawn than the scans hold: moving, or still with a still budget below them.
  bool reducedDetail() const;
  /// Points drawn per moving frame by the whole scene, split among the scans by size
  /// (LodBudget chooses it from measured frame times). Applies to layers added later too.
  void setLodBudget(std::size_t points);
  std::size_t lodBudget() const { return lod_budget_; }
  /// Points drawn per still frame by the whole scene, split among the scans by size;
  /// kFullDetail (the default): every point.
  static constexpr std::size_t kFullDetail = static_cast<std::size_t>(-1);
  void setStillBudget(std::size_t points);
  std::size_t stillBudget() const { return still_budget_; }
  /// Points the visible scans draw now (subsets while reduced, full clouds otherwise).
  std::size_t drawnPointCount() const;
  /// Picks a feature at display position (x, y), VTK convention (y up, device pixels).
  std::optional<PickResult> pick(int x, int y);
  /// Highlights the picked feature (and no other, in any layer); nullptr: none.
  void highlight(const PickResult* picked);

  /// Call after changing a layer's style, visibility, transform or distances: renders, and
  /// recolours a dataset in the background when its colours went stale.
  void layerChanged(Layer* layer);

  /// Clips every layer's drawing to `box` (world; nullopt: no clipping), layers added later
  /// included (clipping planes of the VTK mappers: drawing only, the data is untouched).
  void setClipBox(std::optional<ClipBox> box);
  const std::optional<ClipBox>& clipBox() const { return clip_; }

 signals:
  /// Emitted before `layer` (and its children) is destroyed.
  void layerAboutToBeRemoved(plumb::ui::Layer* layer);
  /// Layers were added or removed.
  void layersChanged();
  /// A layer's appearance changed: the view must render.
  void renderNeeded();
  /// A dataset added or restyled is not drawn as its style asks on some scans (they lack
  /// its data and are drawn by elevation): DatasetLayer::colourFallback's message.
  void colourFallback(const QString& message);

 private:
  void ensureOrigin(const Bounds& b);
  void applyClip(Layer& layer);
  void addProps(Layer& layer);
  void removeProps(Layer& layer);
  Layer& adopt(std::unique_ptr<Layer> layer, Layer* parent);
  /// Emits colourFallback when `layer` cannot show `style` as asked.
  void tellColourFallback(const DatasetLayer& layer, const PointStyle& style);

  vtkSmartPointer<vtkRenderer> renderer_;  ///< shared with the view
  std::vector<std::unique_ptr<Layer>> layers_;
  std::optional<Eigen::Vector3d> origin_;
  void applyLodBudget();
  std::size_t scanPointCount() const;
  bool moving_ = false;
  std::size_t lod_budget_;
  std::size_t still_budget_ = kFullDetail;
  TaskManager* tasks_ = nullptr;
  /// Scan colour of the next dataset's first scan (Scan colour mode): never reused, so a
  /// colour stays with its scan when other layers are removed.
  std::size_t next_scan_colour_ = 0;
  std::size_t next_dataset_colour_ = 0;  ///< Dataset colour of the next dataset, likewise
  std::optional<ClipBox> clip_;
};

}  // namespace plumb::ui
