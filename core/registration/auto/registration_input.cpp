#include "registration/auto/registration_input.hpp"

#include <algorithm>

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

namespace {

/// A static station: its sensor sits at the pose translation. A scan with per-point times and
/// no trajectory is taken for a mobile one (an MMS pass read from a file): its pose says
/// nothing about where each point was seen from.
bool isStaticStation(const Scan& s) {
  return s.has_pose && !s.cloud.hasSensorOrigins() && !s.cloud.hasTimestamps();
}

}  // namespace

RegistrationInput makeRegistrationInput(const Dataset& d, const RigidTransform& to_world) {
  if (d.pointCount() == 0) throw FileError(d.source, "holds no points to register");
  RegistrationInput in;
  // Per-point sensor origins (openings need them: 2023 §III-A ray tracing) when every scan
  // has them or is a static station; none otherwise (an origin is per point or not at all).
  const bool origins = std::all_of(d.scans.begin(), d.scans.end(), [](const Scan& s) {
    return s.cloud.empty() || s.cloud.hasSensorOrigins() || isStaticStation(s);
  });
  in.cloud = d.merged(origins);
  in.cloud.removeNonFinite();
  if (!to_world.isIdentity()) in.cloud.transform(to_world);
  if (d.scans.size() == 1 && isStaticStation(d.scans[0]))
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
