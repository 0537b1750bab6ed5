#include "hostile_files.hpp"

#include <cstring>

#include "io/e57/crc32c.hpp"
#include "io/e57/e57_pages.hpp"

namespace plumb::test {
namespace {

template <class T>
void put(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof v);
}
template <class T>
std::string bytesOf(T v) {
  std::string s(sizeof v, '\0');
  put(s, 0, v);
  return s;
}

const char* const kPlyXyz = "property float x\nproperty float y\nproperty float z\n";

std::vector<HostileFile> plyFiles() {
  const std::string bin = "ply\nformat binary_little_endian 1.0\n";
  const std::string vertex(12, '\0');
  std::vector<HostileFile> f;
  f.push_back({"no_properties.ply", bin + "element vertex 1\n" + kPlyXyz + "element junk 3\nend_header\n" + vertex,
               "element 'junk' declares 3 records but has no properties", "PLY header", 7, -1,
               "SIGFPE: records of 0 bytes divide the bytes left"});
  HostileFile count{"vertex_count.ply", bin + "element vertex 1000000000\n" + kPlyXyz + "end_header\n" + vertex,
                    "truncated data: expected 1000000000 vertices", "vertex 1", 0, -1,
                    "12 GB of columns sized before the count was checked against the file"};
  count.offset = static_cast<std::int64_t>(count.bytes.size());
  f.push_back(count);
  HostileFile ascii{"ascii_count.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\n" + std::string(kPlyXyz) +
                                           "end_header\n1 2 3\n",
                    "truncated data: expected 1000000000000 vertices", "vertex 1", 0, -1,
                    "std::bad_alloc without the file name"};
  ascii.offset = static_cast<std::int64_t>(ascii.bytes.size());
  f.push_back(ascii);
  return f;
}

std::vector<HostileFile> pcdFiles() {
  const std::string xyz = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  std::vector<HostileFile> f;
  f.push_back({"count_overflow.pcd",
               "VERSION 0.7\nFIELDS x y z h\nSIZE 4 4 4 8\nTYPE F F F F\nCOUNT 1 1 1 536870912\nWIDTH 1\nHEIGHT 1\n"
               "POINTS 1\nDATA binary\n" + std::string(12, '\0'),
               "field 'h' has COUNT 536870912", "PCD header", 9, -1,
               "SIZE x COUNT overflowed an int to 0: the size check passed and PCL crashed"});
  HostileFile ascii{"ascii_points.pcd", xyz + "WIDTH 100000000\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 100000000\n"
                                              "DATA ascii\n1 2 3\n",
                    "truncated data: expected 100000000 points", "point 1", 0, -1,
                    "PCL allocated 1.2 GB for a 154-byte file"};
  ascii.offset = static_cast<std::int64_t>(ascii.bytes.size());
  f.push_back(ascii);
  // PCL reads header lines after DATA: this FIELDS line widened its records after it had sized
  // the buffer for 3-value records (fuzz_pcd: heap corruption inside PCL).
  f.push_back({"header_after_data.pcd", xyz + "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\nFIELDS a b c d e f g h i j k\n"
                                           "1 2 3 4 5 6 7 8 9 10 11\n1 2 3 4 5 6 7 8 9 10 11\n",
               "a FIELDS header line after the DATA line", "data", 10, -1,
               "PCL wrote 11-value records into a buffer sized for 3 (heap overflow)"});
  // 357913941 points x 12 bytes = 4294967292 bytes declared for a 16-byte LZF block.
  const std::string head = xyz + "WIDTH 357913941\nHEIGHT 1\nPOINTS 357913941\nDATA binary_compressed\n";
  f.push_back({"compressed_lie.pcd", head + bytesOf<std::uint32_t>(16) + bytesOf<std::uint32_t>(4294967292u) +
                                         std::string(16, '\0'),
               "cannot hold 4294967292 uncompressed bytes", "binary_compressed header", 0,
               static_cast<std::int64_t>(head.size()), "PCL allocated 4 GB for the uncompressed block"});
  return f;
}

std::vector<HostileFile> textFiles() {
  std::string line;
  for (int i = 0; i < 5000000; ++i) line += "1 ";
  std::string wide;
  for (int i = 0; i < 300; ++i) wide += "1 ";
  return {{"long_line.xyz", line + "\n", "line of 10000000 bytes is longer than the 65536 bytes accepted", "", 1,
           -1, "5 million columns, 1.3 GB"},
          {"many_columns.xyz", wide + "\n" + wide + "\n", "line has 300 values, more than the 256 columns accepted",
           "", 1, -1, "read as 297 scalar fields"}};
}

/// XML of one scan whose prototype has x y z and `fields` more Integer fields, all with
/// minimum = maximum (0 bits per record).
std::string zeroBitXml(std::uint64_t records, int fields) {
  std::string proto;
  for (const char* axis : {"cartesianX", "cartesianY", "cartesianZ"})
    proto += std::string("<") + axis + " type=\"ScaledInteger\" minimum=\"7\" maximum=\"7\" scale=\"0.001\"/>";
  for (int i = 0; i < fields; ++i) proto += "<f" + std::to_string(i) + " type=\"Integer\" minimum=\"3\" maximum=\"3\"/>";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<e57Root type=\"Structure\" "
         "xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\"><data3D type=\"Vector\"><s type=\"Structure\">"
         "<points type=\"CompressedVector\" fileOffset=\"48\" recordCount=\"" + std::to_string(records) +
         "\"><prototype type=\"Structure\">" + proto + "</prototype></points></s></data3D></e57Root>\n";
}

/// XML of one scan of float x y z (96 bits per record) in the section at 48.
std::string floatXml(std::uint64_t records) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<e57Root type=\"Structure\" "
         "xmlns=\"http://www.astm.org/COMMIT/E57/2010-e57-v1.0\"><data3D type=\"Vector\"><s type=\"Structure\">"
         "<points type=\"CompressedVector\" fileOffset=\"48\" recordCount=\"" + std::to_string(records) +
         "\"><prototype type=\"Structure\"><cartesianX type=\"Float\" precision=\"single\"/><cartesianY type=\"Float\" "
         "precision=\"single\"/><cartesianZ type=\"Float\" precision=\"single\"/></prototype></points></s></data3D>"
         "</e57Root>\n";
}

