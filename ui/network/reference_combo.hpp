#pragma once
// The Network dock's "Reference": the first station, any station by name (plumb-cli network
// --reference NAME), or a model layer (--model: the network comes out in the model's frame).
// The station names are those the run will give (NetworkInputs::stationNames), refreshed when
// the layers change; the choice is kept across refreshes while it still exists.
#include <QComboBox>

#include <string>

namespace plumb::ui {

class Layer;
class Scene;

class ReferenceCombo : public QComboBox {
  Q_OBJECT
 public:
  explicit ReferenceCombo(QWidget* parent = nullptr);

  void refresh(const Scene& scene);
  /// The chosen model layer of `scene` (nullptr: a station is the reference).
  const Layer* model(const Scene& scene) const;
  /// The chosen station's name; empty for the first station or a model.
  std::string station() const;
  /// Chooses station `name`; false when the combo does not offer it.
  bool chooseStation(const QString& name);
};

}  // namespace plumb::ui
