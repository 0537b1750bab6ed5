#include "io/las/las_decode.hpp"

#include <algorithm>
#include <limits>

#include "io/las/las_bytes.hpp"

namespace plumb::las {

namespace {
// double -> float without the undefined behaviour of out-of-range conversions (fuzzed scales).
inline float toFloat(double v) {
  constexpr double kMax = std::numeric_limits<float>::max();
  return static_cast<float>(v < -kMax ? -kMax : (v > kMax ? kMax : v));
}

double extraValue(const std::uint8_t* p, int type) {
  switch (type) {
    case 1: return p[0];
    case 2: return static_cast<std::int8_t>(p[0]);
    case 3: return load<std::uint16_t>(p);
    case 4: return load<std::int16_t>(p);
    case 5: return load<std::uint32_t>(p);
    case 6: return load<std::int32_t>(p);
    case 7: return static_cast<double>(load<std::uint64_t>(p));
    case 8: return static_cast<double>(load<std::int64_t>(p));
    case 9: return load<float>(p);
    case 10: return load<double>(p);
    default: return 0.0;
  }
}
}  // namespace

PointDecoder::PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud)
    : layout_(pointLayout(h.format())),
      stride_(h.record_length),
      scale_(h.scale),
      extras_(std::move(extras)),
      cloud_(cloud) {
  for (int a = 0; a < 3; ++a) {
    shift_[a] = h.offset[a] - cloud.offset[a];
    world_offset_[a] = h.offset[a];
  }
  raw_min_.fill(std::numeric_limits<std::int32_t>::max());
  raw_max_.fill(std::numeric_limits<std::int32_t>::min());
  const std::size_t n = h.point_count;
  cloud.positions.resize(n);
  cloud.intensity.resize(n);
  cloud.return_index.resize(n);
  cloud.return_count.resize(n);
  cloud.classification.resize(n);
  if (layout_.gps_at >= 0) cloud.timestamps.resize(n);
  if (layout_.rgb_at >= 0) cloud.colors.resize(n);
  cloud.scan_angle.resize(n);
  cloud.user_data.resize(n);
  cloud.point_source_id.resize(n);
  cloud.classification_flags.resize(n);
  if (layout_.extended) cloud.scanner_channel.resize(n);
  cloud.scan_flags.resize(n);
  auto add = [&](const std::string& name) {
    cloud.scalar_fields.push_back({name, Column<float>(n, 0.0f)});
  };
  if (layout_.nir_at >= 0) add("nir");
  for (const auto& e : extras_) add(e.name);
  // Pointers taken after every push_back (the vector no longer grows).
  std::size_t k = 0;
  if (layout_.nir_at >= 0) nir_ = &cloud.scalar_fields[k++];
  for (std::size_t e = 0; e < extras_.size(); ++e) extra_fields_.push_back(&cloud.scalar_fields[k++]);
}

