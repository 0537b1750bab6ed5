#include "io/las/las_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <sstream>

#include "common/error.hpp"
#include "io/las/las_decode.hpp"
#include "io/las/las_header.hpp"
#include "io/las/las_source.hpp"
#include "io/las/las_vlr.hpp"

namespace plumb {
namespace {
using namespace las;

constexpr std::size_t kChunkRecords = 1 << 15;

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string triple(const std::array<double, 3>& v) {
  return num(v[0]) + " " + num(v[1]) + " " + num(v[2]);
}

std::string vlrSummary(const LasVlr& v) {
  std::ostringstream s;
  s << v.user_id << " " << v.record_id << ", " << v.length << " bytes at byte " << v.at;
  if (!v.description.empty()) s << ": " << v.description;
  return s.str();
}

// Centre of the header bounds rounded to 1 m, unless the header bounds are unusable or do not
// hold the first point; then the first point rounded to 1 m.
Eigen::Vector3d chooseOffset(const LasHeader& h, const ByteSource& src) {
  if (h.point_count == 0) return Eigen::Vector3d::Zero();
  std::uint8_t rec[12];
  src.read(h.offset_to_points, rec, sizeof rec);
  Eigen::Vector3d first;
  for (int a = 0; a < 3; ++a) {
    std::int32_t raw;
    std::memcpy(&raw, rec + 4 * a, 4);
    first[a] = raw * h.scale[a] + h.offset[a];
  }
  bool header_ok = true;
  Eigen::Vector3d centre;
  for (int a = 0; a < 3; ++a) {
    const double lo = h.min[a], hi = h.max[a];
    header_ok = header_ok && std::isfinite(lo) && std::isfinite(hi) && lo <= hi &&
                first[a] >= lo - 1.0 && first[a] <= hi + 1.0;
    centre[a] = (lo + hi) / 2;
  }
  const Eigen::Vector3d o = header_ok ? centre : first;
  Eigen::Vector3d rounded;
  for (int a = 0; a < 3; ++a) rounded[a] = std::isfinite(o[a]) ? std::round(o[a]) : 0.0;
  return rounded;
}

/// The header, the VLRs and the EVLRs, with the warnings of reading them.
struct LasPrologue {
  LasHeader header;
  std::vector<LasVlr> vlrs;
  std::vector<std::string> warnings;
};

/// Reads the header and the (E)VLRs; refuses LASzip data (its VLR, whatever the extension).
LasPrologue readPrologue(const ByteSource& src, const std::filesystem::path& file) {
  const std::uint64_t size = src.size();
  // Header and VLRs: [0, offset_to_points), read once (or used in place for memory input).
  std::vector<std::uint8_t> owned;
  std::span<const std::uint8_t> prefix;
  auto view = [&](std::uint64_t n) {
    if (src.data()) {
      prefix = {src.data(), static_cast<std::size_t>(n)};
    } else {
      owned.resize(n);
      src.read(0, owned.data(), n);
      prefix = owned;
    }
  };
  view(std::min<std::uint64_t>(size, 1 << 16));
  LasPrologue p{parseHeader(prefix, size, file), {}, {}};
  const LasHeader& h = p.header;
  if (h.offset_to_points > prefix.size()) view(h.offset_to_points);
  p.warnings = h.warnings;
  p.vlrs = parseVlrs(prefix.first(h.offset_to_points), h, file);
  parseEvlrs(src, h, file, p.vlrs, p.warnings);
  for (const auto& v : p.vlrs)
    if (v.user_id == "laszip encoded" && v.record_id == 22204)
      throw FileError(file, lazMessage("it carries the LASzip VLR"), atByte(v.at, "VLR"));
  return p;
}

/// The fields of the `extra_bytes` bytes after each record's format fields, from the first
/// Extra Bytes VLR (LASF_Spec 4); none without it (a warning) or when options say so.
std::vector<ExtraField> extraFields(const std::vector<LasVlr>& vlrs, std::size_t extra_bytes,
                                    const LasReadOptions& options, const std::filesystem::path& file,
                                    std::vector<std::string>& warnings) {
  std::vector<ExtraField> extras;
  const LasVlr* extra_vlr = nullptr;
  for (const auto& v : vlrs)
    if (v.user_id == "LASF_Spec" && v.record_id == 4 && !extra_vlr) extra_vlr = &v;
  if (extra_bytes > 0 && !extra_vlr)
    warnings.push_back(std::to_string(extra_bytes) +
                       " extra bytes per point without an Extra Bytes VLR; ignored");
  if (extra_vlr) extras = parseExtraBytes(*extra_vlr, extra_bytes, file, warnings);
  if (!options.extra_bytes) extras.clear();
  return extras;
}

/// Decodes the h.point_count records in chunks of kChunkRecords (in place for memory input).
void decodePoints(const ByteSource& src, const LasHeader& h, PointDecoder& decoder, Progress* progress) {
  const std::uint64_t n = h.point_count;
  std::vector<std::uint8_t> chunk;
  for (std::uint64_t first = 0; first < n; first += kChunkRecords) {
    checkCanceled(progress);
    const std::size_t count = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkRecords, n - first));
    const std::uint64_t at = h.offset_to_points + first * h.record_length;
    const std::uint8_t* records;
    if (src.data()) {
      records = src.data() + at;
    } else {
      chunk.resize(count * h.record_length);
      src.read(at, chunk.data(), chunk.size());
      records = chunk.data();
    }
    decoder.decode(records, count, static_cast<std::size_t>(first));
    reportProgress(progress, static_cast<double>(first + count) / static_cast<double>(n),
                   "reading LAS points");
  }
}

