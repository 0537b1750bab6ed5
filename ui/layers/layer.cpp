#include "ui/layers/layer.hpp"

#include "common/error.hpp"

namespace plumb::ui {

Layer::Layer(LayerKind kind, QString name) : kind_(kind), name_(std::move(name)) {}

Layer::~Layer() = default;

Layer& Layer::addChild(std::unique_ptr<Layer> child) {
  child->parent_ = this;
  children_.push_back(std::move(child));
  children_.back()->propagateVisibility();
  return *children_.back();
}

std::unique_ptr<Layer> Layer::takeChild(const Layer* child) {
  for (auto it = children_.begin(); it != children_.end(); ++it)
    if (it->get() == child) {
      std::unique_ptr<Layer> out = std::move(*it);
      children_.erase(it);
      out->parent_ = nullptr;
      return out;
    }
  return nullptr;
}

bool Layer::effectivelyVisible() const {
  for (const Layer* l = this; l; l = l->parent_)
    if (!l->visible_) return false;
  return true;
}

void Layer::setVisible(bool visible) {
  visible_ = visible;
  propagateVisibility();
}

void Layer::propagateVisibility() {
  applyVisibility(effectivelyVisible());
  for (auto& c : children_) c->propagateVisibility();
}

Bounds Layer::bounds() const {
  Bounds b;
  for (const auto& c : children_) b.extend(c->bounds());
  return b;
}

Bounds Layer::framingBounds() const {
  if (children_.empty()) return bounds();
  Bounds b;
  for (const auto& c : children_) b.extend(c->framingBounds());
  return b;
}

std::vector<PropertyRow> Layer::describe() const {
  std::vector<PropertyRow> rows{{"Name", name_}, {"Kind", layerKindName(kind_)}};
  const Bounds b = bounds();
  if (!b.empty()) {
    const auto s = b.size();
    rows.emplace_back("Extent (m)", QString("%1 x %2 x %3")
                                        .arg(s.x(), 0, 'f', 2)
                                        .arg(s.y(), 0, 'f', 2)
                                        .arg(s.z(), 0, 'f', 2));
  }
  return rows;
}

QString layerKindName(LayerKind kind) {
  switch (kind) {
    case LayerKind::Dataset: return "Dataset";
    case LayerKind::Scan: return "Scan";
    case LayerKind::Model: return "Model";
    case LayerKind::Features: return "Features";
    case LayerKind::Result: return "Result";
    case LayerKind::Detail: return "Level-of-detail cache";
  }
  return "Layer";
}

Layer& stillThere(const LayerRef& layer, const QString& name, const char* what) {
  if (Layer* l = layer.get()) return *l;
  throw InputError("'" + name.toStdString() + "' was removed during " + what +
                   "; the result was dropped");
}

}  // namespace plumb::ui
