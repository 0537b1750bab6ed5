#pragma once
// The source and target the Registration dock proposes before the user picks: a scan moves
// onto the model, or onto the largest other dataset. Never the same layer twice, so the first
// click on Register works.
#include <memory>
#include <utility>
#include <vector>

namespace plumb::ui {

class Layer;

struct LayerPair {
  Layer* source = nullptr;
  Layer* target = nullptr;
};

/// Among the registrable layers of `layers`: target = the first model, else the dataset with
/// the most points; source = the first dataset that is not the target. Both null unless two
/// different layers exist.
LayerPair defaultRegistrationPair(const std::vector<std::unique_ptr<Layer>>& layers);

}  // namespace plumb::ui
