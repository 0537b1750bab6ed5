#include "io/las/las_stream_writer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <limits>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/las/las_bytes.hpp"
#include "io/las/las_crs.hpp"
#include "io/las/las_header.hpp"
#include "io/las/las_point_fields.hpp"
#include "io/las/las_vlr.hpp"

namespace plumb {
namespace {
using namespace las;

constexpr std::size_t kChunk = 1 << 15;

// The serialized variable-length records and their count.
struct Vlrs {
  std::vector<std::uint8_t> bytes;
  std::uint32_t count = 0;
  void add(const std::string& user, std::uint16_t id, const std::string& desc,
           std::span<const std::uint8_t> payload) {
    auto v = serializeVlr(user, id, desc, payload);
    bytes.insert(bytes.end(), v.begin(), v.end());
    ++count;
  }
};

// The coordinate system (notes on what could not be written go to `crs_notes`), then the
// extra-bytes descriptors.
Vlrs buildVlrs(const LasStreamFormat& f, bool v14, std::vector<std::string>& crs_notes) {
  Vlrs vlrs;
  if (const auto crs = crsRecord(f.coordinate_system, v14, crs_notes))
    vlrs.add("LASF_Projection", crs->record_id, crs->description, crs->payload);
  if (!f.extra_fields.empty()) {
    if (f.extra_fields.size() * 192 > 65535) throw InputError("too many scalar fields for LAS extra bytes");
    std::vector<std::uint8_t> desc;
    for (const auto& name : f.extra_fields) {
      const auto d = floatExtraDescriptor(name);
      desc.insert(desc.end(), d.begin(), d.end());
    }
    vlrs.add("LASF_Spec", 4, "Extra Bytes", desc);
  }
  return vlrs;
}

int pointFormat(const LasStreamFormat& f, bool v14) {
  if (v14) return f.rgb ? (f.nir ? 8 : 7) : 6;
  return f.gps_time ? (f.rgb ? 3 : 1) : (f.rgb ? 2 : 0);
}

// The header as first written: counts and bounds are filled by finishHeader.
LasHeader initialHeader(const LasStreamFormat& f, const LasWriteOptions& options, int format,
                        std::size_t record_length, const Vlrs& vlrs) {
  const bool v14 = options.version_minor == 4;
  LasHeader h;
  h.version_minor = static_cast<std::uint8_t>(options.version_minor);
  h.header_size = static_cast<std::uint16_t>(v14 ? kHeaderSize14 : kHeaderSize12);
  h.offset_to_points = static_cast<std::uint32_t>(h.header_size + vlrs.bytes.size());
  h.vlr_count = vlrs.count;
  h.format_byte = static_cast<std::uint8_t>(format);
  h.record_length = static_cast<std::uint16_t>(record_length);
  h.system_identifier = "Plumb";
  h.generating_software = options.software;
  // Bit 4 (WKT) exists from 1.4 on, where format 7 requires it; 1.2 readers find the WKT
  // VLR by its record id.
  h.global_encoding = static_cast<std::uint16_t>((f.gps_time && f.adjusted_gps_time ? 1 : 0) |
                                                 (v14 ? 0x10 : 0));
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  h.creation_day = static_cast<std::uint16_t>(tm.tm_yday + 1);
  h.creation_year = static_cast<std::uint16_t>(tm.tm_year + 1900);
  for (int a = 0; a < 3; ++a) {
    h.scale[a] = options.scale;
    h.offset[a] = f.offset[a];
  }
  return h;
}

// Range of the scaled integer coordinates written.
struct IntegerBounds {
  std::array<std::int32_t, 3> lo, hi;
  IntegerBounds() {
    lo.fill(std::numeric_limits<std::int32_t>::max());
    hi.fill(std::numeric_limits<std::int32_t>::min());
  }
};

// Which points have a finite position (kept), and how many.
std::uint64_t markKept(const PointCloud& cloud, std::vector<std::uint8_t>& keep) {
  keep.resize(cloud.size());
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) count += keep[i] = cloud.positions[i].allFinite();
  return count;
}

// round(v) half away from zero, as std::llround, for |v| < 2^31 (adding 0.5 is exact there).
inline std::int32_t roundRecord(double v) {
  return static_cast<std::int32_t>(v >= 0 ? v + 0.5 : v - 0.5);
}

[[noreturn]] void extentError(const std::filesystem::path& path, int axis, double scale) {
  const double limit = 2147483647.0 * scale;
  throw FileError(path, std::string("the points span too far from the offset along ") + "XYZ"[axis] +
                            " for LAS integers at scale " + std::to_string(scale) + " m (limit +-" +
                            std::to_string(limit) + " m); use a coarser scale");
}

// Writes the kept points' records in chunks: coordinates here, the other fields by `fields`.
// Throws FileError for a point beyond int32 records of the offset (nothing is committed).
void writeRecords(std::ostream& out, const std::filesystem::path& path, const PointCloud& cloud,
                  const std::vector<std::uint8_t>& keep, RecordFields& fields, std::size_t record_length,
                  const Eigen::Vector3d& offset, double scale, IntegerBounds& ib,
                  std::vector<std::uint8_t>& buf, Progress* progress) {
  const Eigen::Vector3d shift = cloud.offset - offset;
  const double inv = 1.0 / scale;
  for (std::size_t begin = 0; begin < cloud.size(); begin += kChunk) {
    checkCanceled(progress);
    const std::size_t end = std::min(cloud.size(), begin + kChunk);
    buf.assign((end - begin) * record_length, 0);
    std::uint8_t* r = buf.data();
    for (std::size_t i = begin; i < end; ++i) {
      if (!keep[i]) continue;
      const Eigen::Vector3d p = cloud.local(i);  // exact (residual included)
      std::int32_t xyz[3];
      for (int a = 0; a < 3; ++a) {
        const double v = (p[a] + shift[a]) * inv;
        if (!(std::abs(v) < 2147483647.0)) extentError(path, a, scale);
        xyz[a] = roundRecord(v);
        ib.lo[a] = std::min(ib.lo[a], xyz[a]);
        ib.hi[a] = std::max(ib.hi[a], xyz[a]);
        store<std::int32_t>(r + 4 * a, xyz[a]);
      }
      r += record_length;
    }
    fields.write(buf.data(), record_length, begin, end, keep.data());
    out.write(reinterpret_cast<const char*>(buf.data()), r - buf.data());
    reportProgress(progress, static_cast<double>(end) / static_cast<double>(cloud.size()),
                   "writing LAS points");
  }
}

// Point counts (legacy fields only where the format allows them) and bounds.
void finishHeader(LasHeader& h, std::uint64_t count, const std::array<std::uint64_t, 15>& by_return,
                  const IntegerBounds& ib, double scale, const Eigen::Vector3d& offset) {
  h.count64 = count;
  h.by_return = by_return;
  const bool legacy_ok = h.version_minor != 4 || (h.format_byte < 6 && count <= 0xFFFFFFFFu);
  if (legacy_ok) {
    h.legacy_count = static_cast<std::uint32_t>(count);
    for (int k = 0; k < 5; ++k) h.legacy_by_return[k] = static_cast<std::uint32_t>(by_return[k]);
  }
  if (count > 0) {
    for (int a = 0; a < 3; ++a) {
      h.min[a] = ib.lo[a] * scale + offset[a];
      h.max[a] = ib.hi[a] * scale + offset[a];
    }
  }
}

}  // namespace

