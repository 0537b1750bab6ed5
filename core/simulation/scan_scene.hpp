#pragma once
// What a simulated scanner sees: a model's mesh (glass panes skipped: the laser passes through
// them) plus, optionally, a ground plane around it at the model's lowest z (MMS sees the
// street). Ray casting against any mesh: generated buildings or imported IFC/OBJ models.
#include <cstdint>
#include <memory>
#include <vector>

#include "model/bim_model.hpp"
#include "simulation/ray_caster.hpp"

namespace plumb {

struct ScanSceneOptions {
  bool ground = true;            ///< add a ground quad at the model's minimum z
  double ground_margin = 150.0;  ///< m, ground extends this far beyond the model bounds
  bool glass_transparent = true; ///< skip triangles flagged as glass
  RayCasterBackend backend = RayCaster::defaultBackend();
};

class ScanScene {
 public:
  /// `glass` flags triangles of model.mesh (may be empty = no glass).
  ScanScene(const BimModel& model, const std::vector<bool>& glass = {}, const ScanSceneOptions& options = {});
  const RayCaster& caster() const { return *caster_; }
  /// True for triangles of the added ground (indices past the model's triangles).
  bool isGround(std::uint32_t triangle) const { return triangle >= model_triangles_; }
  std::size_t modelTriangles() const { return model_triangles_; }

 private:
  std::size_t model_triangles_ = 0;
  std::unique_ptr<RayCaster> caster_;
};

}  // namespace plumb
