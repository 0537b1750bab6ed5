#include "io/ply/ply_reader.hpp"
#include "common/float_cast.hpp"

#include <unistd.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cerrno>
#include <optional>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <type_traits>

#include "common/error.hpp"
#include "io/ply/block_reader.hpp"
#include "io/ply/record_copy.hpp"
#include "io/ply/ply_values.hpp"

namespace plumb {
namespace {

using ply::BlockReader;
using ply::Element;
using ply::Encoding;
using ply::Type;

std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

enum class Target : std::uint8_t { Skip, Position, Normal, Color, Intensity, Scalar, Extra };
// Typed per-point columns other than positions/normals/colors/intensity, read through doubles.
const char* const kExtraNames[] = {"return_index", "return_count", "timestamp", "gps_time",
                                   "row", "column", "classification", "scan_id"};
struct Slot {
  Target target = Target::Skip;
  int comp = 0;
  Type type = Type::Float32;
  std::size_t offset = 0;  ///< byte offset inside a binary record
  std::size_t scalar = 0;  ///< index into scalar columns
};

/// Destination columns of the vertex element.
struct Columns {
  float* pos = nullptr;
  float* res = nullptr;  ///< position residuals (double positions only), else null
  float* nrm = nullptr;
  std::uint8_t* rgb = nullptr;
  float* inten = nullptr;
  std::vector<float*> scalars;
  std::vector<double*> extras;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

template <class T>
inline std::uint8_t toColor(T v) {
  if constexpr (std::is_same_v<T, std::uint8_t>) {
    return v;
  } else if constexpr (std::is_same_v<T, std::uint16_t>) {
    return static_cast<std::uint8_t>(v >> 8);
  } else if constexpr (std::is_floating_point_v<T>) {
    if (std::isnan(v)) return 0;  // found by fuzz_ply: converting NaN to an integer is undefined
    const double s = std::clamp(static_cast<double>(v) * 255.0 + 0.5, 0.0, 255.0);
    return static_cast<std::uint8_t>(s);
  } else {
    return static_cast<std::uint8_t>(std::clamp<long long>(v, 0, 255));
  }
}

/// v converted to T: integers clamped to T's range (NaN -> 0), floats beyond range -> +-inf.
/// Out-of-range conversions of file values are undefined behaviour.
template <class T>
T saturate(double v) {
  if constexpr (std::is_floating_point_v<T>) {
    if constexpr (std::is_same_v<T, float>) return toFloat(v);  // found by fuzz_ply
    else return static_cast<T>(v);
  } else {
    if (std::isnan(v)) return T{0};
    return static_cast<T>(std::clamp(v, static_cast<double>(std::numeric_limits<T>::lowest()),
                                     static_cast<double>(std::numeric_limits<T>::max())));
  }
}

/// Extracts k binary records (stride bytes each) starting at p into the columns at `base`.
template <bool Swap>
void extractBlock(const char* p, std::size_t k, std::size_t stride, const std::vector<Slot>& slots,
                  const Columns& c, std::size_t base) {
  for (const Slot& s : slots) {
    if (s.target == Target::Skip) continue;
    const char* q = p + s.offset;
    ply::withType(s.type, [&](auto tag) {
      using T = decltype(tag);
      switch (s.target) {
        case Target::Position: {
          float* d = c.pos + base * 3 + s.comp;
          const double off = c.offset[s.comp];
          if (std::is_same_v<T, float> && off == 0.0) {
            for (std::size_t i = 0; i < k; ++i)
              d[3 * i] = static_cast<float>(ply::load<T, Swap>(q + i * stride));
          } else if (c.res) {  // exact local: float part and residual
            float* r = c.res + base * 3 + s.comp;
            for (std::size_t i = 0; i < k; ++i)
              PointCloud::splitComponent(static_cast<double>(ply::load<T, Swap>(q + i * stride)) - off,
                                         d[3 * i], r[3 * i]);
          } else {
            for (std::size_t i = 0; i < k; ++i)
              d[3 * i] = toFloat(static_cast<double>(ply::load<T, Swap>(q + i * stride)) - off);
          }
          break;
        }
        case Target::Normal: {
          float* d = c.nrm + base * 3 + s.comp;
          for (std::size_t i = 0; i < k; ++i)
            d[3 * i] = toFloat(static_cast<double>(ply::load<T, Swap>(q + i * stride)));
          break;
        }
        case Target::Color: {
          std::uint8_t* d = c.rgb + base * 3 + s.comp;
          for (std::size_t i = 0; i < k; ++i) d[3 * i] = toColor(ply::load<T, Swap>(q + i * stride));
          break;
        }
        case Target::Intensity:
        case Target::Scalar: {
          float* d = (s.target == Target::Intensity ? c.inten : c.scalars[s.scalar]) + base;
          for (std::size_t i = 0; i < k; ++i)
            d[i] = toFloat(static_cast<double>(ply::load<T, Swap>(q + i * stride)));
          break;
        }
        case Target::Extra: {
          double* d = c.extras[s.scalar] + base;
          for (std::size_t i = 0; i < k; ++i)
            d[i] = static_cast<double>(ply::load<T, Swap>(q + i * stride));
          break;
        }
        case Target::Skip: break;
      }
    });
  }
}

/// One value of a generic (ASCII or list-carrying) vertex record.
void putValue(const Slot& s, const Columns& c, std::size_t i, double v) {
  switch (s.target) {
    case Target::Position:
      if (c.res) PointCloud::splitComponent(v - c.offset[s.comp], c.pos[i * 3 + s.comp], c.res[i * 3 + s.comp]);
      else c.pos[i * 3 + s.comp] = toFloat(v - c.offset[s.comp]);
      break;
    case Target::Normal: c.nrm[i * 3 + s.comp] = toFloat(v); break;
    case Target::Color:
      c.rgb[i * 3 + s.comp] = ply::withType(s.type, [&](auto tag) {
        return toColor(saturate<decltype(tag)>(v));
      });
      break;
    case Target::Intensity: c.inten[i] = toFloat(v); break;
    case Target::Scalar: c.scalars[s.scalar][i] = toFloat(v); break;
    case Target::Extra: c.extras[s.scalar][i] = v; break;
    case Target::Skip: break;
  }
}

/// Splits slots into plain copies (no byte swap, same type, consecutive components, zero
/// offset) and the rest (converted value by value).
void planCopies(const std::vector<Slot>& slots, const Columns& c, bool sw, std::vector<ply::FieldCopy>& copies,
                std::vector<Slot>& rest) {
  std::vector<bool> used(slots.size(), false);
  if (!sw) {
    auto triple = [&](Target t, Type type, char* dst, std::size_t bytes) {
      int idx[3] = {-1, -1, -1};
      for (std::size_t j = 0; j < slots.size(); ++j)
        if (slots[j].target == t) idx[slots[j].comp] = static_cast<int>(j);
      if (idx[0] < 0 || !dst) return;
      const std::size_t sz = bytes / 3;
      for (int k = 0; k < 3; ++k)
        if (slots[idx[k]].type != type || slots[idx[k]].offset != slots[idx[0]].offset + k * sz) return;
      if (t == Target::Position && (!c.offset.isZero() || c.res)) return;
      copies.push_back({slots[idx[0]].offset, dst, bytes});
      for (int k : idx) used[k] = true;
    };
    triple(Target::Position, Type::Float32, reinterpret_cast<char*>(c.pos), 12);
    triple(Target::Normal, Type::Float32, reinterpret_cast<char*>(c.nrm), 12);
    triple(Target::Color, Type::UInt8, reinterpret_cast<char*>(c.rgb), 3);
    for (std::size_t j = 0; j < slots.size(); ++j) {
      const Slot& s = slots[j];
      if (s.type != Type::Float32 || used[j]) continue;
      float* d = s.target == Target::Intensity ? c.inten : s.target == Target::Scalar ? c.scalars[s.scalar] : nullptr;
      if (!d) continue;
      copies.push_back({s.offset, reinterpret_cast<char*>(d), 4});
      used[j] = true;
    }
  }
  for (std::size_t j = 0; j < slots.size(); ++j)
    if (!used[j]) rest.push_back(slots[j]);
}

/// Reads [offset, offset+size) of a file with pread into `buffer` (reused between windows of
/// one thread, so no memory is mapped or faulted per window).
const char* readWindow(int fd, std::uint64_t offset, std::size_t size, Column<char>& buffer,
                       const std::filesystem::path& path) {
  if (buffer.size() < size) buffer.resize(size);
  std::size_t got = 0;
  while (got < size) {
    const ssize_t r = ::pread(fd, buffer.data() + got, size - got, static_cast<off_t>(offset + got));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw FileError(path, "read error (file changed while reading?)", atByte(offset + got));
    got += static_cast<std::size_t>(r);
  }
  return buffer.data();
}

/// Bytes of vertex records read per window: one pread, then converted while still in the L2
/// cache (1 MiB measured as fast as 4 MiB and 512 KiB, with less memory per thread).
constexpr std::size_t kWindowBytes = std::size_t{1} << 20;

/// Block size of the sequential reader (header, ASCII and list-carrying elements; fixed-size
/// binary vertices are read in windows by the threads): small enough to come from malloc's heap
/// rather than a fresh mapping, whose 4 KiB page faults cost more than reading a 4 MiB block.
/// It grows when a header or line needs more.
constexpr std::size_t kHeadBlockBytes = std::size_t{64} << 10;

/// World position of a record whose values (one per slot) are `v`.
Eigen::Vector3d valuePosition(const std::vector<Slot>& slots, const std::vector<double>& v) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < slots.size(); ++j)
    if (slots[j].target == Target::Position) p[slots[j].comp] = v[j];
  return p;
}

/// World position of the binary record at `record`.
template <bool Swap>
Eigen::Vector3d binaryPosition(const std::vector<Slot>& slots, const char* record) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const Slot& s : slots)
    if (s.target == Target::Position) p[s.comp] = ply::loadAsDouble<Swap>(s.type, record + s.offset);
  return p;
}

