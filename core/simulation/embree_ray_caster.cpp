// Embree 3 backend of the ray caster (the only file that includes Embree headers). Vertices
// are stored in float relative to the mesh centre; hit distances are refined in double
// precision on the hit triangle's plane.
#include "simulation/ray_caster_backends.hpp"

#include "common/error.hpp"

#ifdef PLUMB_HAVE_EMBREE
#include <embree3/rtcore.h>

#include <limits>

namespace plumb::sim {

namespace {

class EmbreeCaster final : public RayCaster::Impl {
 public:
  EmbreeCaster(const TriangleMesh& m, const std::vector<bool>& skip) {
    mesh = m;
    centre_ = m.bounds().center();
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw InputError("ray caster: Embree device creation failed");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
      if (skip.empty() || !skip[t]) index_.push_back(static_cast<std::uint32_t>(t));
    if (!index_.empty()) {
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), m.vertices.size()));
      for (std::size_t i = 0; i < m.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + static_cast<std::size_t>(k)] = static_cast<float>(m.vertices[i][k] - centre_[k]);
      auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), index_.size()));
      for (std::size_t i = 0; i < index_.size(); ++i)
        for (int k = 0; k < 3; ++k) f[3 * i + static_cast<std::size_t>(k)] = m.triangles[index_[i]][static_cast<std::size_t>(k)];
      rtcCommitGeometry(geom);
      rtcAttachGeometry(scene_, geom);
      rtcReleaseGeometry(geom);
    }
    rtcCommitScene(scene_);
  }
  ~EmbreeCaster() override {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }

  RayHit cast(const Ray& ray, double max_range, double min_range) const override {
    RayHit hit;
    if (index_.empty()) return hit;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(ray.origin.x() - centre_.x());
    rh.ray.org_y = static_cast<float>(ray.origin.y() - centre_.y());
    rh.ray.org_z = static_cast<float>(ray.origin.z() - centre_.z());
    rh.ray.dir_x = static_cast<float>(ray.direction.x());
    rh.ray.dir_y = static_cast<float>(ray.direction.y());
    rh.ray.dir_z = static_cast<float>(ray.direction.z());
    rh.ray.tnear = static_cast<float>(min_range);
    rh.ray.tfar = max_range > 1e30 ? std::numeric_limits<float>::infinity() : static_cast<float>(max_range * (1 + 1e-6));
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    const std::uint32_t t = index_[rh.hit.primID];
    double d = distanceToTrianglePlane(mesh, t, ray);
    if (!(std::abs(d - rh.ray.tfar) < 1e-3 * (1.0 + rh.ray.tfar))) d = rh.ray.tfar;  // grazing ray
    if (d <= min_range || d > max_range) return hit;
    hit.distance = d;
    hit.triangle = t;
    return hit;
  }

 private:
  Eigen::Vector3d centre_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<std::uint32_t> index_;
};

}  // namespace

std::unique_ptr<RayCaster::Impl> makeEmbreeCaster(const TriangleMesh& mesh, const std::vector<bool>& skip) {
  return std::make_unique<EmbreeCaster>(mesh, skip);
}

}  // namespace plumb::sim

#else

namespace plumb::sim {
std::unique_ptr<RayCaster::Impl> makeEmbreeCaster(const TriangleMesh&, const std::vector<bool>&) {
  throw InputError("ray caster: Embree backend not compiled in");
}
}  // namespace plumb::sim

#endif