void PointDecoder::decode(const std::uint8_t* records, std::size_t n, std::size_t first) {
  Eigen::Vector3f* pos = cloud_.positions.data() + first;
  float* intensity = cloud_.intensity.data() + first;
  std::uint8_t* ret = cloud_.return_index.data() + first;
  std::uint8_t* cnt = cloud_.return_count.data() + first;
  std::uint8_t* cls = cloud_.classification.data() + first;
  const bool extended = layout_.extended;
  std::array<std::int32_t, 3> lo = raw_min_, hi = raw_max_;
  std::uint64_t bad = 0;
  const std::uint8_t* r = records;
  for (std::size_t i = 0; i < n; ++i, r += stride_) {
    const std::int32_t x = load<std::int32_t>(r), y = load<std::int32_t>(r + 4),
                       z = load<std::int32_t>(r + 8);
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
    lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
    lo[2] = std::min(lo[2], z), hi[2] = std::max(hi[2], z);
    pos[i] = Eigen::Vector3f(toFloat(x * scale_[0] + shift_[0]), toFloat(y * scale_[1] + shift_[1]),
                             toFloat(z * scale_[2] + shift_[2]));
    intensity[i] = load<std::uint16_t>(r + 12);
    const std::uint8_t b = r[14];
    if (extended) {
      ret[i] = b & 0x0F;
      cnt[i] = b >> 4;
      cls[i] = r[16];
    } else {
      ret[i] = b & 0x07;
      cnt[i] = (b >> 3) & 0x07;
      cls[i] = r[15] & 0x1F;
    }
    bad += (ret[i] == 0) | (ret[i] > cnt[i]);
  }
  bad_returns_ += bad;
  raw_min_ = lo;
  raw_max_ = hi;
  if (layout_.gps_at >= 0) {
    double* t = cloud_.timestamps.data() + first;
    const std::uint8_t* g = records + layout_.gps_at;
    for (std::size_t i = 0; i < n; ++i, g += stride_) t[i] = load<double>(g);
  }
  if (layout_.rgb_at >= 0) {
    Rgb8* c = cloud_.colors.data() + first;
    const std::uint8_t* g = records + layout_.rgb_at;
    std::uint16_t cmax = color_max_;
    if (cmax > 255) {
      for (std::size_t i = 0; i < n; ++i, g += stride_)
        c[i] = {static_cast<std::uint8_t>(g[1]), static_cast<std::uint8_t>(g[3]),
                static_cast<std::uint8_t>(g[5])};  // high bytes
    } else {
      // Still possibly an 8-bit writer: keep low bytes and watch for a value > 255.
      for (std::size_t i = 0; i < n; ++i, g += stride_) {
        const auto rr = load<std::uint16_t>(g), gg = load<std::uint16_t>(g + 2),
                   bb = load<std::uint16_t>(g + 4);
        cmax = std::max({cmax, rr, gg, bb});
        c[i] = {static_cast<std::uint8_t>(rr >> (cmax > 255 ? 8 : 0)),
                static_cast<std::uint8_t>(gg >> (cmax > 255 ? 8 : 0)),
                static_cast<std::uint8_t>(bb >> (cmax > 255 ? 8 : 0))};
        if (cmax > 255) {
          // 16-bit after all: earlier points (all <= 255) have a zero high byte.
          std::fill(cloud_.colors.begin(), cloud_.colors.begin() + first + i, Rgb8{0, 0, 0});
          // The remaining points of this chunk are converted by the high-byte loop.
          g += stride_;
          for (std::size_t j = i + 1; j < n; ++j, g += stride_)
            c[j] = {g[1], g[3], g[5]};
          break;
        }
      }
    }
    color_max_ = cmax;
  }
  decodeAuxiliary(records, n, first);
  for (std::size_t e = 0; e < extras_.size(); ++e) {
    const ExtraField& f = extras_[e];
    float* out = extra_fields_[e]->values.data() + first;
    const std::uint8_t* p = records + layout_.min_size + f.offset;
    for (std::size_t i = 0; i < n; ++i, p += stride_)
      out[i] = toFloat(extraValue(p, f.type) * f.scale + f.add);
  }
}

void PointDecoder::decodeAuxiliary(const std::uint8_t* records, std::size_t n, std::size_t first) {
  PointCloud& c = cloud_;
  const std::uint8_t* p = records;
  for (std::size_t i = 0, k = first; i < n; ++i, ++k, p += stride_) {
    c.user_data[k] = p[17];
    c.scan_flags[k] = (layout_.extended ? p[15] : p[14]) >> 6;  // direction, edge of line
    if (layout_.extended) {
      c.scan_angle[k] = static_cast<float>(load<std::int16_t>(p + 18) * 0.006);
      c.point_source_id[k] = load<std::uint16_t>(p + 20);
      c.classification_flags[k] = p[15] & 0x0F;
      c.scanner_channel[k] = (p[15] >> 4) & 0x03;
    } else {
      c.scan_angle[k] = static_cast<std::int8_t>(p[16]);
      c.point_source_id[k] = load<std::uint16_t>(p + 18);
      c.classification_flags[k] = (p[15] >> 5) & 0x07;
    }
    if (nir_) nir_->values[k] = load<std::uint16_t>(p + layout_.nir_at);
  }
}

namespace {
// An all-zero LAS field carries nothing (the writer writes 0 when it is absent): free it.
template <class V>
void dropIfZero(V& v) {
  for (const auto& x : v)
    if (x != 0) return;
  V().swap(v);
}
}  // namespace

bool PointDecoder::finish() {
  dropIfZero(cloud_.scan_angle);
  dropIfZero(cloud_.user_data);
  dropIfZero(cloud_.point_source_id);
  dropIfZero(cloud_.classification_flags);
  dropIfZero(cloud_.scanner_channel);
  dropIfZero(cloud_.scan_flags);
  return color_max_ > 255;
}

Bounds PointDecoder::worldBounds() const {
  Bounds b;
  if (raw_min_[0] > raw_max_[0]) return b;
  for (int a = 0; a < 3; ++a) {
    const double u = raw_min_[a] * scale_[a] + world_offset_[a];
    const double v = raw_max_[a] * scale_[a] + world_offset_[a];
    b.min[a] = std::min(u, v);
    b.max[a] = std::max(u, v);
  }
  return b;
}

}  // namespace plumb::las
