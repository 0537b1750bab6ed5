#include "io/lod/lod_format.hpp"

#include <sys/stat.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "common/error.hpp"

namespace plumb {
namespace {

static_assert(std::endian::native == std::endian::little, "the cache is written little-endian");

constexpr char kIndexMagic[8] = {'P', 'L', 'U', 'M', 'B', 'L', 'O', 'D'};
constexpr char kPointsMagic[8] = {'P', 'L', 'U', 'M', 'B', 'P', 'T', 'S'};
constexpr std::size_t kNodeRecordBytes = 4 + 1 + 12 + 8 + 8;

std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  return h;
}

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
void putString(std::string& out, const std::string& s) {
  put(out, static_cast<std::uint32_t>(s.size()));
  out += s;
}

/// Reads values from the index bytes; every read past the end is a FileError at its byte.
class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, const std::filesystem::path& file)
      : bytes_(bytes), end_(end), file_(file) {}
  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, bytes_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  std::string getString(const char* what) {
    const auto n = get<std::uint32_t>(what);
    need(n, what);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  void need(std::uint64_t n, const char* what) const {
    if (n > end_ - pos_) fail(std::string("truncated ") + what);
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw FileError(file_, "damaged level-of-detail index: " + message, atByte(pos_));
  }
  std::size_t pos() const { return pos_; }

 private:
  const std::string& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
  const std::filesystem::path& file_;
};

void encodeHierarchyHeader(std::string& out, const LodHierarchy& h) {
  for (int a = 0; a < 3; ++a) put(out, h.grid.origin[a]);
  put(out, h.grid.quantum);
  put(out, static_cast<std::int32_t>(h.grid.levels));
  put(out, static_cast<std::int32_t>(h.grid.cell_bits));
  for (int a = 0; a < 3; ++a) put(out, h.bounds.min[a]);
  for (int a = 0; a < 3; ++a) put(out, h.bounds.max[a]);
  put(out, h.node_capacity);
  put(out, h.points);
  put(out, static_cast<std::uint32_t>(h.stations.size()));
  for (const LodStation& s : h.stations) {
    putString(out, s.name);
    put(out, static_cast<std::uint8_t>(s.has_intensity));
    put(out, static_cast<std::uint8_t>(s.has_rgb));
  }
  put(out, static_cast<std::uint8_t>(h.has_intensity));
  put(out, static_cast<std::uint8_t>(h.has_rgb));
}

void decodeGrid(Reader& r, LodHierarchy& h) {
  for (int a = 0; a < 3; ++a) h.grid.origin[a] = r.get<double>("origin");
  h.grid.quantum = r.get<double>("quantum");
  h.grid.levels = r.get<std::int32_t>("levels");
  h.grid.cell_bits = r.get<std::int32_t>("cell bits");
  if (!h.grid.origin.allFinite() || !(h.grid.quantum > 0) || !std::isfinite(h.grid.quantum))
    r.fail("origin or quantum not a finite positive number");
  if (h.grid.cell_bits < 4 || h.grid.cell_bits > 10 || h.grid.levels < 0 || h.grid.rootBits() > 31)
    r.fail("octree levels " + std::to_string(h.grid.levels) + " / cell bits " + std::to_string(h.grid.cell_bits) +
           " out of range");
  for (int a = 0; a < 3; ++a) h.bounds.min[a] = r.get<double>("bounds");
  for (int a = 0; a < 3; ++a) h.bounds.max[a] = r.get<double>("bounds");
  h.node_capacity = r.get<std::uint32_t>("node capacity");
  h.points = r.get<std::uint64_t>("point count");
}

void decodeStations(Reader& r, LodHierarchy& h) {
  const auto n = r.get<std::uint32_t>("station count");
  r.need(std::uint64_t{n} * 6, "station list");  // each at least a length and two flags
  for (std::uint32_t i = 0; i < n; ++i) {
    LodStation s;
    s.name = r.getString("station name");
    s.has_intensity = r.get<std::uint8_t>("station flags") != 0;
    s.has_rgb = r.get<std::uint8_t>("station flags") != 0;
    h.stations.push_back(std::move(s));
  }
  h.has_intensity = r.get<std::uint8_t>("flags") != 0;
  h.has_rgb = r.get<std::uint8_t>("flags") != 0;
}

/// Checks one node against its parent and links it; fails on any inconsistency.
void linkNode(Reader& r, LodHierarchy& h, LodNode& n, std::uint64_t points_bytes) {
  const std::string where = "node " + std::to_string(n.id);
  const std::uint64_t side = std::uint64_t{1} << n.key.depth;
  if (n.key.depth > h.grid.levels || n.key.xyz[0] >= side || n.key.xyz[1] >= side || n.key.xyz[2] >= side)
    r.fail(where + ": position outside the octree");
  if (n.id == 0 ? (n.parent != kNoLodNode || n.key.depth != 0) : (n.parent >= n.id))
    r.fail(where + ": parent " + std::to_string(n.parent) + " does not come before it");
  if (n.id != 0) {
    LodNode& p = h.nodes[n.parent];
    const int o = static_cast<int>((n.key.xyz[0] & 1) | ((n.key.xyz[1] & 1) << 1) | ((n.key.xyz[2] & 1) << 2));
    if (!(p.key.child(o) == n.key) || p.children[o] != kNoLodNode) r.fail(where + ": not a child of its parent");
    p.children[o] = n.id;
  }
  const std::uint64_t bytes = lodNodeBytes(n.point_count, h.has_intensity, h.has_rgb);
  if (n.data_offset < kLodPointsHeaderBytes || n.data_offset > points_bytes || bytes > points_bytes - n.data_offset)
    r.fail(where + ": points at byte " + std::to_string(n.data_offset) + " beyond the point file's " +
           std::to_string(points_bytes) + " bytes");
  n.bounds = h.grid.bounds(n.key);
  n.spacing = h.grid.spacing(n.key.depth);
}

