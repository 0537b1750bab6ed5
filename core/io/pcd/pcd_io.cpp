#include "io/pcd/pcd_io.hpp"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace plumb {
namespace {

/// What our own header check learned (PCL's reader only says "failed").
struct PcdHeader {
  std::vector<std::string> fields;
  std::vector<int> sizes, counts;
  std::vector<char> types;
  std::uint64_t width = 0, height = 1, points = 0;
  std::string data;
  std::uint64_t data_offset = 0;  ///< first byte after the DATA line
  std::uint64_t data_line = 0;
  /// Bytes of one binary record (fields were checked: sizes 1..8, counts 1..kMaxRecordBytes).
  std::uint64_t recordSize() const {
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      n += static_cast<std::uint64_t>(sizes[i]) * static_cast<std::uint64_t>(counts[i]);
    return n;
  }
  /// Values of one record (an ASCII record needs at least one character per value).
  std::uint64_t valueCount() const {
    std::uint64_t n = 0;
    for (int c : counts) n += static_cast<std::uint64_t>(c);
    return n;
  }
};

/// Largest record accepted (PCL keeps field offsets and the point step in 32-bit integers).
constexpr std::uint64_t kMaxRecordBytes = std::uint64_t{1} << 20;

/// WIDTH, HEIGHT or POINTS: a whole number in 0 .. 2^32-1 (PCL's range), nothing else on the line.
bool parseDimension(std::istringstream& words, std::uint64_t& out) {
  std::string text, rest;
  if (!(words >> text) || (words >> rest)) return false;
  const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && p == text.data() + text.size() && out <= UINT32_MAX;
}

/// Checks FIELDS/SIZE/TYPE/COUNT/WIDTH/HEIGHT/POINTS once the DATA line is reached.
template <class Fail>
void checkFields(PcdHeader& h, bool have_width, bool have_points, Fail&& fail) {
  if (h.fields.empty()) fail("PCD header has no FIELDS line before DATA");
  if (h.counts.empty()) h.counts.assign(h.fields.size(), 1);
  if (h.sizes.size() != h.fields.size() || h.types.size() != h.fields.size() ||
      h.counts.size() != h.fields.size())
    fail("FIELDS, SIZE, TYPE and COUNT have different numbers of entries (" +
         std::to_string(h.fields.size()) + ", " + std::to_string(h.sizes.size()) + ", " +
         std::to_string(h.types.size()) + ", " + std::to_string(h.counts.size()) + ")");
  for (std::size_t i = 0; i < h.types.size(); ++i) {
    const char t = h.types[i];
    const int s = h.sizes[i];
    if (!((t == 'F' && (s == 4 || s == 8)) || ((t == 'I' || t == 'U') && (s == 1 || s == 2 || s == 4 || s == 8))))
      fail("field '" + h.fields[i] + "' has an invalid TYPE/SIZE " + std::string(1, t) + "/" + std::to_string(s));
    if (h.counts[i] < 1 || static_cast<std::uint64_t>(h.counts[i]) > kMaxRecordBytes)
      fail("field '" + h.fields[i] + "' has COUNT " + std::to_string(h.counts[i]) + " (expected 1 .. " +
           std::to_string(kMaxRecordBytes) + ")");
  }
  if (h.recordSize() > kMaxRecordBytes)
    fail("a point record of " + std::to_string(h.recordSize()) + " bytes is larger than the " +
         std::to_string(kMaxRecordBytes) + " bytes accepted");
  if (!have_width) fail("PCD header has no WIDTH line");
  if (!have_points) h.points = h.width * h.height;
  if (h.width * h.height != h.points)
    fail("WIDTH x HEIGHT (" + std::to_string(h.width) + " x " + std::to_string(h.height) +
         ") differs from POINTS " + std::to_string(h.points));
}

/// PCL's PCDReader goes on reading header lines after DATA while they are empty, comments or
/// start with a header keyword, so a FIELDS, SIZE, COUNT or POINTS line there changes the
/// layout after it sized its buffers: a heap overflow inside PCL (found by fuzz_pcd). Such a
/// line is refused, naming it.
void checkNoHeaderAfterData(std::istream& in, const std::filesystem::path& path, std::uint64_t line_no,
                            std::uint64_t offset) {
  static const char* const kKeywords[] = {"FIELDS", "COLUMNS", "SIZE",   "TYPE", "COUNT",
                                          "WIDTH",  "HEIGHT",  "VIEWPOINT", "POINTS", "DATA"};
  std::string line;
  while (offset < (1u << 20) && std::getline(in, line)) {
    ++line_no;
    const std::uint64_t start = offset;
    offset += line.size() + 1;
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#' || key.starts_with("VERSION")) continue;
    for (const char* k : kKeywords)
      if (key.starts_with(k)) {
        FileLocation loc = atLine(line_no, "data");
        loc.byte_offset = start;
        throw FileError(path, "a " + std::string(k) + " header line after the DATA line", loc);
      }
    return;
  }
}

PcdHeader checkHeader(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  const auto file_size = std::filesystem::file_size(path);
  if (file_size == 0) throw FileError(path, "file is empty (0 bytes)");
  PcdHeader h;
  std::string line;
  std::uint64_t line_no = 0, offset = 0;
  bool have_points = false, have_width = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::uint64_t line_start = offset;
    offset += line.size() + 1;
    const bool crlf = !line.empty() && line.back() == '\r';
    if (crlf) line.pop_back();
    // PCL skips an empty line but not a lone CR, which crashes its PCDReader (fuzz_pcd: a SEGV).
    if (line.empty() && crlf)
      throw FileError(path, "blank header line holding only a carriage return (CR)",
                      FileLocation{line_start, line_no, "PCD header"});
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string key;
    words >> key;
    auto fail = [&](const std::string& what) {
      FileLocation loc = atLine(line_no, "PCD header");
      loc.byte_offset = line_start;
      throw FileError(path, what + ": \"" + line.substr(0, 80) + "\"", loc);
    };
    // PCL splits header lines at spaces, tabs and CRs only, and takes the first character of
    // each TYPE word: other separators or longer TYPE words would make its layout differ from
    // the one checked here (fuzz_pcd: a NULL read inside PCL for "TYPE FF F F").
    // PCD headers are ASCII: a control byte (NUL, CR, VT, FF...) or a non-ASCII byte would also
    // let PCL split the line differently (fuzz_pcd: a SEGV inside PCL for NULs in FIELDS).
    for (unsigned char ch : line)
      if ((ch < 0x20 && ch != '\t') || ch >= 0x7F) fail("control or non-ASCII byte in a header line");
    auto readAll = [&](auto& vec) {
      typename std::decay_t<decltype(vec)>::value_type v;
      while (words >> v) vec.push_back(v);
      if (!words.eof()) fail("malformed " + key + " line");
    };
    if (key == "VERSION") {
    } else if (key == "FIELDS" || key == "COLUMNS") {
      readAll(h.fields);
    } else if (key == "SIZE") {
      readAll(h.sizes);
    } else if (key == "TYPE") {
      std::vector<std::string> types;
      readAll(types);
      for (const auto& t : types) {
        if (t.size() != 1) fail("TYPE '" + t + "' is not one of F, I, U");
        h.types.push_back(t[0]);
      }
    } else if (key == "COUNT") {
      readAll(h.counts);
    } else if (key == "WIDTH") {
      if (!parseDimension(words, h.width)) fail("WIDTH is not a whole number in 0 .. 4294967295");
      have_width = true;
    } else if (key == "HEIGHT") {
      if (!parseDimension(words, h.height)) fail("HEIGHT is not a whole number in 0 .. 4294967295");
    } else if (key == "VIEWPOINT") {
    } else if (key == "POINTS") {
      if (!parseDimension(words, h.points)) fail("POINTS is not a whole number in 0 .. 4294967295");
      have_points = true;
    } else if (key == "DATA") {
      words >> h.data;
      if (h.data != "ascii" && h.data != "binary" && h.data != "binary_compressed")
        fail("unknown DATA type (expected ascii, binary or binary_compressed)");
      h.data_offset = offset;
      h.data_line = line_no + 1;
      checkFields(h, have_width, have_points, fail);
      checkNoHeaderAfterData(in, path, line_no, offset);
      return h;
    } else {
      if (line_no == 1 && line.size() > 0)
        throw FileError(path, "not a PCD file: the first line is not a PCD header keyword", atByte(0));
      fail("unknown PCD header keyword '" + key + "'");
    }
    if (offset > (1u << 20)) break;
  }
  throw FileError(path, "PCD header has no DATA line", atLine(line_no, "PCD header"));
}