/// A CompressedVector section of `length` logical bytes: its 32-byte header, then zeros.
std::string zeroSection(std::uint64_t length) {
  std::string s(length, '\0');
  s[0] = 1;
  put<std::uint64_t>(s, 8, length);
  put<std::uint64_t>(s, 16, 48 + 32);  // first data packet right after the header (page 0)
  return s;
}

std::vector<HostileFile> e57Files() {
  // 1.599 million records of 323 fields stored in 0 bits: the section holds no bytes for them
  // (main allowed a record per bit of the section: 1,599,744).
  return {{"zero_bit_fields.e57", e57File(zeroSection(200000), zeroBitXml(1599000, 320)), "recordCount 1599000",
           "/e57Root/data3D/0/points", 0, -1, "2 GB of columns for a 216 KB file"},
          {"zero_section.e57", e57File(zeroSection(4 << 20), floatXml(1000)), "invalid index packet length 1",
           "/e57Root/data3D/0/points", 0, 80, "walked 4 MB as 1-byte packets (17 s here; 100 MB: 86 s) before failing"}};
}

}  // namespace

std::string e57File(const std::string& section, const std::string& xml) {
  std::string logical(48, '\0');
  logical += section;
  const std::uint64_t xml_logical = logical.size();
  logical += xml;
  const std::uint64_t pages = (logical.size() + e57::kPagePayload - 1) / e57::kPagePayload;
  logical.resize(pages * e57::kPagePayload, '\0');
  std::memcpy(logical.data(), "ASTM-E57", 8);
  put<std::uint32_t>(logical, 8, 1);
  put<std::uint64_t>(logical, 16, pages * e57::kPageSize);
  put<std::uint64_t>(logical, 24, e57::logicalToPhysical(xml_logical));
  put<std::uint64_t>(logical, 32, xml.size());
  put<std::uint64_t>(logical, 40, e57::kPageSize);
  std::string file;
  for (std::uint64_t p = 0; p < pages; ++p) {
    const char* payload = logical.data() + p * e57::kPagePayload;
    file.append(payload, e57::kPagePayload);
    const std::uint32_t crc = e57::crc32c(payload, e57::kPagePayload);
    for (int shift = 24; shift >= 0; shift -= 8) file.push_back(static_cast<char>(crc >> shift));
  }
  return file;
}

std::vector<HostileFile> hostileFiles() {
  std::vector<HostileFile> all;
  for (auto&& group : {plyFiles(), pcdFiles(), textFiles(), e57Files()})
    all.insert(all.end(), group.begin(), group.end());
  return all;
}

}  // namespace plumb::test
