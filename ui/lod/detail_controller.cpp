#include "ui/lod/detail_controller.hpp"

#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "ui/app_context.hpp"
#include "ui/layers/color_ramp.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/lod/camera_lod_view.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {

/// Intensity limits of the dataset's subsample, robust as the subsample's own ramp (1 % and
/// 99 % quantiles, robustRange): one bright retro-reflector must not turn the detail grey.
std::pair<double, double> intensityRange(const Dataset& data) {
  std::vector<float> values;
  for (const Scan& s : data.scans) values.insert(values.end(), s.cloud.intensity.begin(), s.cloud.intensity.end());
  if (values.empty()) return {0.0, 0.0};
  return robustRange(values);
}

DetailColouring colouringOf(const DatasetLayer& dataset, const DetailLayer& detail) {
  DetailColouring c;
  c.coloring.style = dataset.style();
  c.coloring.dataset_index = dataset.datasetColourIndex();
  const std::vector<ScanLayer*> scans = dataset.scans();
  if (!scans.empty()) c.coloring.scan_index = scans.front()->colourIndex();
  for (const ScanLayer* s : scans) {
    if (c.station_colour.size() <= s->scanIndex()) c.station_colour.resize(s->scanIndex() + 1, 0);
    c.station_colour[s->scanIndex()] = s->colourIndex();
  }
  c.coloring.elevation_row = detail.datasetTransform().matrix().row(2).transpose();
  const Bounds b = dataset.bounds();
  c.coloring.z_min = b.min.z();
  c.coloring.z_max = b.max.z();
  std::tie(c.coloring.value_min, c.coloring.value_max) = intensityRange(dataset.dataset());
  if (c.coloring.style.mode == PointColorMode::Distance) c.distances = dataset.distanceReference();
  c.to_world = detail.datasetTransform();
  return c;
}

}  // namespace

DetailController::DetailController(AppContext& app, LodController& lod, QObject* parent)
    : QObject(parent), app_(app), lod_(lod) {
  connect(&lod_, &LodController::stillFrameDrawn, this, [this] { refresh(); });
}

void DetailController::refresh() {
  if (lod_.moving()) return;
  std::vector<std::pair<DatasetLayer*, DetailLayer*>> shown;
  for (const auto& root : app_.scene.layers()) {
    if (root->kind() != LayerKind::Dataset || !root->effectivelyVisible()) continue;
    auto& dataset = static_cast<DatasetLayer&>(*root);
    for (const auto& child : dataset.children())
      if (child->kind() == LayerKind::Detail && child->effectivelyVisible())
        shown.emplace_back(&dataset, static_cast<DetailLayer*>(child.get()));
  }
  // One still frame's budget for all files: a campaign of several files draws (and holds) no
  // more detail than one.
  const std::size_t budget = shown.empty() ? 0 : lod_.stillBudget().points() / shown.size();
  for (auto [dataset, detail] : shown)
    refreshLayer(*dataset, *detail, {std::clamp(budget, kMinPoints, kMaxPoints), shown.size()});
}

void DetailController::refreshLayer(DatasetLayer& dataset, DetailLayer& detail, Share share) {
  if (loading_.count(&detail)) return;
  VtkViewWidget& view = app_.view;
  const double dpr = view.devicePixelRatioF();
  const CameraState camera = cameraState(*view.renderer()->GetActiveCamera(), int(view.width() * dpr),
                                         int(view.height() * dpr));
  LodSelectParams select;
  select.point_budget = share.points;
  const LodView lod_view = lodViewInDataset(camera, app_.scene.origin(), detail.datasetTransform());
  std::vector<std::uint32_t> nodes = selectLodNodes(detail.cache()->hierarchy(), lod_view, select).nodes;
  const DetailColouring colouring = colouringOf(dataset, detail);
  if (nodes == detail.drawn().nodes && colouring == detail.drawn().colouring && detail.polyData()) return;
  loading_[&detail] = true;
  const LayerRef held(detail);
  const Layer* key = &detail;
  Task* task = app_.tasks.run(
      tr("Loading detail of %1").arg(dataset.name()),
      [cache = detail.cache(), nodes = std::move(nodes), colouring, held, share, this](Progress& progress) -> Task::Apply {
        auto points = std::make_shared<DetailPoints>(loadDetailPoints(*cache, nodes, colouring, &progress));
        points->point_budget = share.points;
        points->layers_sharing = share.layers;
        return [points, held, this] {
          if (auto* target = static_cast<DetailLayer*>(held.get())) {
            target->show(std::move(*points));
            app_.view.requestRender();
            emit detailShown();
          }
        };
      });
  connect(task, &Task::finished, this, [this, key, name = dataset.name()](bool ok, const QString& message) {
    loading_.erase(key);
    if (!ok && message != "cancelled") app_.log.error(tr("Cannot load the detail of %1: %2").arg(name, message));
  });
}

}  // namespace plumb::ui
