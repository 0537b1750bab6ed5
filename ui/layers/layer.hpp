#pragma once
// A node of the layer tree: datasets (with their scans as children), models, feature sets,
// results. A layer owns its children and its VTK props; the Scene owns the root layers.
#include <QString>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "model/point_cloud.hpp"

class vtkProp;

namespace plumb::ui {

enum class LayerKind { Dataset, Scan, Model, Features, Result, Detail };

/// One row of the properties panel.
using PropertyRow = std::pair<QString, QString>;

/// One entry of a layer's colour legend (properties panel): what a colour in the view means.
struct LegendEntry {
  QString label;
  Rgb8 colour{};
};

class Layer {
 public:
  Layer(LayerKind kind, QString name);
  virtual ~Layer();
  Layer(const Layer&) = delete;
  Layer& operator=(const Layer&) = delete;

  LayerKind kind() const { return kind_; }
  const QString& name() const { return name_; }
  Layer* parent() const { return parent_; }
  const std::vector<std::unique_ptr<Layer>>& children() const { return children_; }
  Layer& addChild(std::unique_ptr<Layer> child);
  /// Detaches a direct child (nullptr if `child` is not one).
  std::unique_ptr<Layer> takeChild(const Layer* child);

  bool visible() const { return visible_; }
  /// Visible and every ancestor visible.
  bool effectivelyVisible() const;
  void setVisible(bool visible);

  /// This layer's own props (children have theirs), added to the renderer by the Scene.
  virtual std::vector<vtkProp*> props() const { return {}; }
  /// World bounds of this layer and its children.
  virtual Bounds bounds() const;
  /// World box the views frame (Reset camera, standard views, Zoom to layer): the bounds
  /// without outliers where the layer knows them (robust_bounds.hpp), else bounds().
  virtual Bounds framingBounds() const;
  /// Rows for the properties panel.
  virtual std::vector<PropertyRow> describe() const;
  /// The colours the layer is drawn with and what they mean (empty: a ramp or its own colours).
  virtual std::vector<LegendEntry> legend() const { return {}; }
  /// Level of detail: show the reduced representation while the camera moves.
  virtual void setReducedDetail(bool /*reduced*/) {}

  /// Expires when this layer is destroyed: background work and undo commands that outlive the
  /// layer check it before touching the layer (LayerRef).
  std::weak_ptr<const char> lifetime() const { return alive_; }

 protected:
  /// Called when the effective visibility of this layer may have changed.
  virtual void applyVisibility(bool /*effective*/) {}

 private:
  void propagateVisibility();
  LayerKind kind_;
  QString name_;
  Layer* parent_ = nullptr;
  bool visible_ = true;
  std::vector<std::unique_ptr<Layer>> children_;
  std::shared_ptr<char> alive_ = std::make_shared<char>();  ///< expires with this layer
};

/// A layer drawn by its own actors whose visibility follows two states: shown (the layer and
/// its ancestors visible) and reduced (the camera moves: level of detail). Each change calls
/// updateActors().
class ActorLayer : public Layer {
 public:
  using Layer::Layer;
  void setReducedDetail(bool reduced) override {
    reduced_ = reduced;
    updateActors();
  }

 protected:
  void applyVisibility(bool effective) override {
    shown_ = effective;
    updateActors();
  }
  /// Sets the actors' visibility and matrices from shown() and reduced().
  virtual void updateActors() = 0;
  bool shown() const { return shown_; }
  bool reduced() const { return reduced_; }

 private:
  bool shown_ = true;
  bool reduced_ = false;
};

/// A layer that may be destroyed while this is held (a running task, an undo command): get()
/// is the layer while it exists, nullptr once it was destroyed.
class LayerRef {
 public:
  LayerRef() = default;
  explicit LayerRef(Layer& layer) : layer_(&layer), alive_(layer.lifetime()) {}
  Layer* get() const { return alive_.expired() ? nullptr : layer_; }
  /// Whether this refers to `layer` (also after it was destroyed: compares addresses only).
  bool is(const Layer* layer) const { return layer_ && layer_ == layer && !alive_.expired(); }

 private:
  Layer* layer_ = nullptr;  ///< not owned; dereferenced only while alive_ holds
  std::weak_ptr<const char> alive_;
};

/// The layer, or an InputError naming it (`name`) when it was removed while `what` ran: a task
/// whose layer went away then finishes with that error and shows nothing.
Layer& stillThere(const LayerRef& layer, const QString& name, const char* what);

QString layerKindName(LayerKind kind);

}  // namespace plumb::ui
