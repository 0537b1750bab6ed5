#include "registration/auto/registration_input.hpp"

#include <algorithm>
#include <sstream>

#include "common/error.hpp"

namespace plumb {

RegistrationSide RegistrationInput::side() const {
  RegistrationSide s;
  if (model) s.model = &*model;
  else s.cloud = &cloud;
  if (whole_model) s.whole_model = &*whole_model;
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

/// A PCD file's VIEWPOINT (the acquisition viewpoint, in the cloud's own frame: PCL does not
/// apply it to the points) is a sensor origin when it lies within the cloud's bounds grown by
/// 1 m: a scanner sits among what it scanned. A merged map keeps PCL's default 0 0 0 far
/// from its points and gets none (its free space is unknown, not empty).
std::optional<Eigen::Vector3d> pcdViewpoint(const Dataset& d) {
  if (d.format != "pcd" || d.scans.size() != 1) return std::nullopt;
  for (const auto& [key, value] : d.metadata) {
    if (key != "viewpoint") continue;
    std::istringstream in(value);
    Eigen::Vector3d v;
    if (!(in >> v.x() >> v.y() >> v.z())) return std::nullopt;
    Bounds b = d.bounds();
    b.min.array() -= 1.0;
    b.max.array() += 1.0;
    if (b.empty() || (v.array() < b.min.array()).any() || (v.array() > b.max.array()).any())
      return std::nullopt;
    return v;
  }
  return std::nullopt;
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
  else if (const auto v = pcdViewpoint(d))
    in.viewpoint = to_world.apply(*v);
  return in;
}

RegistrationInput makeRegistrationInput(const BimModel& m, const RigidTransform& to_world) {
  if (m.mesh.triangles.empty()) throw FileError(m.source, "model has no triangles to register");
  RegistrationInput in;
  in.model = m;
  if (!to_world.isIdentity()) in.model->transform(to_world);
  return in;
}

RegistrationInput makeRegistrationInput(const BimModel& m, const RigidTransform& to_world,
                                        const ModelElementFilter& filter) {
  if (filter.empty()) return makeRegistrationInput(m, to_world);
  FilteredModel kept = filterModelElements(m, filter);
  RegistrationInput in = makeRegistrationInput(kept.model, to_world);
  in.model_selection = std::move(kept.selection);
  in.whole_model = m;
  if (!to_world.isIdentity()) in.whole_model->transform(to_world);
  return in;
}

DistanceTarget distanceTarget(const RegistrationInput& in) {
  if (in.whole_model) return DistanceTarget{nullptr, &in.whole_model->mesh};  // deviations from every element
  return in.model ? DistanceTarget{nullptr, &in.model->mesh} : DistanceTarget{&in.cloud, nullptr};
}

}  // namespace plumb