/// LZF output is at most 88 times its input (a 3-byte back reference copies up to 264 bytes).
constexpr std::uint64_t kLzfMaxRatio = 88;

[[noreturn]] void truncatedPoints(const std::filesystem::path& path, const PcdHeader& h,
                                  std::uint64_t file_size, std::uint64_t fit) {
  throw FileError(path, "truncated data: expected " + std::to_string(h.points) +
                            " points, file ends at byte " + std::to_string(file_size) +
                            " in point " + std::to_string(fit),
                  FileLocation{file_size, {}, "point " + std::to_string(fit)});
}

/// binary_compressed: the two block sizes must agree with POINTS, the file size and each
/// other before PCL allocates the uncompressed block.
void checkCompressedSizes(const std::filesystem::path& path, const PcdHeader& h, std::uint64_t file_size) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(h.data_offset));
  std::uint32_t sizes[2] = {0, 0};
  if (!in.read(reinterpret_cast<char*>(sizes), sizeof sizes))
    throw FileError(path, "truncated data: the compressed block sizes are missing",
                    atByte(h.data_offset, "binary_compressed header"));
  const FileLocation where = atByte(h.data_offset, "binary_compressed header");
  const std::uint64_t need = h.points * h.recordSize();  // < 2^52: both factors were bounded
  if (sizes[1] != need)
    throw FileError(path, "compressed block declares " + std::to_string(sizes[1]) +
                              " uncompressed bytes, but " + std::to_string(h.points) +
                              " points need " + std::to_string(need), where);
  if (sizes[0] > file_size - std::min(file_size, h.data_offset + 8))
    throw FileError(path, "truncated data: the compressed block has " + std::to_string(sizes[0]) +
                              " bytes, file ends at byte " + std::to_string(file_size),
                    atByte(file_size, "binary_compressed block"));
  if (sizes[1] > std::uint64_t{sizes[0]} * kLzfMaxRatio)
    throw FileError(path, "compressed block of " + std::to_string(sizes[0]) + " bytes cannot hold " +
                              std::to_string(sizes[1]) + " uncompressed bytes (LZF expands at most " +
                              std::to_string(kLzfMaxRatio) + " times)", where);
}

