#include "io/las/las_writer.hpp"

#include <algorithm>
#include <array>
#include <chrono>
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

/// A scan's dataset-frame coordinates must be finite and representable to `scale` beside a
/// double header offset (|coordinate| / scale < 2^53); a pose translation of 1e308 is not.
void checkScanRange(const std::filesystem::path& path, const Scan& scan, double scale) {
  const Bounds b = scan.cloud.bounds();
  if (b.empty()) return;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3d c((corner & 1) ? b.max.x() : b.min.x(), (corner & 2) ? b.max.y() : b.min.y(),
                            (corner & 4) ? b.max.z() : b.min.z());
    const Eigen::Vector3d w = scan.pose.apply(c);
    for (int a = 0; a < 3; ++a)
      if (!std::isfinite(w[a]) || std::abs(w[a]) / scale >= 9007199254740992.0)
        throw FileError(path, std::string("scan '") + scan.name + "': its pose puts " + "XYZ"[a] +
                                  " at " + std::to_string(w[a]) + " m, outside what LAS scaled " +
                                  "integers can hold at scale " + std::to_string(scale) +
                                  " m (|coordinate| / scale must stay below 2^53)");
  }
}

// Rejects options no LAS file can be written with.
void checkOptions(const LasWriteOptions& options) {
  if (options.version_minor != 2 && options.version_minor != 4)
    throw InputError("LAS version 1." + std::to_string(options.version_minor) +
                     " cannot be written (1.2 or 1.4)");
  if (!(options.scale > 0.0) || !std::isfinite(options.scale))
    throw InputError("LAS scale must be a positive number of metres");
}

// Scalar fields written as extra bytes: those LAS has no standard field for.
std::vector<const ScalarField*> extraFields(const PointCloud& cloud, const PointLayout& layout,
                                            const LasWriteOptions& options) {
  std::vector<const ScalarField*> extras;
  if (options.extra_fields)
    for (const auto& f : cloud.scalar_fields)
      if (!isLasFieldName(f.name) && !(f.name == "nir" && layout.nir_at >= 0) &&
          f.values.size() == cloud.size())
        extras.push_back(&f);
  return extras;
}

// Points with a finite position, and their world bounds.
struct KeptPoints {
  std::vector<std::uint8_t> keep;
  Bounds bounds;
  std::uint64_t count = 0;
};
KeptPoints keptPoints(const PointCloud& cloud) {
  KeptPoints k;
  k.keep.resize(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    k.keep[i] = cloud.positions[i].allFinite();
    if (k.keep[i]) {
      k.bounds.extend(cloud.world(i));
      ++k.count;
    }
  }
  return k;
}

// The header offset (given, or the rounded bounds centre), checked to keep every point within
// int32 scaled integers of it.
Eigen::Vector3d chooseOffset(const std::filesystem::path& path, const Bounds& bounds,
                             const LasWriteOptions& options) {
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  if (options.offset) {
    offset = *options.offset;
  } else if (!bounds.empty()) {
    offset = bounds.center().array().round();
  }
  const double limit = 2147483647.0 * options.scale;
  if (!bounds.empty()) {
    for (int a = 0; a < 3; ++a)
      if (std::abs(bounds.min[a] - offset[a]) >= limit || std::abs(bounds.max[a] - offset[a]) >= limit)
        throw FileError(path, std::string("the points span too far from the offset along ") +
                                  "XYZ"[a] + " for LAS integers at scale " +
                                  std::to_string(options.scale) + " m (limit +-" +
                                  std::to_string(limit) + " m); use a coarser scale");
  }
  return offset;
}

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
Vlrs buildVlrs(const Dataset& data, bool v14, const std::vector<const ScalarField*>& extras,
               std::vector<std::string>& crs_notes) {
  Vlrs vlrs;
  if (const auto crs = crsRecord(data.coordinate_system, v14, crs_notes))
    vlrs.add("LASF_Projection", crs->record_id, crs->description, crs->payload);
  if (!extras.empty()) {
    if (extras.size() * 192 > 65535) throw InputError("too many scalar fields for LAS extra bytes");
    std::vector<std::uint8_t> desc;
    for (const auto* f : extras) {
      const auto d = floatExtraDescriptor(f->name);
      desc.insert(desc.end(), d.begin(), d.end());
    }
    vlrs.add("LASF_Spec", 4, "Extra Bytes", desc);
  }
  return vlrs;
}

// What a LAS header needs beyond the options, decided before the records are written.
struct HeaderFacts {
  int format = 0;
  std::size_t record_length = 0;
  std::size_t vlr_bytes = 0;
  std::uint32_t vlr_count = 0;
  bool has_time = false;
  Eigen::Vector3d offset;
};