const char* const kFaceIdNames[] = {"element_id", "element", "object_id", "segment_id"};

/// Reads one PLY file. Holds the state shared by the element readers.
/// Moves the kExtraNames values read as doubles into their PointCloud columns (saturated to
/// each column's type) and frees them.
void storeExtras(const std::vector<std::string>& names, std::vector<Column<double>>& values, PointCloud& cloud) {
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& v = values[k];
    auto fill = [&](auto& dst) {
      dst.resize(v.size());
      for (std::size_t i = 0; i < v.size(); ++i)
        dst[i] = saturate<typename std::decay_t<decltype(dst)>::value_type>(v[i]);
    };
    const std::string& nm = names[k];
    if (nm == "return_index") fill(cloud.return_index);
    else if (nm == "return_count") fill(cloud.return_count);
    else if (nm == "timestamp" || nm == "gps_time") fill(cloud.timestamps);
    else if (nm == "row") fill(cloud.row);
    else if (nm == "column") fill(cloud.column);
    else if (nm == "classification") fill(cloud.classification);
    else if (nm == "scan_id") fill(cloud.scan_id);
    Column<double>().swap(values[k]);
  }
}

/// What the vertex properties become: one Slot per property, and which optional columns
/// the cloud gets.
struct VertexLayout {
  std::vector<Slot> slots;
  bool has_normals = false;
  bool has_colors = false;
  int intensity = -1;  ///< property index, -1 when none
  std::vector<std::string> extra_names;  ///< kExtraNames present, in Slot::scalar order
  bool double_coords = false;            ///< some coordinate is a double
};