/// Checks that the data section can hold POINTS records before PCL sizes anything from it.
void checkDataSize(const std::filesystem::path& path, const PcdHeader& h) {
  const std::uint64_t file_size = std::filesystem::file_size(path);
  const std::uint64_t left = file_size - std::min(file_size, h.data_offset);
  if (h.data == "binary") {
    const std::uint64_t rec = h.recordSize();
    if (h.points > left / rec) truncatedPoints(path, h, file_size, left / rec);
  } else if (h.data == "ascii") {
    // Every value takes a character and a separator (the last one of the file may lack it).
    const std::uint64_t record = 2 * h.valueCount();
    if (h.points > (left + 1) / record) truncatedPoints(path, h, file_size, (left + 1) / record);
  } else if (h.data == "binary_compressed") {
    checkCompressedSizes(path, h, file_size);
  }
}

float getFloat(const std::uint8_t* p, std::uint8_t datatype) {
  switch (datatype) {
    case pcl::PCLPointField::INT8: return static_cast<float>(*reinterpret_cast<const std::int8_t*>(p));
    case pcl::PCLPointField::UINT8: return static_cast<float>(*p);
    case pcl::PCLPointField::INT16: { std::int16_t v; std::memcpy(&v, p, 2); return v; }
    case pcl::PCLPointField::UINT16: { std::uint16_t v; std::memcpy(&v, p, 2); return v; }
    case pcl::PCLPointField::INT32: { std::int32_t v; std::memcpy(&v, p, 4); return static_cast<float>(v); }
    case pcl::PCLPointField::UINT32: { std::uint32_t v; std::memcpy(&v, p, 4); return static_cast<float>(v); }
    case pcl::PCLPointField::FLOAT32: { float v; std::memcpy(&v, p, 4); return v; }
    case pcl::PCLPointField::FLOAT64: { double v; std::memcpy(&v, p, 8); return static_cast<float>(v); }
    default: break;
  }
  return std::numeric_limits<float>::quiet_NaN();
}

