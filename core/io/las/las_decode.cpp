#include "io/las/las_decode.hpp"
#include "common/float_cast.hpp"

#include <algorithm>
#include <limits>

#include "io/las/las_bytes.hpp"

namespace plumb::las {

namespace {
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
    : PointDecoder(h, std::move(extras), cloud, h.point_count, false, false) {}

PointDecoder::PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud,
                           std::size_t capacity, bool rgb16)
    : PointDecoder(h, std::move(extras), cloud, capacity, rgb16, true) {}

PointDecoder::PointDecoder(const LasHeader& h, std::vector<ExtraField> extras, PointCloud& cloud,
                           std::size_t n, bool rgb16, bool dense)
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
  if (rgb16) color_max_ = 0xFFFF;
  // Every record writes every one of these columns (decode), so they are not zeroed first.
  resizeForOverwrite(cloud.positions, n);
  resizeForOverwrite(cloud.position_residuals, n);  // scaled integers: exact locals
  resizeForOverwrite(cloud.intensity, n);
  resizeForOverwrite(cloud.return_index, n);
  resizeForOverwrite(cloud.return_count, n);
  resizeForOverwrite(cloud.classification, n);
  if (layout_.gps_at >= 0) resizeForOverwrite(cloud.timestamps, n);
  if (layout_.rgb_at >= 0) resizeForOverwrite(cloud.colors, n);
  total_ = n;  // the LAS field columns are allocated by decodeAuxiliary when needed, or now
  if (dense) {
    cloud.user_data.assign(n, 0), cloud.scan_flags.assign(n, 0), cloud.point_source_id.assign(n, 0);
    cloud.scan_angle.assign(n, 0.0f), cloud.classification_flags.assign(n, 0);
    if (layout_.extended) cloud.scanner_channel.assign(n, 0);
  }
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
  Eigen::Vector3f* res = cloud_.position_residuals.data() + first;
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
    const std::int32_t raw[3] = {x, y, z};
    for (int a = 0; a < 3; ++a)
      PointCloud::splitComponent(inFloatRange(raw[a] * scale_[a] + shift_[a]), pos[i][a], res[i][a]);
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

namespace {
// One LAS field of a chunk into `column` (points [first, first+n)), allocated (zeros) only at
// the first chunk where the field is not 0: a field that is 0 everywhere costs no memory.
template <class V, class Get>
void fillColumn(V& column, bool nonzero, std::size_t total, const std::uint8_t* records,
                std::size_t stride, std::size_t n, std::size_t first, Get get) {
  if (column.empty() && !nonzero) return;
  if (column.empty()) column.resize(total, 0);
  const std::uint8_t* p = records;
  for (std::size_t i = 0; i < n; ++i, p += stride) column[first + i] = get(p);
}
}  // namespace

void PointDecoder::decodeAuxiliary(const std::uint8_t* records, std::size_t n, std::size_t first) {
  const bool ext = layout_.extended;
  const int angle_at = ext ? 18 : 16, source_at = ext ? 20 : 18, bits_at = ext ? 15 : 14;
  // Which fields are not 0 in this chunk: one pass over bytes already in cache.
  unsigned user = 0, angle = 0, source = 0, flags = 0, channel = 0, scan = 0;
  const std::uint8_t* p = records;
  for (std::size_t i = 0; i < n; ++i, p += stride_) {
    user |= p[17];
    angle |= p[angle_at] | (ext ? p[angle_at + 1] : 0);
    source |= load<std::uint16_t>(p + source_at);
    flags |= ext ? p[15] & 0x0F : p[15] >> 5;
    channel |= ext ? p[15] & 0x30 : 0;
    scan |= p[bits_at] >> 6;
  }
  PointCloud& c = cloud_;
  const std::size_t total = total_;
  auto fill = [&](auto& column, unsigned any, auto get) {
    fillColumn(column, any != 0, total, records, stride_, n, first, get);
  };
  fill(c.user_data, user, [](const std::uint8_t* r) { return r[17]; });
  fill(c.scan_flags, scan, [bits_at](const std::uint8_t* r) { return static_cast<std::uint8_t>(r[bits_at] >> 6); });
  fill(c.point_source_id, source, [source_at](const std::uint8_t* r) { return load<std::uint16_t>(r + source_at); });
  if (ext) {
    fill(c.scan_angle, angle, [](const std::uint8_t* r) { return static_cast<float>(load<std::int16_t>(r + 18) * 0.006); });
    fill(c.classification_flags, flags, [](const std::uint8_t* r) { return static_cast<std::uint8_t>(r[15] & 0x0F); });
    fill(c.scanner_channel, channel, [](const std::uint8_t* r) { return static_cast<std::uint8_t>((r[15] >> 4) & 3); });
  } else {
    fill(c.scan_angle, angle, [](const std::uint8_t* r) { return static_cast<float>(static_cast<std::int8_t>(r[16])); });
    fill(c.classification_flags, flags, [](const std::uint8_t* r) { return static_cast<std::uint8_t>(r[15] >> 5); });
  }
  if (nir_) {
    const std::uint8_t* q = records + layout_.nir_at;
    for (std::size_t i = 0; i < n; ++i, q += stride_) nir_->values[first + i] = load<std::uint16_t>(q);
  }
}

bool PointDecoder::finish() { return color_max_ > 255; }

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
