#include "registration/auto/registration_input.hpp"

#include "common/error.hpp"

namespace plumb {

RegistrationSide RegistrationInput::side() const {
  RegistrationSide s;
  if (model) s.model = &*model;
  else s.cloud = &cloud;
  s.viewpoint = viewpoint;
  if (features) s.features = &*features;
  return s;
}

RegistrationInput makeRegistrationInput(const Dataset& d, const RigidTransform& to_world) {
  if (d.pointCount() == 0) throw FileError(d.source, "holds no points to register");
  RegistrationInput in;
  in.cloud = d.merged(false);
  in.cloud.removeNonFinite();
  if (!to_world.isIdentity()) in.cloud.transform(to_world);
  if (d.scans.size() == 1 && d.scans[0].has_pose && !d.scans[0].cloud.hasSensorOrigins())
    in.viewpoint = to_world.apply(d.scans[0].pose.translation());
  return in;
}

RegistrationInput makeRegistrationInput(const BimModel& m, const RigidTransform& to_world) {
  if (m.mesh.triangles.empty()) throw FileError(m.source, "model has no triangles to register");
  RegistrationInput in;
  in.model = m;
  if (!to_world.isIdentity()) in.model->transform(to_world);
  return in;
}

}  // namespace plumb