void decodeNodes(Reader& r, LodHierarchy& h, std::uint64_t points_bytes) {
  const auto n = r.get<std::uint64_t>("node count");
  if (n > (std::uint64_t{1} << 32) - 1) r.fail("node count " + std::to_string(n));
  r.need(n * kNodeRecordBytes, "node list");  // checked before allocating
  h.nodes.resize(n);
  std::uint64_t total = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    LodNode& node = h.nodes[i];
    node.id = i;
    node.parent = r.get<std::uint32_t>("node");
    node.key.depth = r.get<std::uint8_t>("node");
    for (auto& c : node.key.xyz) c = r.get<std::uint32_t>("node");
    node.point_count = r.get<std::uint64_t>("node");
    node.data_offset = r.get<std::uint64_t>("node");
    linkNode(r, h, node, points_bytes);
    total += node.point_count;
  }
  if (total != h.points) r.fail("nodes hold " + std::to_string(total) + " points, header says " + std::to_string(h.points));
}

}  // namespace

LodSourceStamp lodSourceStamp(const std::filesystem::path& source) {
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::canonical(source, ec);
  struct stat st {};
  if (ec || ::stat(canonical.c_str(), &st) != 0)
    throw FileError(source, "cannot read the file's size and modification time");
  return {canonical.string(), static_cast<std::uint64_t>(st.st_size),
          static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec};
}

std::filesystem::path lodCacheDirectory(const std::filesystem::path& source, const std::filesystem::path& cache_root) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::weakly_canonical(source, ec);
  if (ec) p = std::filesystem::absolute(source).lexically_normal();
  const std::string s = p.string();
  char name[17];
  std::snprintf(name, sizeof name, "%016llx", static_cast<unsigned long long>(fnv1a(s.data(), s.size())));
  return cache_root / name;
}

std::uint64_t lodNodeBytes(std::uint64_t count, bool has_intensity, bool has_rgb) {
  return count * (12 + 2 + (has_intensity ? 4 : 0) + (has_rgb ? 3 : 0));
}

std::string encodeLodPoints(const std::vector<LodPoint>& points, bool has_intensity, bool has_rgb) {
  std::string out;
  out.reserve(lodNodeBytes(points.size(), has_intensity, has_rgb));
  for (const LodPoint& p : points) put(out, p.q);
  for (const LodPoint& p : points) put(out, p.station);
  if (has_intensity)
    for (const LodPoint& p : points) put(out, p.intensity);
  if (has_rgb)
    for (const LodPoint& p : points) put(out, p.rgb);
  return out;
}

std::string lodPointsHeader() {
  std::string out(kPointsMagic, sizeof kPointsMagic);
  put(out, kLodFormatVersion);
  put(out, std::uint32_t{0});
  return out;
}

std::string encodeLodIndex(const LodIndex& index) {
  std::string out(kIndexMagic, sizeof kIndexMagic);
  put(out, kLodFormatVersion);
  putString(out, index.source.path);
  put(out, index.source.size);
  put(out, index.source.mtime_ns);
  put(out, index.points_file_bytes);
  encodeHierarchyHeader(out, index.hierarchy);
  put(out, static_cast<std::uint64_t>(index.hierarchy.nodes.size()));
  for (const LodNode& n : index.hierarchy.nodes) {
    put(out, n.parent);
    put(out, static_cast<std::uint8_t>(n.key.depth));
    put(out, n.key.xyz);
    put(out, n.point_count);
    put(out, n.data_offset);
  }
  put(out, fnv1a(out.data(), out.size()));
  return out;
}

LodIndex decodeLodIndex(const std::string& bytes, const std::filesystem::path& file) {
  if (bytes.size() < sizeof kIndexMagic + 4 + 8 || std::memcmp(bytes.data(), kIndexMagic, sizeof kIndexMagic) != 0)
    throw FileError(file, "not a level-of-detail index (no PLUMBLOD signature)", atByte(0));
  Reader r(bytes, bytes.size() - 8, file);
  r.get<std::uint64_t>("signature");
  const auto version = r.get<std::uint32_t>("version");
  if (version != kLodFormatVersion)
    throw FileError(file, "format version " + std::to_string(version) + ", this build reads version " +
                              std::to_string(kLodFormatVersion), atByte(8));
  std::uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (stored != fnv1a(bytes.data(), bytes.size() - 8))
    throw FileError(file, "damaged level-of-detail index: checksum mismatch", atByte(bytes.size() - 8));
  LodIndex index;
  index.source.path = r.getString("source path");
  index.source.size = r.get<std::uint64_t>("source size");
  index.source.mtime_ns = r.get<std::int64_t>("source time");
  index.points_file_bytes = r.get<std::uint64_t>("point file size");
  decodeGrid(r, index.hierarchy);
  decodeStations(r, index.hierarchy);
  decodeNodes(r, index.hierarchy, index.points_file_bytes);
  if (r.pos() != bytes.size() - 8) r.fail("unexpected bytes after the node list");
  return index;
}

}  // namespace plumb