class Reader {
 public:
  Reader(const std::filesystem::path& path, Progress* progress, const PlyVertexStream* stream = nullptr,
         std::size_t chunk_points = 0)
      : path_(path), in_(path, kHeadBlockBytes), progress_(progress), stream_(stream), chunk_points_(chunk_points) {}

  PlyData run() {
    if (in_.fileSize() == 0) throw FileError(path_, "file is empty (0 bytes)");
    // The header: read until "end_header" is in the buffer (headers are small; cap at 1 MB).
    std::size_t want = 4096;
    while (true) {
      in_.fill(want);
      const std::string_view text(in_.data(), in_.available());
      if (text.find("end_header") != std::string_view::npos &&
          text.find('\n', text.find("end_header")) != std::string_view::npos)
        break;
      if (in_.available() < want || want >= (1u << 20)) break;  // EOF or too long: parser reports
      want *= 4;
    }
    out_.header = ply::parseHeader(in_.data(), in_.available(), path_);
    ply::checkElementSizes(out_.header, in_.fileSize() - out_.header.data_offset, path_);
    in_.consume(out_.header.data_offset);
    line_ = out_.header.data_line;
    for (const Element& e : out_.header.elements) {
      if (e.name == "vertex") stream_ ? streamVertices(e) : readVertices(e);
      else if (e.name == "face" && !stream_) readFaces(e);
      else skipElement(e);
    }
    if (!saw_vertex_)
      throw FileError(path_, "PLY file has no \"vertex\" element", atLine(1, "PLY header"));
    if (stream_) {
      readGridComment(vertex_count_);
      return std::move(out_);
    }
    checkFaceIndices();
    readElementComments();
    readGridComment(out_.vertices.size());
    return std::move(out_);
  }

 private:
  bool binary() const { return out_.header.encoding != Encoding::Ascii; }
  bool swap() const {
    const bool little = out_.header.encoding == Encoding::BinaryLittleEndian;
    return binary() && (little != (std::endian::native == std::endian::little));
  }

  [[noreturn]] void truncated(const Element& e, std::uint64_t index,
                              std::optional<std::uint64_t> end_byte = {}) {
    std::ostringstream msg;
    const std::string plural = e.name == "vertex" ? "vertices" : e.name + "s";
    msg << "truncated data: expected " << e.count << " " << plural << ", file ends at byte "
        << end_byte.value_or(in_.offset() + in_.available()) << " in " << e.name << " " << index;
    FileLocation loc;
    loc.element = e.name + " " + std::to_string(index);
    if (!binary()) loc.line = line_;
    throw FileError(path_, msg.str(), loc);
  }

  [[noreturn]] void badValue(const Element& e, std::uint64_t index, const std::string& what) {
    FileLocation loc;
    loc.element = e.name + " " + std::to_string(index);
    if (binary()) loc.byte_offset = in_.offset();
    else loc.line = line_;
    throw FileError(path_, what, loc);
  }

  void report() {
    if (!progress_) return;
    checkCanceled(progress_);
    const double total = static_cast<double>(std::max<std::uint64_t>(in_.fileSize(), 1));
    reportProgress(progress_, static_cast<double>(in_.offset()) / total, "reading PLY");
  }