/// Header bounds are informative; a disagreement with the decoded points beyond scale
/// rounding is reported as a warning.
void checkHeaderBounds(const LasHeader& h, const Bounds& actual, std::vector<std::string>& warnings) {
  if (actual.empty()) return;
  for (int a = 0; a < 3; ++a) {
    const double tol = 2 * std::abs(h.scale[a]) + 1e-6 * std::abs(actual.max[a]);
    if (!(std::abs(actual.min[a] - h.min[a]) <= tol && std::abs(actual.max[a] - h.max[a]) <= tol)) {
      warnings.push_back("header bounds (min " + triple(h.min) + ", max " + triple(h.max) +
                         ") disagree with the points (min " + num(actual.min.x()) + " " +
                         num(actual.min.y()) + " " + num(actual.min.z()) + ", max " +
                         num(actual.max.x()) + " " + num(actual.max.y()) + " " +
                         num(actual.max.z()) + ")");
      return;
    }
  }
}

/// The facts `info` shows: header fields, how GPS time and colours are stored, every (E)VLR
/// and the warnings (moved out of `warnings`).
void addMetadata(std::vector<std::pair<std::string, std::string>>& m, const LasHeader& h,
                 const PointLayout& layout, std::size_t extra_bytes, bool rgb16,
                 const std::vector<LasVlr>& vlrs, std::vector<std::string>& warnings) {
  m.emplace_back("LAS version", std::to_string(h.version_major) + "." + std::to_string(h.version_minor));
  m.emplace_back("point format", std::to_string(h.format()));
  m.emplace_back("point record length", std::to_string(h.record_length) + " bytes (" +
                                            std::to_string(extra_bytes) + " extra)");
  m.emplace_back("point count", std::to_string(h.point_count));
  if (!h.system_identifier.empty()) m.emplace_back("system identifier", h.system_identifier);
  if (!h.generating_software.empty()) m.emplace_back("generating software", h.generating_software);
  if (h.creation_year)
    m.emplace_back("creation date", "day " + std::to_string(h.creation_day) + " of " +
                                        std::to_string(h.creation_year));
  m.emplace_back("file source id", std::to_string(h.file_source_id));
  m.emplace_back("global encoding", std::to_string(h.global_encoding));
  if (layout.gps_at >= 0)
    m.emplace_back("GPS time", (h.global_encoding & 1) ? "adjusted standard GPS time"
                                                       : "GPS week time");
  if (layout.rgb_at >= 0)
    m.emplace_back("RGB", rgb16 ? "16-bit (high byte kept)"
                                : "8-bit values in 16-bit fields (kept as they are)");
  if (layout.wave_at >= 0) m.emplace_back("waveform packets", "present, not read");
  m.emplace_back("scale", triple(h.scale));
  m.emplace_back("offset", triple(h.offset));
  m.emplace_back("header bounds", "min " + triple(h.min) + ", max " + triple(h.max));
  std::size_t nv = 0, ne = 0;
  for (const auto& v : vlrs)
    m.emplace_back(v.extended ? "EVLR " + std::to_string(++ne) : "VLR " + std::to_string(++nv),
                   vlrSummary(v));
  for (auto& w : warnings) m.emplace_back("warning", std::move(w));
}