struct LasStreamWriter::State {
  std::filesystem::path path;
  LasStreamFormat format;
  LasWriteOptions options;
  PointLayout layout;
  std::size_t record_length = 0;
  IntensityMap intensity;
  LasHeader header;
  AtomicFileWriter writer;
  WriteReport report;
  IntegerBounds ib;
  std::array<std::uint64_t, 15> by_return{};
  std::uint64_t zero_returns = 0, invalid_colors = 0;
  std::vector<std::uint8_t> keep, records;  // reused from chunk to chunk
  State(const std::filesystem::path& p) : path(p), writer(p) {}
};


LasStreamFormat lasFormatOf(const PointCloud& sample, const LasWriteOptions& options) {
  LasStreamFormat f;
  f.rgb = sample.hasColors();
  f.gps_time = sample.hasTimestamps();
  const ScalarField* nir = sample.findScalarField("nir");
  f.nir = f.rgb && options.version_minor == 4 && nir && nir->values.size() == sample.size();
  if (options.extra_fields)
    for (const auto& s : sample.scalar_fields)
      if (!isLasFieldName(s.name) && !(s.name == "nir" && f.nir) && s.values.size() == sample.size())
        f.extra_fields.push_back(s.name);
  return f;
}

LasStreamWriter::LasStreamWriter(const std::filesystem::path& path, const LasStreamFormat& format,
                                 const LasWriteOptions& options) {
  checkLasWriteOptions(options);
  const bool v14 = options.version_minor == 4;
  const int point_format = pointFormat(format, v14);
  const PointLayout layout = pointLayout(point_format);
  const std::size_t record_length = layout.min_size + 4 * format.extra_fields.size();
  if (record_length > 65535) throw InputError("too many scalar fields for one LAS record");
  std::vector<std::string> crs_notes;
  const Vlrs vlrs = buildVlrs(format, v14, crs_notes);
  s_ = std::make_unique<State>(path);
  s_->format = format;
  s_->options = options;
  s_->layout = layout;
  s_->record_length = record_length;
  s_->report.notes = std::move(crs_notes);
  if (format.intensity_scale)
    s_->intensity = scaledIntensity(format.intensity_scale->lo, format.intensity_scale->hi,
                                    format.intensity_scale->source, s_->report.notes);
  s_->header = initialHeader(format, options, point_format, record_length, vlrs);
  std::ostream& out = s_->writer.stream();
  out.write(reinterpret_cast<const char*>(serializeHeader(s_->header).data()), s_->header.header_size);
  out.write(reinterpret_cast<const char*>(vlrs.bytes.data()), static_cast<std::streamsize>(vlrs.bytes.size()));
}