  // ---- ASCII record access ----------------------------------------------------------------
  /// Loads the next non-blank line into line_text_; false at end of file.
  bool nextLine() {
    while (true) {
      if (in_.available() == 0 && in_.fill(1) == 0) return false;
      const void* nl = std::memchr(in_.data(), '\n', in_.available());
      while (!nl) {
        const std::size_t have = in_.available();
        if (in_.fill(have + 1) == have) break;  // end of file: last line has no newline
        nl = std::memchr(in_.data(), '\n', in_.available());
      }
      const std::size_t len =
          nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - in_.data()) : in_.available();
      line_text_.assign(in_.data(), len);
      in_.consume(nl ? len + 1 : len);
      cursor_ = 0;
      if (line_text_.find_first_not_of(" \t\r") != std::string::npos) return true;
      ++line_;  // blank line
    }
  }

  double asciiValue(const Element& e, std::uint64_t index) {
    while (cursor_ < line_text_.size() &&
           (line_text_[cursor_] == ' ' || line_text_[cursor_] == '\t' || line_text_[cursor_] == '\r'))
      ++cursor_;
    if (cursor_ >= line_text_.size())
      badValue(e, index, "too few values on the line for " + e.name + " " + std::to_string(index));
    const char* b = line_text_.data() + cursor_;
    const char* end = line_text_.data() + line_text_.size();
    double v = 0;
    auto [p, ec] = std::from_chars(b, end, v);
    if (ec != std::errc() || (p < end && *p != ' ' && *p != '\t' && *p != '\r')) {
      const char* tok_end = b;
      while (tok_end < end && *tok_end != ' ' && *tok_end != '\t' && *tok_end != '\r') ++tok_end;
      badValue(e, index, "'" + std::string(b, tok_end) + "' is not a number");
    }
    cursor_ = static_cast<std::size_t>(p - line_text_.data());
    return v;
  }

  void endAsciiRecord(const Element& e, std::uint64_t index) {
    if (line_text_.find_first_not_of(" \t\r", cursor_) != std::string::npos)
      badValue(e, index, "more values on the line than the header declares for " + e.name);
    ++line_;
  }

  // ---- generic value access (ASCII or binary) ---------------------------------------------
  bool beginRecord() { return binary() || nextLine(); }

  double value(const Element& e, std::uint64_t index, Type t) {
    if (!binary()) return asciiValue(e, index);
    const std::size_t n = ply::typeSize(t);
    if (in_.fill(n) < n) truncated(e, index);
    const double v = swap() ? ply::loadAsDouble<true>(t, in_.data())
                            : ply::loadAsDouble<false>(t, in_.data());
    in_.consume(n);
    return v;
  }

  void endRecord(const Element& e, std::uint64_t index) {
    if (!binary()) endAsciiRecord(e, index);
  }

  std::uint64_t listCount(const Element& e, std::uint64_t index, const ply::Property& p) {
    const double c = value(e, index, p.count_type);
    if (!(c >= 0) || c > 1e6 || c != std::floor(c))
      badValue(e, index, "invalid list length " + std::to_string(c) + " for property '" + p.name + "'");
    return static_cast<std::uint64_t>(c);
  }

  // ---- elements -----------------------------------------------------------------------------
  void skipElement(const Element& e) {
    if (binary() && !e.hasLists()) {
      const std::uint64_t rs = e.recordSize();
      for (std::uint64_t i = 0; i < e.count;) {
        if (in_.fill(rs) < rs) truncated(e, i);
        const std::uint64_t k = std::min<std::uint64_t>(in_.available() / rs, e.count - i);
        in_.consume(k * rs);
        i += k;
      }
      return;
    }
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (!beginRecord()) truncated(e, i);
      for (const auto& p : e.properties) {
        const std::uint64_t n = p.is_list ? listCount(e, i, p) : 1;
        for (std::uint64_t j = 0; j < n; ++j) value(e, i, p.type);
      }
      endRecord(e, i);
    }
  }

  /// Maps the vertex properties to columns: x y z (required), normals and colours when all
  /// three are present, intensity, kExtraNames, and every other property a scalar field of
  /// `cloud` (added here); with each property's type and byte offset in a fixed-size record.
  VertexLayout mapVertexProperties(const Element& e, PointCloud& cloud) {
    VertexLayout l;
    std::vector<Slot>& slots = l.slots;
    slots.resize(e.properties.size());
    std::map<std::string, int> index;
    for (std::size_t i = 0; i < e.properties.size(); ++i)
      if (!e.properties[i].is_list) index.emplace(lower(e.properties[i].name), static_cast<int>(i));
    auto findAny = [&](std::initializer_list<const char*> names) {
      for (const char* nm : names)
        if (auto it = index.find(nm); it != index.end() && slots[it->second].target == Target::Skip)
          return it->second;
      return -1;
    };
    auto mapTriple = [&](Target t, std::initializer_list<std::initializer_list<const char*>> names) {
      int idx[3];
      int k = 0;
      for (const auto& alternatives : names) idx[k++] = findAny(alternatives);
      if (idx[0] < 0 || idx[1] < 0 || idx[2] < 0) return false;
      for (int c = 0; c < 3; ++c) slots[idx[c]] = {t, c};
      return true;
    };
    if (!mapTriple(Target::Position, {{"x"}, {"y"}, {"z"}}))
      throw FileError(path_, "vertex element has no x, y and z properties",
                      atLine(e.header_line, "PLY header"));
    l.has_normals = mapTriple(Target::Normal, {{"nx", "normal_x"}, {"ny", "normal_y"}, {"nz", "normal_z"}});
    l.has_colors = mapTriple(Target::Color, {{"red", "diffuse_red", "r"}, {"green", "diffuse_green", "g"},
                                             {"blue", "diffuse_blue", "b"}});
    l.intensity = findAny({"intensity", "scalar_intensity"});
    if (l.intensity >= 0) slots[l.intensity].target = Target::Intensity;
    for (const char* nm : kExtraNames)
      if (int k = findAny({nm}); k >= 0) {
        slots[k].target = Target::Extra;
        slots[k].scalar = l.extra_names.size();
        l.extra_names.emplace_back(nm);
      }
    std::size_t offset = 0;
    std::size_t n_scalars = 0;
    for (std::size_t i = 0; i < slots.size(); ++i) {
      const auto& p = e.properties[i];
      slots[i].type = p.type;
      slots[i].offset = offset;
      offset += ply::typeSize(p.type);
      if (!p.is_list && slots[i].target == Target::Skip) {
        slots[i].target = Target::Scalar;
        slots[i].scalar = n_scalars++;
        cloud.scalar_fields.push_back({p.name, {}});
      }
    }
    // Double coordinates: offset from a sample of the first records (offsetFromSample), and
    // a residual column so every double keeps its exact value (float sources need neither).
    l.double_coords = std::any_of(slots.begin(), slots.end(), [](const Slot& s) {
      return s.target == Target::Position && s.type == Type::Float64;
    });
    return l;
  }

  /// Sizes the columns of `n` points and returns where the records go.
  static Columns sizeColumns(PointCloud& cloud, std::size_t n, const VertexLayout& l,
                             std::vector<Column<double>>& extra_values) {
    // resizeForOverwrite leaves the values uninitialised (every record writes every column)
    // and Column<T> maps large columns on huge pages, so the threads that convert the records
    // touch them first, window by window: the kernel's zeroing is spread evenly over the
    // threads and each huge page is still in cache when the converted values overwrite its
    // zeros (zeroing colours and intensity in a pass of their own first cost 70 MB of extra
    // memory traffic and 22% of the read time on 10M points).
    resizeForOverwrite(cloud.positions, n);
    if (l.double_coords) resizeForOverwrite(cloud.position_residuals, n);
    if (l.has_normals) resizeForOverwrite(cloud.normals, n);
    if (l.has_colors) resizeForOverwrite(cloud.colors, n);
    if (l.intensity >= 0) resizeForOverwrite(cloud.intensity, n);
    for (auto& f : cloud.scalar_fields) resizeForOverwrite(f.values, n);
    for (auto& v : extra_values) resizeForOverwrite(v, n);
    Columns c;
    c.pos = cloud.positions.empty() ? nullptr : cloud.positions[0].data();
    c.res = cloud.position_residuals.empty() ? nullptr : cloud.position_residuals[0].data();
    c.nrm = l.has_normals && n ? cloud.normals[0].data() : nullptr;
    c.rgb = l.has_colors && n ? cloud.colors[0].data() : nullptr;
    c.inten = l.intensity >= 0 ? cloud.intensity.data() : nullptr;
    for (auto& f : cloud.scalar_fields) c.scalars.push_back(f.values.data());
    for (auto& v : extra_values) c.extras.push_back(v.data());
    return c;
  }

  /// Binary vertex records without lists: the offset from a sample of the first records (with
  /// double coordinates), then all records at their fixed stride.
  void readFixedVertices(const Element& e, std::size_t n, const VertexLayout& l, Columns& c, PointCloud& cloud) {
    const std::uint64_t start = in_.offset();
    c.offset = fixedVertexOffset(e, n, l);
    cloud.offset = c.offset;
    readFixedRecords(start, n, e.recordSize(), swap(), l.slots, c);
    in_.seek(start + static_cast<std::uint64_t>(n) * e.recordSize());
  }

  /// Fixed-size binary vertices at the reader's position: checks that all `n` fit in the file
  /// and gives their offset (double coordinates: from a sample of the first records).
  Eigen::Vector3d fixedVertexOffset(const Element& e, std::size_t n, const VertexLayout& l) {
    const std::size_t stride = e.recordSize();
    const std::uint64_t start = in_.offset();
    if (n > 0 && in_.fill(stride) < stride) truncated(e, 0);
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    if (l.double_coords && n > 0) {
      const std::size_t k = std::min({n, kOffsetSampleSize, std::max<std::size_t>(1, kWindowBytes / stride)});
      const std::size_t got = std::min(k, in_.fill(k * stride) / stride);
      std::vector<Eigen::Vector3d> sample(got);
      for (std::size_t j = 0; j < got; ++j)
        sample[j] = swap() ? binaryPosition<true>(l.slots, in_.data() + j * stride)
                           : binaryPosition<false>(l.slots, in_.data() + j * stride);
      offset = offsetFromSample(std::move(sample));
    }
    if (start + static_cast<std::uint64_t>(n) * stride > in_.fileSize())
      truncated(e, (in_.fileSize() - start) / stride, in_.fileSize());
    return offset;
  }

  /// The vertices handed to stream_ in chunks of chunk_points_ (readDataset's values: same
  /// offset, columns and numbers; residuals below 1 µm are kept, as every stream does).
  void streamVertices(const Element& e) {
    if (saw_vertex_) throw FileError(path_, "PLY file has two \"vertex\" elements", atLine(e.header_line, "PLY header"));
    saw_vertex_ = true;
    PointCloud named;  // the scalar fields' names; no points
    const VertexLayout l = mapVertexProperties(e, named);
    const std::size_t n = static_cast<std::size_t>(e.count);
    vertex_count_ = n;
    stream_->begin(out_.header, e.count, chunkOf(named, l, 1).fieldNames(), intensityIntegral(e, l));
    const bool fixed = binary() && !e.hasLists();
    const std::uint64_t start = in_.offset();
    Eigen::Vector3d offset = fixed ? fixedVertexOffset(e, n, l) : Eigen::Vector3d::Zero();
    for (std::size_t first = 0; first < n; first += chunk_points_) {
      const std::size_t m = std::min(chunk_points_, n - first);
      std::vector<Column<double>> extras(l.extra_names.size());
      PointCloud chunk = named;
      Columns c = sizeColumns(chunk, m, l, extras);
      c.offset = offset;
      if (fixed) readFixedRecords(start + static_cast<std::uint64_t>(first) * e.recordSize(), m, e.recordSize(), swap(), l.slots, c);
      else readRecords(e, first, m, l.slots, l.double_coords && first == 0, c);
      offset = c.offset;  // chosen in the first chunk (>= kOffsetSampleSize records)
      chunk.offset = offset;
      storeExtras(l.extra_names, extras, chunk);
      stream_->chunk(chunk);
    }
    if (fixed) in_.seek(start + static_cast<std::uint64_t>(n) * e.recordSize());
  }

  /// A cloud of `n` (uninitialised) points with the columns a chunk carries.
  static PointCloud chunkOf(const PointCloud& named, const VertexLayout& l, std::size_t n) {
    PointCloud c = named;
    std::vector<Column<double>> extras(l.extra_names.size());
    sizeColumns(c, n, l, extras);
    storeExtras(l.extra_names, extras, c);
    return c;
  }

  /// Intensity stored as an unsigned type of at most 16 bits: whole numbers within 0..65535.
  static bool intensityIntegral(const Element& e, const VertexLayout& l) {
    if (l.intensity < 0) return false;
    const Type t = e.properties[l.intensity].type;
    return t == Type::UInt8 || t == Type::UInt16;
  }

  void readVertices(const Element& e) {
    if (saw_vertex_) throw FileError(path_, "PLY file has two \"vertex\" elements", atLine(e.header_line, "PLY header"));
    saw_vertex_ = true;
    PointCloud& cloud = out_.vertices;
    const std::size_t n = static_cast<std::size_t>(e.count);
    const VertexLayout l = mapVertexProperties(e, cloud);
    std::vector<Column<double>> extra_values(l.extra_names.size());
    Columns c = sizeColumns(cloud, n, l, extra_values);
    if (binary() && !e.hasLists()) {
      readFixedVertices(e, n, l, c, cloud);
    } else {
      readRecords(e, 0, n, l.slots, l.double_coords, c);
      cloud.offset = c.offset;
    }
    cloud.dropNegligibleResiduals();
    storeExtras(l.extra_names, extra_values, cloud);  // only when the records were read
  }

  /// ASCII or list-carrying vertex records `first` .. first+n-1, one by one, into columns from
  /// index 0. With `double_coords` the first kOffsetSampleSize records are held until the
  /// offset is chosen from them.
  void readRecords(const Element& e, std::size_t first, std::size_t n, const std::vector<Slot>& slots,
                   bool double_coords, Columns& c) {
    std::vector<double> values(slots.size());
    std::vector<std::vector<double>> held;
    auto put = [&](std::size_t i, const std::vector<double>& v) {
      for (std::size_t j = 0; j < slots.size(); ++j) putValue(slots[j], c, i, v[j]);
    };
    auto release = [&] {  // choose the offset from the held records, then store them
      std::vector<Eigen::Vector3d> sample;
      for (const auto& v : held) sample.push_back(valuePosition(slots, v));
      c.offset = offsetFromSample(std::move(sample));
      for (std::size_t i = 0; i < held.size(); ++i) put(i, held[i]);
      held.clear();
    };
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t record = first + i;
      if (!beginRecord()) truncated(e, record);
      for (std::size_t j = 0; j < slots.size(); ++j) {
        const auto& p = e.properties[j];
        if (p.is_list) {
          const std::uint64_t m = listCount(e, record, p);
          for (std::uint64_t q = 0; q < m; ++q) value(e, record, p.type);
        } else {
          values[j] = value(e, record, p.type);
        }
      }
      endRecord(e, record);
      if (double_coords && i < kOffsetSampleSize) {
        held.push_back(values);
        if (held.size() == kOffsetSampleSize) release();
      } else {
        put(i, values);
      }
      if ((i & 0xFFFF) == 0) report();
    }
    if (!held.empty()) release();
  }

  /// Binary vertex records of fixed size: the file is read in 1 MiB windows (never all at once,
  /// so peak memory is the columns plus one window per thread), windows are processed in
  /// parallel, and each window is converted in L2-sized chunks: fields whose file layout equals
  /// the column layout are copied by a RecordCopier (one pass per record for common layouts),
  /// the others converted one column at a time. pread into a reused buffer measured faster than
  /// mapping each window with MAP_POPULATE, and as fast as mapping the whole file once.
  void readFixedRecords(std::uint64_t start, std::size_t n, std::size_t stride, bool sw,
                        const std::vector<Slot>& slots, const Columns& c) {
    std::vector<ply::FieldCopy> copies;
    std::vector<Slot> rest;
    planCopies(slots, c, sw, copies, rest);
    const ply::RecordCopier copier(stride, std::move(copies));
    const std::size_t per_window = std::max<std::size_t>(1, kWindowBytes / stride);
    tbb::enumerable_thread_specific<Column<char>> buffers;  // one window buffer per thread (not zeroed)
    const std::size_t windows = (n + per_window - 1) / per_window;
    std::atomic<std::size_t> done{0};
    const int fd = in_.fd();
    tbb::parallel_for(std::size_t{0}, windows, [&](std::size_t w) {
      checkCanceled(progress_);
      const std::size_t i0 = w * per_window;
      const std::size_t i1 = std::min(n, i0 + per_window);
      const std::uint64_t b = start + static_cast<std::uint64_t>(i0) * stride;
      const char* window = readWindow(fd, b, (i1 - i0) * stride, buffers.local(), path_);
      constexpr std::size_t kChunk = 8192;  // records per column pass (stays in L2)
      for (std::size_t i = i0; i < i1; i += kChunk) {
        const std::size_t m = std::min(kChunk, i1 - i);
        const char* p = window + (i - i0) * stride;
        copier.run(p, m, i);
        if (sw) extractBlock<true>(p, m, stride, rest, c, i);
        else extractBlock<false>(p, m, stride, rest, c, i);
      }
      const std::size_t total = done += i1 - i0;
      if (progress_ && tbb::this_task_arena::current_thread_index() == 0)
        reportProgress(progress_, static_cast<double>(total) / static_cast<double>(n), "reading PLY");
    });
  }

  void readFaces(const Element& e) {
    out_.has_faces = true;
    int list = e.find("vertex_indices");
    if (list < 0) list = e.find("vertex_index");
    if (list < 0 || !e.properties[list].is_list)
      throw FileError(path_, "face element has no list property \"vertex_indices\"",
                      atLine(e.header_line, "PLY header"));
    int id_prop = -1;
    for (const char* nm : kFaceIdNames)
      if (int k = e.find(nm); k >= 0 && !e.properties[k].is_list && id_prop < 0) id_prop = k;
    auto& tris = out_.triangles;
    tris.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(e.count, 1u << 26)));
    std::vector<std::uint32_t> poly;
    std::vector<double> ids;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (!beginRecord()) truncated(e, i);
      double id = 0;
      for (std::size_t j = 0; j < e.properties.size(); ++j) {
        const auto& p = e.properties[j];
        const std::uint64_t m = p.is_list ? listCount(e, i, p) : 1;
        if (static_cast<int>(j) == list) poly.clear();
        for (std::uint64_t q = 0; q < m; ++q) {
          const double v = value(e, i, p.type);
          if (static_cast<int>(j) == list) {
            if (!(v >= 0) || v > 4294967295.0)
              badValue(e, i, "invalid vertex index " + std::to_string(v));
            poly.push_back(static_cast<std::uint32_t>(v));
          } else if (static_cast<int>(j) == id_prop) {
            id = v;
          }
        }
      }
      endRecord(e, i);
      for (std::size_t q = 2; q < poly.size(); ++q) {
        tris.push_back({poly[0], poly[q - 1], poly[q]});
        if (id_prop >= 0) ids.push_back(id);
      }
      if ((i & 0xFFFF) == 0) report();
    }
    // Elements: one per distinct id (in order of first appearance), else one for all.
    if (id_prop >= 0) {
      std::map<double, std::uint32_t> element_of;
      out_.triangle_element.reserve(ids.size());
      for (double id : ids) {
        auto [it, added] = element_of.emplace(id, static_cast<std::uint32_t>(element_of.size()));
        if (added) out_.elements.push_back({"", "element " + std::to_string(saturate<long long>(id)), ""});
        out_.triangle_element.push_back(it->second);
      }
      face_ids_ = std::move(element_of);
    }
  }

  void checkFaceIndices() {
    const std::size_t nv = out_.vertices.size();
    for (std::size_t t = 0; t < out_.triangles.size(); ++t)
      for (std::uint32_t v : out_.triangles[t])
        if (v >= nv)
          throw FileError(path_, "a face refers to vertex " + std::to_string(v) + " but there are only " +
                                     std::to_string(nv) + " vertices",
                          FileLocation{{}, {}, "triangle " + std::to_string(t)});
  }

  /// "comment plumb-element ID TYPE NAME" lines written by writePlyMesh restore element names.
  void readElementComments() {
    for (const auto& cmt : out_.header.comments) {
      std::istringstream in(cmt);
      std::string key, type;
      double id = 0;
      if (!(in >> key >> id >> type) || key != "plumb-element") continue;
      std::string name;
      std::getline(in, name);
      if (!name.empty() && name[0] == ' ') name.erase(0, 1);
      auto it = face_ids_.find(id);
      if (it == face_ids_.end()) continue;
      auto& el = out_.elements[it->second];
      el.type = type == "-" ? "" : type;
      el.name = name;
    }
  }

  /// "comment plumb-grid ROWS COLUMNS" restores the grid size of an organized cloud.
  void readGridComment(std::size_t vertices) {
    auto& v = out_.vertices;
    for (const auto& cmt : out_.header.comments) {
      std::istringstream in(cmt);
      std::string key;
      long long rows = 0, cols = 0;
      if (in >> key >> rows >> cols && key == "plumb-grid" && rows > 0 && cols > 0 &&
          rows <= INT32_MAX && cols <= INT32_MAX && static_cast<std::size_t>(rows * cols) == vertices) {
        v.grid_rows = static_cast<std::int32_t>(rows);
        v.grid_columns = static_cast<std::int32_t>(cols);
      }
    }
  }

  std::filesystem::path path_;
  BlockReader in_;
  Progress* progress_;
  PlyData out_;
  const PlyVertexStream* stream_ = nullptr;  ///< streaming read: vertices go there in chunks
  std::size_t chunk_points_ = 0;
  std::size_t vertex_count_ = 0;
  bool saw_vertex_ = false;
  std::uint64_t line_ = 0;  ///< ASCII: 1-based line of the record being parsed
  std::string line_text_;
  std::size_t cursor_ = 0;
  std::map<double, std::uint32_t> face_ids_;
};

}  // namespace

