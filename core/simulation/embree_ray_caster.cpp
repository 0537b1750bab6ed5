// Embree 3 backend of the ray caster (the only file that includes Embree headers). Vertices
// are stored in float relative to the mesh centre; hit distances are refined in double
// precision on the hit triangle's plane.
#include "simulation/ray_caster_backends.hpp"

#include "common/error.hpp"

#ifdef PLUMB_HAVE_EMBREE
#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>

namespace plumb::sim {

namespace {

class EmbreeCaster final : public RayCaster::Impl {
 public:
  EmbreeCaster(const TriangleMesh& m, const std::vector<bool>& skip) : Impl(m) {
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
    if (index_.empty()) return {};
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    setRay(rh, ray, max_range, min_range);
    rtcIntersect1(scene_, &context, &rh);
    return result(ray, rh.hit.geomID != RTC_INVALID_GEOMETRY_ID, rh.hit.primID, rh.ray.tfar, max_range, min_range);
  }

  // Packets of 16 rays (rtcIntersect16). Coherent batches (a scanner row or profile: nearby
  // origins, neighbouring directions) use Embree's coherent packet traversal, ~2x faster than
  // single rays there; arbitrary rays use the incoherent flag (Embree then traces the packet's
  // rays as single rays without per-call overhead). rtcIntersect1M streams were measured no
  // faster than these packets (see tests/bench/simulation).
  void castBatch(const Ray* rays, std::size_t n, RayHit* hits, double max_range, double min_range,
                 bool coherent) const override {
    if (index_.empty()) return Impl::castBatch(rays, n, hits, max_range, min_range, coherent);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    alignas(64) RTCRayHit16 p;
    alignas(64) int valid[16];
    for (std::size_t b = 0; b < n; b += 16) {
      const std::size_t m = std::min<std::size_t>(16, n - b);
      for (std::size_t i = 0; i < 16; ++i) {
        valid[i] = i < m ? -1 : 0;
        const Ray& r = rays[b + std::min(i, m - 1)];
        p.ray.org_x[i] = static_cast<float>(r.origin.x() - centre_.x());
        p.ray.org_y[i] = static_cast<float>(r.origin.y() - centre_.y());
        p.ray.org_z[i] = static_cast<float>(r.origin.z() - centre_.z());
        p.ray.dir_x[i] = static_cast<float>(r.direction.x());
        p.ray.dir_y[i] = static_cast<float>(r.direction.y());
        p.ray.dir_z[i] = static_cast<float>(r.direction.z());
        p.ray.tnear[i] = static_cast<float>(min_range);
        p.ray.tfar[i] = farLimit(max_range);
        p.ray.time[i] = 0.0f;
        p.ray.mask[i] = 0xFFFFFFFFu;
        p.ray.id[i] = static_cast<unsigned>(i);
        p.ray.flags[i] = 0;
        p.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
        p.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      }
      rtcIntersect16(valid, scene_, &context, &p);
      for (std::size_t i = 0; i < m; ++i)
        hits[b + i] = result(rays[b + i], p.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID, p.hit.primID[i], p.ray.tfar[i], max_range, min_range);
    }
  }

 private:
  static float farLimit(double max_range) {
    return max_range > 1e30 ? std::numeric_limits<float>::infinity() : static_cast<float>(max_range * (1 + 1e-6));
  }
  void setRay(RTCRayHit& rh, const Ray& ray, double max_range, double min_range) const {
    rh.ray.org_x = static_cast<float>(ray.origin.x() - centre_.x());
    rh.ray.org_y = static_cast<float>(ray.origin.y() - centre_.y());
    rh.ray.org_z = static_cast<float>(ray.origin.z() - centre_.z());
    rh.ray.dir_x = static_cast<float>(ray.direction.x());
    rh.ray.dir_y = static_cast<float>(ray.direction.y());
    rh.ray.dir_z = static_cast<float>(ray.direction.z());
    rh.ray.tnear = static_cast<float>(min_range);
    rh.ray.tfar = farLimit(max_range);
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  RayHit result(const Ray& ray, bool found, unsigned prim, float tfar, double max_range, double min_range) const {
    RayHit hit;
    if (!found) return hit;
    const std::uint32_t t = index_[prim];
    const double d = refineDistance(t, ray, tfar);
    if (d <= min_range || d > max_range) return hit;
    hit.distance = d;
    hit.triangle = t;
    return hit;
  }

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