Dataset readFromSource(const ByteSource& src, const std::filesystem::path& file,
                       const LasReadOptions& options, Progress* progress) {
  LasPrologue p = readPrologue(src, file);
  const LasHeader& h = p.header;
  const PointLayout layout = pointLayout(h.format());
  const std::size_t extra_bytes = h.record_length - layout.min_size;
  std::vector<ExtraField> extras = extraFields(p.vlrs, extra_bytes, options, file, p.warnings);

  Dataset d;
  d.source = file;
  d.format = "las";
  d.coordinate_system = coordinateSystem(p.vlrs, h, p.warnings);
  Scan scan;
  scan.name = file.stem().string();
  PointCloud& cloud = scan.cloud;
  cloud.offset = chooseOffset(h, src);

  PointDecoder decoder(h, std::move(extras), cloud);
  decodePoints(src, h, decoder, progress);
  cloud.dropNegligibleResiduals();
  const bool rgb16 = decoder.finish();
  if (decoder.badReturns() > 0)
    p.warnings.push_back(std::to_string(decoder.badReturns()) +
                         " points have a return number outside 1..number of returns (kept as "
                         "stored)");
  checkHeaderBounds(h, decoder.worldBounds(), p.warnings);
  addMetadata(d.metadata, h, layout, extra_bytes, rgb16, p.vlrs, p.warnings);
  d.scans.push_back(std::move(scan));
  return d;
}

/// Reads `n` records from `first` (in place for memory input, else into `chunk`).
const std::uint8_t* recordsAt(const ByteSource& src, const LasHeader& h, std::uint64_t first,
                              std::size_t n, std::vector<std::uint8_t>& chunk) {
  const std::uint64_t at = h.offset_to_points + first * h.record_length;
  if (src.data()) return src.data() + at;
  chunk.resize(n * h.record_length);
  src.read(at, chunk.data(), chunk.size());
  return chunk.data();
}

/// The RGB rule decided before streaming: true when some channel of some record exceeds 255
/// (the scan stops at the first; only files of 8-bit values are read to the end).
bool sixteenBitColor(const ByteSource& src, const LasHeader& h, const PointLayout& layout, Progress* progress) {
  if (layout.rgb_at < 0) return false;
  std::vector<std::uint8_t> chunk;
  for (std::uint64_t first = 0; first < h.point_count; first += kChunkRecords) {
    checkCanceled(progress);
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(kChunkRecords, h.point_count - first));
    const std::uint8_t* r = recordsAt(src, h, first, n, chunk) + layout.rgb_at;
    for (std::size_t i = 0; i < n; ++i, r += h.record_length)
      if (r[1] | r[3] | r[5]) return true;  // a high byte: a value above 255
  }
  return false;
}

/// The final columns of the streamed scan: the declared ones but the LAS fields in `zero` (0
/// in every point: readLas gives them no column).
std::vector<std::string> streamedFields(const std::vector<std::string>& declared, const std::vector<std::string>& zero) {
  std::vector<std::string> out;
  for (const auto& f : declared)
    if (std::find(zero.begin(), zero.end(), f) == zero.end()) out.push_back(f);
  return out;
}

/// Names of the LAS field columns of `c` that hold a value other than 0.
void markNonzero(const PointCloud& c, std::vector<std::string>& nonzero) {
  auto mark = [&](const char* name, const auto& v) {
    if (std::find(nonzero.begin(), nonzero.end(), name) != nonzero.end()) return;
    if (std::any_of(v.begin(), v.end(), [](auto x) { return x != 0; })) nonzero.push_back(name);
  };
  mark("scan_angle", c.scan_angle), mark("user_data", c.user_data), mark("point_source_id", c.point_source_id);
  mark("classification_flags", c.classification_flags), mark("scanner_channel", c.scanner_channel);
  mark("scan_flags", c.scan_flags);
}

/// What streaming needs from the header and VLRs, decided before the first point.
struct StreamSetup {
  LasPrologue p;
  PointLayout layout;
  std::size_t extra_bytes = 0;
  std::vector<ExtraField> extras;
  bool rgb16 = false;
  Eigen::Vector3d offset;
};

StreamSetup streamSetup(const ByteSource& src, const std::filesystem::path& file, Progress* progress) {
  StreamSetup s{readPrologue(src, file), {}, 0, {}, false, {}};
  const LasHeader& h = s.p.header;
  s.layout = pointLayout(h.format());
  s.extra_bytes = h.record_length - s.layout.min_size;
  s.extras = extraFields(s.p.vlrs, s.extra_bytes, LasReadOptions{}, file, s.p.warnings);
  s.rgb16 = sixteenBitColor(src, h, s.layout, progress);
  s.offset = chooseOffset(h, src);
  return s;
}