PlyData readPly(const std::filesystem::path& path, Progress* progress) {
  Reader reader(path, progress);
  PlyData data = reader.run();
  reportProgress(progress, 1.0, "reading PLY");
  return data;
}

std::pair<std::int32_t, std::int32_t> streamPlyVertices(const std::filesystem::path& path, std::size_t chunk_points,
                                                        const PlyVertexStream& stream, Progress* progress) {
  Reader reader(path, progress, &stream, std::max<std::size_t>(chunk_points, kOffsetSampleSize));
  const PlyData data = reader.run();
  return {data.vertices.grid_rows, data.vertices.grid_columns};
}

Dataset plyToDataset(PlyData&& ply, const std::filesystem::path& path) {
  Dataset d = Dataset::fromCloud(std::move(ply.vertices), path.stem().string());
  d.source = path;
  d.format = "ply";
  d.metadata.emplace_back("encoding", ply.header.encoding == Encoding::Ascii ? "ascii"
                                      : ply.header.encoding == Encoding::BinaryLittleEndian
                                          ? "binary_little_endian"
                                          : "binary_big_endian");
  return d;
}

BimModel plyToModel(PlyData&& ply, const std::filesystem::path& path) {
  BimModel m;
  m.source = path;
  m.format = "ply";
  const PointCloud& v = ply.vertices;
  m.mesh.vertices.resize(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) m.mesh.vertices[i] = v.world(i);
  if (v.hasNormals()) m.mesh.vertex_normals.assign(v.normals.begin(), v.normals.end());
  if (v.hasColors()) m.mesh.vertex_colors.assign(v.colors.begin(), v.colors.end());
  m.mesh.triangles = std::move(ply.triangles);
  if (ply.elements.empty()) {
    m.elements.push_back({"", path.stem().string(), ""});
    m.triangle_element.assign(m.mesh.triangles.size(), 0);
  } else {
    m.elements = std::move(ply.elements);
    m.triangle_element = std::move(ply.triangle_element);
  }
  return m;
}

}  // namespace plumb
