#pragma once
// The Registration dock's source and target combo boxes: the registrable layers of the scene,
// listed again whenever the layers change. The choice of the user (or of a project) holds
// while both layers are there and differ; until then, and after, the default pair
// (defaultRegistrationPair).
#include <QObject>

class QComboBox;
class QWidget;

namespace plumb::ui {

class Layer;
class Scene;

class LayerPairCombos : public QObject {
  Q_OBJECT
 public:
  /// The combo boxes are children of `parent` (the dock), which places them.
  LayerPairCombos(Scene& scene, QWidget* parent);

  QComboBox& source() const { return *source_; }
  QComboBox& target() const { return *target_; }
  Layer* sourceLayer() const;
  Layer* targetLayer() const;
  /// Selects `layer` as chosen by the user.
  void setSourceLayer(const Layer* layer);
  void setTargetLayer(const Layer* layer);
  void setEnabled(bool enabled);

 signals:
  /// The selection or the list changed.
  void changed();

 private:
  void rebuild();
  static Layer* selected(const QComboBox& combo);
  static void select(QComboBox& combo, const Layer* layer);

  Scene& scene_;
  QComboBox* source_;
  QComboBox* target_;
  bool chosen_ = false;  ///< the user (or a project) chose the source/target
};

}  // namespace plumb::ui
