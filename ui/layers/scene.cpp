#include "ui/layers/scene.hpp"

#include <vtkActor.h>
#include <vtkCellPicker.h>
#include <vtkMapper.h>
#include <vtkPlane.h>
#include <vtkProp.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

#include "ui/layers/dataset_layer.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/render_frame.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/view/lod_budget.hpp"

namespace plumb::ui {

namespace {

template <class F>
void forEachLayer(Layer& layer, const F& f) {
  f(layer);
  for (const auto& c : layer.children()) forEachLayer(*c, f);
}

}  // namespace

Scene::Scene(vtkRenderer* renderer, QObject* parent)
    : QObject(parent), renderer_(renderer), lod_budget_(LodBudget().points()) {}

Scene::~Scene() {
  for (auto& l : layers_) removeProps(*l);
}

void Scene::ensureOrigin(const Bounds& b) {
  if (origin_ || b.empty()) return;
  // Rounded to metres: render coordinates stay readable and exactly representable.
  const Eigen::Vector3d c = b.center();
  origin_ = Eigen::Vector3d(std::round(c.x()), std::round(c.y()), std::round(c.z()));
}

DatasetLayer& Scene::addDataset(std::shared_ptr<const Dataset> data) {
  PreparedDataset prepared = prepareDataset(data);
  return addDataset(std::move(data), std::move(prepared));
}

DatasetLayer& Scene::addDataset(std::shared_ptr<const Dataset> data, PreparedDataset prepared) {
  ensureOrigin(prepared.bounds);
  const std::size_t scans = data->scans.size();
  auto& layer = static_cast<DatasetLayer&>(adopt(
      std::make_unique<DatasetLayer>(std::move(data), origin(), std::move(prepared)), nullptr));
  // Scan and Dataset colours: numbered across the scene, never reused.
  layer.setColourIndices(next_scan_colour_, next_dataset_colour_++);
  next_scan_colour_ += scans;
  tellColourFallback(layer, layer.style());
  return layer;
}

void Scene::tellColourFallback(const DatasetLayer& layer, const PointStyle& style) {
  if (const QString why = layer.colourFallback(style); !why.isEmpty()) emit colourFallback(why);
}

void Scene::requestStyle(DatasetLayer& layer, const PointStyle& style) {
  if (style.mode != layer.style().mode || style.scalar_field != layer.style().scalar_field)
    tellColourFallback(layer, style);
  if (tasks_) {
    layer.requestStyle(style, *tasks_, [this] { emit renderNeeded(); });
  } else {
    layer.setStyle(style);
  }
  emit renderNeeded();  // point size now; the colours when they are in
}

ModelLayer& Scene::addModel(std::shared_ptr<const BimModel> model) {
  ensureOrigin(model->mesh.bounds());
  return static_cast<ModelLayer&>(
      adopt(std::make_unique<ModelLayer>(std::move(model), origin()), nullptr));
}

FeatureLayer& Scene::addFeatures(QString name, std::shared_ptr<const FeatureSet> features,
                                 Layer* parent) {
  auto layer = std::make_unique<FeatureLayer>(name, features, origin());
  if (!origin_) {
    // The first layer fixes the render origin: rebuild the layer relative to it.
    ensureOrigin(layer->bounds());
    if (origin_) layer = std::make_unique<FeatureLayer>(std::move(name), std::move(features), origin());
  }
  return static_cast<FeatureLayer&>(adopt(std::move(layer), parent));
}

DetailLayer& Scene::addDetail(std::unique_ptr<DetailLayer> detail, DatasetLayer& parent) {
  return static_cast<DetailLayer&>(adopt(std::move(detail), &parent));
}

Layer& Scene::adopt(std::unique_ptr<Layer> layer, Layer* parent) {
  Layer* added = nullptr;
  if (parent) {
    added = &parent->addChild(std::move(layer));
  } else {
    layers_.push_back(std::move(layer));
    added = layers_.back().get();
  }
  addProps(*added);
  applyLodBudget();
  added->setReducedDetail(moving_);
  emit layersChanged();
  emit renderNeeded();
  return *added;
}

void Scene::addProps(Layer& layer) {
  forEachLayer(layer, [this](Layer& l) {
    for (vtkProp* p : l.props()) renderer_->AddViewProp(p);
  });
  applyClip(layer);
}

void Scene::setClipBox(std::optional<ClipBox> box) {
  clip_ = std::move(box);
  for (const auto& l : layers_) applyClip(*l);
  emit renderNeeded();
}

void Scene::applyClip(Layer& layer) {
  // One plane per finite face, its normal pointing inside (VTK keeps the normal's side).
  std::vector<vtkSmartPointer<vtkPlane>> planes;
  if (clip_) {
    const Eigen::Vector3d o = origin();
    for (int a = 0; a < 3; ++a)
      for (int side : {-1, 1}) {
        const double v = side < 0 ? clip_->min[a] : clip_->max[a];
        if (!std::isfinite(v)) continue;
        auto plane = vtkSmartPointer<vtkPlane>::New();
        double point[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
        point[a] = v - o[a];
        normal[a] = side < 0 ? 1.0 : -1.0;
        plane->SetOrigin(point);
        plane->SetNormal(normal);
        planes.push_back(plane);
      }
  }
  forEachLayer(layer, [&planes](Layer& l) {
    for (vtkProp* p : l.props()) {
      auto* actor = vtkActor::SafeDownCast(p);
      if (!actor || !actor->GetMapper()) continue;
      actor->GetMapper()->RemoveAllClippingPlanes();
      for (const auto& plane : planes) actor->GetMapper()->AddClippingPlane(plane);
    }
  });
}

void Scene::removeProps(Layer& layer) {
  forEachLayer(layer, [this](Layer& l) {
    for (vtkProp* p : l.props()) renderer_->RemoveViewProp(p);
  });
}

void Scene::removeLayer(Layer* layer) {
  if (!layer) return;
  if (Layer* parent = layer->parent()) {
    emit layerAboutToBeRemoved(layer);
    removeProps(*layer);
    parent->takeChild(layer);
    emit layersChanged();
    emit renderNeeded();
    return;
  }
  takeLayer(layer);  // destroyed here
}

std::unique_ptr<Layer> Scene::takeLayer(Layer* layer) {
  auto it = std::find_if(layers_.begin(), layers_.end(),
                         [layer](const auto& l) { return l.get() == layer; });
  if (it == layers_.end()) return nullptr;
  emit layerAboutToBeRemoved(layer);
  removeProps(**it);
  std::unique_ptr<Layer> taken = std::move(*it);
  layers_.erase(it);
  emit layersChanged();
  emit renderNeeded();
  return taken;
}

void Scene::restoreLayer(std::unique_ptr<Layer> layer, std::size_t index) {
  if (!layer) return;
  Layer& restored = **layers_.insert(layers_.begin() + std::ptrdiff_t(std::min(index, layers_.size())),
                                     std::move(layer));
  addProps(restored);
  applyLodBudget();
  restored.setReducedDetail(moving_);
  emit layersChanged();
  emit renderNeeded();
}

void Scene::clear() {
  for (auto& l : layers_) {
    emit layerAboutToBeRemoved(l.get());
    removeProps(*l);
  }
  layers_.clear();
  origin_.reset();
  next_scan_colour_ = next_dataset_colour_ = 0;
  emit layersChanged();
}

Bounds Scene::visibleBounds() const {
  Bounds b;
  for (const auto& l : layers_)
    forEachLayer(*l, [&b](Layer& x) {
      if (x.effectivelyVisible() && x.children().empty()) b.extend(x.bounds());
    });
  return b;
}

Bounds Scene::visibleFramingBounds() const {
  Bounds b;
  for (const auto& l : layers_)
    if (l->effectivelyVisible()) b.extend(l->framingBounds());
  return b;
}

void Scene::renderBounds(const Bounds& world, double out[6]) const {
  toRenderBounds(world, origin(), out);
}

void Scene::setMovingDetail(bool moving) {
  moving_ = moving;
  for (auto& l : layers_) forEachLayer(*l, [moving](Layer& x) { x.setReducedDetail(moving); });
}

bool Scene::reducedDetail() const {
  return moving_ || (still_budget_ != kFullDetail && still_budget_ < scanPointCount());
}

void Scene::setLodBudget(std::size_t points) {
  lod_budget_ = points;
  applyLodBudget();
}

void Scene::setStillBudget(std::size_t points) {
  still_budget_ = points;
  applyLodBudget();
}

std::size_t Scene::scanPointCount() const {
  std::size_t n = 0;
  for (const auto& l : layers_)
    forEachLayer(*l, [&n](Layer& x) {
      if (x.kind() == LayerKind::Scan) n += static_cast<ScanLayer&>(x).scan().cloud.size();
    });
  return n;
}

void Scene::applyLodBudget() {
  std::vector<ScanLayer*> scans;
  std::size_t total = 0;
  for (auto& l : layers_)
    forEachLayer(*l, [&](Layer& x) {
      if (x.kind() != LayerKind::Scan) return;
      scans.push_back(static_cast<ScanLayer*>(&x));
      total += scans.back()->scan().cloud.size();
    });
  if (total == 0) return;
  // Each scan's share of a budget, rounded down, in exact integer arithmetic (in doubles,
  // budget / total * n came out one point short for a single scan, e.g. 114,539 of 114,540).
  const auto share = [total](std::size_t budget, std::size_t n) {
    if (budget >= total) return n;
    return static_cast<std::size_t>(static_cast<unsigned __int128>(budget) * n / total);
  };
  for (ScanLayer* s : scans) {
    const std::size_t n = s->scan().cloud.size();
    s->setLodPointCount(share(lod_budget_, n));
    s->setStillPointCount(share(still_budget_, n));
  }
}

std::size_t Scene::drawnPointCount() const {
  std::size_t n = 0;
  for (const auto& l : layers_)
    forEachLayer(*l, [&n](Layer& x) {
      if (x.kind() == LayerKind::Scan) n += static_cast<ScanLayer&>(x).drawnPointCount();
    });
  return n;
}

std::optional<PickResult> Scene::pick(int x, int y) {
  // Outlines (openings, segments, plane rings) first: they are thin lines drawn over the
  // translucent plane fills, and a click on one means that feature, not the wall behind it.
  std::vector<FeatureLayer*> feature_layers;
  for (auto& l : layers_)
    forEachLayer(*l, [&](Layer& layer) {
      if (layer.kind() == LayerKind::Features && layer.effectivelyVisible())
        feature_layers.push_back(static_cast<FeatureLayer*>(&layer));
    });
  for (const bool outlines_only : {true, false}) {
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.005);
    if (outlines_only) {
      picker->PickFromListOn();
      for (FeatureLayer* f : feature_layers) picker->AddPickList(f->outlineProp());
    }
    if (!picker->Pick(x, y, 0.0, renderer_)) continue;
    vtkProp* prop = picker->GetViewProp();
    for (FeatureLayer* f : feature_layers)
      if (auto ref = f->featureAt(prop, picker->GetCellId()))
        return PickResult{f, *ref, f->describeFeature(*ref)};
    if (!outlines_only) break;
  }
  return std::nullopt;
}

void Scene::highlight(const PickResult* picked) {
  for (auto& l : layers_)
    forEachLayer(*l, [picked](Layer& layer) {
      if (layer.kind() != LayerKind::Features) return;
      auto& f = static_cast<FeatureLayer&>(layer);
      if (picked && picked->layer == &layer) f.setHighlight(picked->feature);
      else if (f.highlight()) f.setHighlight(std::nullopt);
    });
  emit renderNeeded();
}

void Scene::layerChanged(Layer* layer) {
  // New distances, or a transform under Elevation colours: recolour off the UI thread.
  if (layer && layer->kind() == LayerKind::Dataset) {
    auto& dataset = static_cast<DatasetLayer&>(*layer);
    if (dataset.takeStaleColours()) requestStyle(dataset, dataset.style());
  }
  emit renderNeeded();
}

}  // namespace plumb::ui