LasStreamWriter::~LasStreamWriter() = default;

void LasStreamWriter::write(const PointCloud& points, Progress* progress) {
  State& s = *s_;
  const std::uint64_t kept = markKept(points, s.keep);
  if (s.options.version_minor != 4 && s.report.points.value_or(0) + kept > std::numeric_limits<std::uint32_t>::max())
    throw InputError("LAS 1.2 holds at most 4294967295 points; write LAS 1.4");
  // Extra fields a chunk lacks are written as 0.
  std::vector<ScalarField> zeros;
  std::vector<const ScalarField*> extras;
  zeros.reserve(s.format.extra_fields.size());
  for (const auto& name : s.format.extra_fields) {
    const ScalarField* f = points.findScalarField(name);
    if (!f || f->values.size() != points.size()) {
      zeros.push_back({name, {}});
      zeros.back().values.assign(points.size(), 0.0f);
      f = &zeros.back();
    }
    extras.push_back(f);
  }
  RecordFields fields(points, s.layout, s.intensity, extras);
  writeRecords(s.writer.stream(), s.path, points, s.keep, fields, s.record_length, s.format.offset,
               s.options.scale, s.ib, s.records, progress);
  for (std::size_t k = 0; k < s.by_return.size(); ++k) s.by_return[k] += fields.byReturn()[k];
  s.zero_returns += fields.zeroReturns();
  if (s.layout.rgb_at >= 0 && points.color_invalid.size() == points.size())
    s.invalid_colors += static_cast<std::uint64_t>(std::count(points.color_invalid.begin(), points.color_invalid.end(), 1));
  s.report.points = s.report.points.value_or(0) + kept;
  s.report.dropped += points.size() - kept;
}

WriteReport LasStreamWriter::finish() {
  State& s = *s_;
  const std::uint64_t count = s.report.points.value_or(0);
  finishHeader(s.header, count, s.by_return, s.ib, s.options.scale, s.format.offset);
  std::ostream& out = s.writer.stream();
  out.seekp(0);
  out.write(reinterpret_cast<const char*>(serializeHeader(s.header).data()), s.header.header_size);
  s.writer.commit();
  s.report.points = count;
  // Notes for the user on what LAS could not hold.
  if (s.report.dropped > 0)
    s.report.notes.push_back(std::to_string(s.report.dropped) +
                             " points with a non-finite (NaN) position were not written");
  if (s.invalid_colors > 0)
    s.report.notes.push_back(std::to_string(s.invalid_colors) +
                             " points have no valid colour (LAS cannot mark it); written as 0");
  if (s.zero_returns > 0)
    s.report.notes.push_back(std::to_string(s.zero_returns) +
                             " points had return number 0 (unknown); written as return 1");
  return std::move(s.report);
}

}  // namespace plumb