double getDouble(const std::uint8_t* p, std::uint8_t datatype) {
  if (datatype == pcl::PCLPointField::FLOAT64) {
    double v;
    std::memcpy(&v, p, 8);
    return v;
  }
  return getFloat(p, datatype);
}

/// RAII: silence PCL's console output while reading (we report errors ourselves).
struct QuietPcl {
  pcl::console::VERBOSITY_LEVEL old = pcl::console::getVerbosityLevel();
  QuietPcl() { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }
  ~QuietPcl() { pcl::console::setVerbosityLevel(old); }
};

}  // namespace

void checkPcdHeader(const std::filesystem::path& path) { checkDataSize(path, checkHeader(path)); }

Dataset readPcd(const std::filesystem::path& path, Progress* progress) {
  const PcdHeader header = checkHeader(path);
  checkDataSize(path, header);
  reportProgress(progress, 0.05, "reading PCD");
  pcl::PCLPointCloud2 pc;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0;
  {
    QuietPcl quiet;
    pcl::PCDReader reader;
    int rc = -1;
    try {
      rc = reader.read(path.string(), pc, origin, orientation, version);
    } catch (const std::exception& e) {
      throw FileError(path, std::string("PCL could not read the data: ") + e.what(),
                      atByte(header.data_offset, "data"));
    }
    if (rc != 0)
      throw FileError(path, "PCL could not read the " + header.data + " data (corrupt or truncated)",
                      atLine(header.data_line, "data"));
  }
  checkCanceled(progress);
  reportProgress(progress, 0.7, "converting PCD");

  const std::size_t n = static_cast<std::size_t>(pc.width) * pc.height;
  auto field = [&](const char* name) -> const pcl::PCLPointField* {
    for (const auto& f : pc.fields)
      if (f.name == name) return &f;
    return nullptr;
  };
  const auto *fx = field("x"), *fy = field("y"), *fz = field("z");
  if (!fx || !fy || !fz) throw FileError(path, "PCD file has no x, y and z fields", atLine(1, "PCD header"));
  const auto *fnx = field("normal_x"), *fny = field("normal_y"), *fnz = field("normal_z");
  const auto* frgb = field("rgb") ? field("rgb") : field("rgba");
  const auto* fint = field("intensity");
  Dataset d;
  d.source = path;
  d.format = "pcd";
  Scan scan;
  scan.name = path.stem().string();
  PointCloud& c = scan.cloud;
  const std::uint8_t* data = pc.data.data();
  const std::size_t step = pc.point_step;
  if (pc.data.size() < n * step) throw FileError(path, "PCL returned fewer bytes than the header declares");
  // Double coordinates: offset from the first finite points (offsetFromSample) and exact
  // locals through residuals; float coordinates are stored as they are.
  const bool dbl = fx->datatype == pcl::PCLPointField::FLOAT64;
  auto position = [&](std::size_t i) {
    const std::uint8_t* p = data + i * step;
    return Eigen::Vector3d(getDouble(p + fx->offset, fx->datatype), getDouble(p + fy->offset, fy->datatype),
                           getDouble(p + fz->offset, fz->datatype));
  };
  c.positions.resize(n);
  if (dbl) {
    std::vector<Eigen::Vector3d> sample;
    for (std::size_t i = 0; i < n && sample.size() < kOffsetSampleSize; ++i)
      if (const Eigen::Vector3d w = position(i); w.allFinite()) sample.push_back(w);
    c.offset = offsetFromSample(std::move(sample));
    c.position_residuals.resize(n);
    for (std::size_t i = 0; i < n; ++i) c.setLocal(i, position(i) - c.offset);
    c.dropNegligibleResiduals();
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t* p = data + i * step;
      c.positions[i] = {getFloat(p + fx->offset, fx->datatype), getFloat(p + fy->offset, fy->datatype),
                        getFloat(p + fz->offset, fz->datatype)};
    }
  }
  if (fnx && fny && fnz) {
    c.normals.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint8_t* p = data + i * step;
      c.normals[i] = {getFloat(p + fnx->offset, fnx->datatype), getFloat(p + fny->offset, fny->datatype),
                      getFloat(p + fnz->offset, fnz->datatype)};
    }
  }
  if (frgb && frgb->count == 1 && (frgb->datatype == pcl::PCLPointField::FLOAT32 || frgb->datatype == pcl::PCLPointField::UINT32)) {
    c.colors.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      std::uint32_t v;
      std::memcpy(&v, data + i * step + frgb->offset, 4);  // packed 0x00RRGGBB (PCL convention)
      c.colors[i] = {static_cast<std::uint8_t>(v >> 16), static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)};
    }
  }
  if (fint && fint->count == 1) {
    c.intensity.resize(n);
    for (std::size_t i = 0; i < n; ++i) c.intensity[i] = getFloat(data + i * step + fint->offset, fint->datatype);
  }
  std::string skipped;
  for (const auto& f : pc.fields) {
    static const char* const known[] = {"x", "y", "z", "normal_x", "normal_y", "normal_z", "rgb", "rgba", "intensity", "_"};
    bool is_known = false;
    for (const char* k : known) is_known |= f.name == k;
    if (is_known && !(f.name == "intensity" && f.count != 1)) continue;
    if (f.count != 1) {
      skipped += (skipped.empty() ? "" : " ") + f.name;
      continue;
    }
    ScalarField sf{f.name, Column<float>(n)};  // every value set below
    for (std::size_t i = 0; i < n; ++i) sf.values[i] = getFloat(data + i * step + f.offset, f.datatype);
    c.scalar_fields.push_back(std::move(sf));
  }
  if (pc.height > 1) {  // organized: keep every grid cell, NaN included
    c.grid_rows = static_cast<std::int32_t>(pc.height);
    c.grid_columns = static_cast<std::int32_t>(pc.width);
    c.row.resize(n);
    c.column.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      c.row[i] = static_cast<std::int32_t>(i / pc.width);
      c.column[i] = static_cast<std::int32_t>(i % pc.width);
    }
  } else {
    c.removeNonFinite();
  }
  d.metadata.emplace_back("PCD data", header.data);
  d.metadata.emplace_back("PCD size", std::to_string(pc.width) + " x " + std::to_string(pc.height) +
                                          (pc.height > 1 ? " (organized)" : " (unorganized)"));
  std::ostringstream vp;
  vp << origin.x() << " " << origin.y() << " " << origin.z() << " " << orientation.w() << " "
     << orientation.x() << " " << orientation.y() << " " << orientation.z();
  d.metadata.emplace_back("viewpoint", vp.str());
  if (!skipped.empty()) d.metadata.emplace_back("skipped multi-valued fields", skipped);
  d.scans.push_back(std::move(scan));
  reportProgress(progress, 1.0, "reading PCD");
  return d;
}