// The header as first written: counts and bounds are filled by finishHeader.
LasHeader initialHeader(const Dataset& data, const LasWriteOptions& options, const HeaderFacts& f) {
  const bool v14 = options.version_minor == 4;
  LasHeader h;
  h.version_minor = static_cast<std::uint8_t>(options.version_minor);
  h.header_size = static_cast<std::uint16_t>(v14 ? kHeaderSize14 : kHeaderSize12);
  h.offset_to_points = static_cast<std::uint32_t>(h.header_size + f.vlr_bytes);
  h.vlr_count = f.vlr_count;
  h.format_byte = static_cast<std::uint8_t>(f.format);
  h.record_length = static_cast<std::uint16_t>(f.record_length);
  h.system_identifier = "Plumb";
  h.generating_software = options.software;
  bool adjusted_time = false;
  for (const auto& [k, v] : data.metadata)
    if (k == "GPS time" && v == "adjusted standard GPS time") adjusted_time = true;
  // Bit 4 (WKT) exists from 1.4 on, where format 7 requires it; 1.2 readers find the WKT
  // VLR by its record id.
  h.global_encoding = static_cast<std::uint16_t>((f.has_time && adjusted_time ? 1 : 0) |
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

// Streams the kept points' records in chunks: coordinates here, the other fields by `fields`.
IntegerBounds writeRecords(std::ostream& out, const PointCloud& cloud, const KeptPoints& kept,
                           RecordFields& fields, std::size_t record_length,
                           const Eigen::Vector3d& offset, double scale, Progress* progress) {
  IntegerBounds ib;
  std::vector<std::uint8_t> buf;
  const Eigen::Vector3d shift = cloud.offset - offset;
  const double inv = 1.0 / scale;
  for (std::size_t begin = 0; begin < cloud.size(); begin += kChunk) {
    checkCanceled(progress);
    const std::size_t end = std::min(cloud.size(), begin + kChunk);
    buf.assign((end - begin) * record_length, 0);
    std::uint8_t* r = buf.data();
    for (std::size_t i = begin; i < end; ++i) {
      if (!kept.keep[i]) continue;
      const Eigen::Vector3d p = cloud.local(i);  // exact (residual included)
      std::int32_t xyz[3];
      for (int a = 0; a < 3; ++a) {
        xyz[a] = static_cast<std::int32_t>(std::llround((p[a] + shift[a]) * inv));
        ib.lo[a] = std::min(ib.lo[a], xyz[a]);
        ib.hi[a] = std::max(ib.hi[a], xyz[a]);
        store<std::int32_t>(r + 4 * a, xyz[a]);
      }
      r += record_length;
    }
    fields.write(buf.data(), record_length, begin, end, kept.keep.data());
    out.write(reinterpret_cast<const char*>(buf.data()), r - buf.data());
    reportProgress(progress, static_cast<double>(end) / static_cast<double>(cloud.size()),
                   "writing LAS points");
  }
  return ib;
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

// Notes for the user on what LAS could not hold.
void addConversionNotes(WriteReport& report, const PointCloud& cloud, const PointLayout& layout,
                        const RecordFields& fields) {
  if (report.dropped > 0)
    report.notes.push_back(std::to_string(report.dropped) +
                           " points with a non-finite (NaN) position were not written");
  if (layout.rgb_at >= 0 && cloud.color_invalid.size() == cloud.size()) {
    const auto unknown = std::count(cloud.color_invalid.begin(), cloud.color_invalid.end(), 1);
    if (unknown > 0)
      report.notes.push_back(std::to_string(unknown) +
                             " points have no valid colour (LAS cannot mark it); written as 0");
  }
  if (fields.zeroReturns() > 0)
    report.notes.push_back(std::to_string(fields.zeroReturns()) +
                           " points had return number 0 (unknown); written as return 1");
}

}  // namespace

void writeLas(const std::filesystem::path& path, const Dataset& data,
              const LasWriteOptions& options, Progress* progress) {
  checkOptions(options);
  // One scan with an identity pose is written in place; otherwise scans are merged (a copy).
  for (const Scan& scan : data.scans) checkScanRange(path, scan, options.scale);
  PointCloud merged;
  const bool in_place = data.scans.size() == 1 && data.scans[0].pose.isIdentity();
  if (!in_place) merged = data.merged();
  const PointCloud& cloud = in_place ? data.scans[0].cloud : merged;
  const bool v14 = options.version_minor == 4;
  HeaderFacts facts;
  facts.has_time = cloud.hasTimestamps();
  facts.format = chooseFormat(cloud, v14);
  const PointLayout layout = pointLayout(facts.format);
  const auto extras = extraFields(cloud, layout, options);
  facts.record_length = layout.min_size + 4 * extras.size();
  if (facts.record_length > 65535) throw InputError("too many scalar fields for one LAS record");
  const KeptPoints kept = keptPoints(cloud);
  facts.offset = chooseOffset(path, kept.bounds, options);
  if (!v14 && kept.count > std::numeric_limits<std::uint32_t>::max())
    throw InputError("LAS 1.2 holds at most 4294967295 points; write LAS 1.4");
  std::vector<std::string> crs_notes;
  const Vlrs vlrs = buildVlrs(data, v14, extras, crs_notes);
  facts.vlr_bytes = vlrs.bytes.size();
  facts.vlr_count = vlrs.count;
  LasHeader h = initialHeader(data, options, facts);

  // Records, streamed in chunks; header rewritten at the end with counts and bounds.
  AtomicFileWriter writer(path);
  std::ostream& out = writer.stream();
  out.write(reinterpret_cast<const char*>(serializeHeader(h).data()), h.header_size);
  out.write(reinterpret_cast<const char*>(vlrs.bytes.data()), static_cast<std::streamsize>(vlrs.bytes.size()));
  WriteReport report;
  report.notes = std::move(crs_notes);
  RecordFields fields(cloud, layout, intensityMap(cloud, knownIntensityLimits(data), report.notes),
                      extras);
  const IntegerBounds ib = writeRecords(out, cloud, kept, fields, facts.record_length, facts.offset,
                                        options.scale, progress);
  finishHeader(h, kept.count, fields.byReturn(), ib, options.scale, facts.offset);
  out.seekp(0);
  out.write(reinterpret_cast<const char*>(serializeHeader(h).data()), h.header_size);
  writer.commit();
  report.points = kept.count;
  report.dropped = cloud.size() - kept.count;
  addConversionNotes(report, cloud, layout, fields);
  if (options.report) *options.report = std::move(report);
}

}  // namespace plumb