/// The one scan's outline; `fields` of a chunk (every LAS field column of the format).
StreamOutline streamOutline(StreamSetup& s, const std::filesystem::path& file) {
  StreamOutline outline;
  outline.dataset.source = file;
  outline.dataset.format = "las";
  outline.dataset.coordinate_system = coordinateSystem(s.p.vlrs, s.p.header, s.p.warnings);
  StreamScan scan;
  scan.scan.name = file.stem().string();
  scan.record_count = s.p.header.point_count;
  scan.intensity_integral = true;  // uint16
  PointCloud sample;
  PointDecoder(s.p.header, s.extras, sample, 1, s.rgb16);
  scan.fields = sample.fieldNames();
  outline.scans.push_back(scan);
  outline.dataset.scans.push_back(scan.scan);
  return outline;
}

/// What the records told beyond the points: readLas's checks and which LAS fields are not 0.
struct StreamedRecords {
  Bounds world;
  std::uint64_t bad_returns = 0;
  std::vector<std::string> nonzero;
};

StreamedRecords streamRecords(const ByteSource& src, const StreamSetup& s, std::size_t capacity,
                              ChunkSink& sink, Progress* progress) {
  const LasHeader& h = s.p.header;
  StreamedRecords r;
  PointCloud chunk;
  chunk.offset = s.offset;
  std::vector<std::uint8_t> buffer;
  for (std::uint64_t first = 0; first < h.point_count; first += capacity) {
    checkCanceled(progress);
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(capacity, h.point_count - first));
    chunk.scalar_fields.clear();
    PointDecoder decoder(h, s.extras, chunk, n, s.rgb16);
    for (std::size_t done = 0; done < n; done += kChunkRecords) {
      const std::size_t m = std::min(kChunkRecords, n - done);
      decoder.decode(recordsAt(src, h, first + done, m, buffer), m, done);
    }
    r.bad_returns += decoder.badReturns();
    r.world.extend(decoder.worldBounds());
    markNonzero(chunk, r.nonzero);
    sink.chunk(chunk);
    reportProgress(progress, static_cast<double>(first + n) / static_cast<double>(h.point_count), "reading LAS points");
  }
  return r;
}

/// The end of the scan as readLas would show it.
StreamScanEnd streamEnd(const StreamSetup& s, const StreamScan& scan, const StreamedRecords& r) {
  StreamScanEnd end;
  end.points = s.p.header.point_count;
  std::vector<std::string> zero;
  for (const char* f : {"scan_angle", "user_data", "point_source_id", "classification_flags", "scanner_channel", "scan_flags"})
    if (std::find(r.nonzero.begin(), r.nonzero.end(), f) == r.nonzero.end()) zero.push_back(f);
  PointCloud none;  // the columns of an empty file
  PointDecoder(s.p.header, s.extras, none, 0, s.rgb16);
  end.fields = streamedFields(end.points > 0 ? scan.fields : none.fieldNames(), zero);
  return end;
}

void streamFromSource(const ByteSource& src, const std::filesystem::path& file, const StreamOptions& options,
                      ChunkSink& sink, Progress* progress) {
  StreamSetup s = streamSetup(src, file, progress);
  StreamOutline outline = streamOutline(s, file);
  sink.begin(outline);
  sink.beginScan(outline.scans[0]);
  const StreamedRecords r = streamRecords(src, s, chunkCapacity(options), sink, progress);
  sink.endScan(streamEnd(s, outline.scans[0], r));
  if (r.bad_returns > 0)
    s.p.warnings.push_back(std::to_string(r.bad_returns) +
                           " points have a return number outside 1..number of returns (kept as stored)");
  checkHeaderBounds(s.p.header, r.world, s.p.warnings);
  addMetadata(outline.dataset.metadata, s.p.header, s.layout, s.extra_bytes, s.rgb16, s.p.vlrs, s.p.warnings);
  sink.end(outline);
}

bool hasLazExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".laz";
}
}  // namespace

Dataset readLas(const std::filesystem::path& path, const LasReadOptions& options,
                Progress* progress) {
  if (hasLazExtension(path)) throw FileError(path, lazMessage(".laz file name"));
  FileSource src(path);
  return readFromSource(src, path, options, progress);
}

void streamLas(const std::filesystem::path& path, const StreamOptions& options, ChunkSink& sink,
               Progress* progress) {
  if (hasLazExtension(path)) throw FileError(path, lazMessage(".laz file name"));
  FileSource src(path);
  streamFromSource(src, path, options, sink, progress);
}

Dataset readLasBuffer(std::span<const std::uint8_t> bytes, const std::filesystem::path& name,
                      const LasReadOptions& options, Progress* progress) {
  MemorySource src(bytes, name);
  return readFromSource(src, name, options, progress);
}

}  // namespace plumb