void writePcd(const std::filesystem::path& path, const PointCloud& cloud,
              const PcdWriteOptions& options, Progress* progress) {
  cloud.validate(true);
  const std::size_t n = cloud.size();
  pcl::PCLPointCloud2 pc;
  const bool organized = cloud.grid_rows > 0 && cloud.grid_columns > 0 &&
                         static_cast<std::size_t>(cloud.grid_rows) * cloud.grid_columns == n;
  pc.width = organized ? static_cast<std::uint32_t>(cloud.grid_columns) : static_cast<std::uint32_t>(n);
  pc.height = organized ? static_cast<std::uint32_t>(cloud.grid_rows) : 1;
  pc.is_dense = false;
  std::uint32_t offset = 0;
  auto add = [&](const std::string& name, std::uint8_t type, std::uint32_t size) {
    pcl::PCLPointField f;
    f.name = name;
    f.offset = offset;
    f.datatype = type;
    f.count = 1;
    pc.fields.push_back(f);
    offset += size;
    return f.offset;
  };
  // Double x y z when float32 would move any point by more than 0.1 mm (georeferenced data).
  const bool dbl = !cloud.worldFitsFloat(kCoordinatePrecision);
  const bool exact_floats = cloud.offset.isZero() && !cloud.hasPositionResiduals();
  const std::uint8_t pt = dbl ? pcl::PCLPointField::FLOAT64 : pcl::PCLPointField::FLOAT32;
  const std::uint32_t ps = dbl ? 8 : 4;
  const std::uint32_t ox = add("x", pt, ps), oy = add("y", pt, ps), oz = add("z", pt, ps);
  std::uint32_t on = 0, orgb = 0, oi = 0;
  if (cloud.hasNormals()) {
    on = add("normal_x", pcl::PCLPointField::FLOAT32, 4);
    add("normal_y", pcl::PCLPointField::FLOAT32, 4);
    add("normal_z", pcl::PCLPointField::FLOAT32, 4);
  }
  if (cloud.hasColors()) orgb = add("rgb", pcl::PCLPointField::FLOAT32, 4);
  if (cloud.hasIntensity()) oi = add("intensity", pcl::PCLPointField::FLOAT32, 4);
  std::vector<std::pair<const ScalarField*, std::uint32_t>> scalars;
  for (const auto& f : cloud.scalar_fields)
    if (f.values.size() == n && f.name.find_first_of(" \t\n") == std::string::npos)
      scalars.emplace_back(&f, add(f.name, pcl::PCLPointField::FLOAT32, 4));
  pc.point_step = offset;
  pc.row_step = pc.point_step * pc.width;
  pc.data.resize(static_cast<std::size_t>(pc.point_step) * n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t* p = pc.data.data() + i * pc.point_step;
    if (dbl) {
      const Eigen::Vector3d w = cloud.world(i);
      std::memcpy(p + ox, &w.x(), 8);
      std::memcpy(p + oy, &w.y(), 8);
      std::memcpy(p + oz, &w.z(), 8);
    } else {
      const Eigen::Vector3f f = exact_floats ? cloud.positions[i] : cloud.world(i).cast<float>();
      std::memcpy(p + ox, &f.x(), 4);
      std::memcpy(p + oy, &f.y(), 4);
      std::memcpy(p + oz, &f.z(), 4);
    }
    if (cloud.hasNormals()) std::memcpy(p + on, cloud.normals[i].data(), 12);
    if (cloud.hasColors()) {
      const auto& c = cloud.colors[i];
      const std::uint32_t v = (std::uint32_t{c[0]} << 16) | (std::uint32_t{c[1]} << 8) | c[2];
      std::memcpy(p + orgb, &v, 4);
    }
    if (cloud.hasIntensity()) std::memcpy(p + oi, &cloud.intensity[i], 4);
    for (const auto& [f, o] : scalars) std::memcpy(p + o, &f->values[i], 4);
  }
  checkCanceled(progress);
  reportProgress(progress, 0.5, "writing PCD");
  AtomicFileWriter writer(path);
  pcl::PCDWriter w;
  if (options.compressed) {
    if (w.writeBinaryCompressed(writer.stream(), pc) != 0)
      throw FileError(path, "PCL could not write the compressed PCD data");
  } else {
    writer.stream() << w.generateHeaderBinary(pc, Eigen::Vector4f::Zero(), Eigen::Quaternionf::Identity())
                    << "DATA binary\n";
    writer.stream().write(reinterpret_cast<const char*>(pc.data.data()), static_cast<std::streamsize>(pc.data.size()));
  }
  writer.commit();
  reportProgress(progress, 1.0, "writing PCD");
}

}  // namespace plumb
