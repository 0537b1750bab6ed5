#pragma once
// "Apply poses" of the Network dock on the undo stack: each dataset layer holding a placed
// station gets the adjusted poses as its scans' poses and the reference's layer transform
// (the registered frame is the reference station's frame), so the 3D view shows the campaign
// as registered. Undo puts the scans' poses and the layer transforms back. A layer destroyed
// meanwhile makes the command a no-op the stack drops (as TransformCommand).
#include <QUndoCommand>

#include <vector>

#include "model/rigid_transform.hpp"
#include "ui/layers/layer.hpp"
#include "ui/network/network_session.hpp"

namespace plumb::ui {

class Scene;

class StationPosesCommand : public QUndoCommand {
 public:
  struct LayerPoses {
    LayerRef layer;
    std::vector<RigidTransform> before, after;  ///< per scan
    RigidTransform transform_before, transform_after;
  };
  StationPosesCommand(Scene& scene, std::vector<LayerPoses> layers);
  void undo() override;
  void redo() override;

 private:
  void apply(bool after);
  Scene& scene_;
  std::vector<LayerPoses> layers_;
};

/// The poses to apply: one entry per dataset layer with a placed station, its placed scans at
/// their adjusted poses (the others keep theirs). Empty when no station is placed or the
/// reference's layer is gone.
std::vector<StationPosesCommand::LayerPoses> stationPoses(const NetworkSession& session);

}  // namespace plumb::ui
