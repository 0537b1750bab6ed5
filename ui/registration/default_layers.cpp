#include "ui/registration/default_layers.hpp"

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"

namespace plumb::ui {

LayerPair defaultRegistrationPair(const std::vector<std::unique_ptr<Layer>>& layers) {
  Layer* model = nullptr;
  Layer* largest = nullptr;
  std::size_t most = 0;
  for (const auto& l : layers) {
    if (!isRegistrable(l.get())) continue;
    if (l->kind() == LayerKind::Model) {
      if (!model) model = l.get();
    } else if (const std::size_t n = static_cast<const DatasetLayer&>(*l).dataset().pointCount();
               !largest || n > most) {
      largest = l.get();
      most = n;
    }
  }
  LayerPair pair;
  pair.target = model ? model : largest;
  for (const auto& l : layers)
    if (isRegistrable(l.get()) && l->kind() == LayerKind::Dataset && l.get() != pair.target) {
      pair.source = l.get();
      break;
    }
  if (!pair.source) pair.target = nullptr;
  return pair;
}

}  // namespace plumb::ui
