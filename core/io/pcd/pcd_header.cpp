#include "io/pcd/pcd_header.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "common/error.hpp"
#include "io/pcd/pcd_io.hpp"

namespace plumb {
namespace {

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

/// PCL splits header lines at spaces, tabs and CRs only, and takes the first character of
/// each TYPE word: other separators or longer TYPE words would make its layout differ from
/// the one checked here (fuzz_pcd: a NULL read inside PCL for "TYPE FF F F").
/// PCD headers are ASCII: a control byte (NUL, CR, VT, FF...) or a non-ASCII byte would also
/// let PCL split the line differently (fuzz_pcd: a SEGV inside PCL for NULs in FIELDS).
template <class Fail>
void checkHeaderLineBytes(const std::string& line, Fail&& fail) {
  for (unsigned char ch : line)
    if ((ch < 0x20 && ch != '\t') || ch >= 0x7F) fail("control or non-ASCII byte in a header line");
}

/// Seen so far in the header: the layout, and whether WIDTH and POINTS were given.
struct HeaderState {
  PcdHeader h;
  bool have_points = false, have_width = false;
};

/// The values of a layout or size keyword line (every keyword but DATA) into `st`; false for
/// a word that is not a PCD header keyword.
template <class Fail>
bool parseKeywordLine(const std::string& key, std::istringstream& words, HeaderState& st, Fail&& fail) {
  PcdHeader& h = st.h;
  // A repeated keyword replaces the earlier line's values, as in PCL's reader (appending
  // them made this check's record layout differ from the one PCL reads with; fuzz_pcd).
  auto readAll = [&](auto& vec) {
    vec.clear();
    typename std::decay_t<decltype(vec)>::value_type v;
    while (words >> v) vec.push_back(v);
    if (!words.eof()) fail("malformed " + key + " line");
  };
  if (key == "VERSION") {
  } else if (key == "VIEWPOINT") {
    // As PCL: with 7 words or more, three floats, then four more through the same variables
    // (a word that does not parse gives 0, and the values after it keep the earlier ones).
    const std::string rest = words.eof() ? std::string() : words.str().substr(static_cast<std::size_t>(words.tellg()));
    std::istringstream count_words(rest), values(rest);
    std::size_t n = 0;
    for (std::string w; count_words >> w;) ++n;
    if (n >= 7) {
      float x = 0, y = 0, z = 0, w = 0;
      values >> x >> y >> z;
      h.viewpoint[0] = x, h.viewpoint[1] = y, h.viewpoint[2] = z;
      values >> w >> x >> y >> z;
      h.viewpoint[3] = w, h.viewpoint[4] = x, h.viewpoint[5] = y, h.viewpoint[6] = z;
    }
  } else if (key == "FIELDS" || key == "COLUMNS") {
    readAll(h.fields);
  } else if (key == "SIZE") {
    readAll(h.sizes);
  } else if (key == "TYPE") {
    std::vector<std::string> types;
    readAll(types);
    h.types.clear();
    for (const auto& t : types) {
      if (t.size() != 1) fail("TYPE '" + t + "' is not one of F, I, U");
      h.types.push_back(t[0]);
    }
  } else if (key == "COUNT") {
    readAll(h.counts);
  } else if (key == "WIDTH") {
    if (!parseDimension(words, h.width)) fail("WIDTH is not a whole number in 0 .. 4294967295");
    st.have_width = true;
  } else if (key == "HEIGHT") {
    if (!parseDimension(words, h.height)) fail("HEIGHT is not a whole number in 0 .. 4294967295");
  } else if (key == "POINTS") {
    if (!parseDimension(words, h.points)) fail("POINTS is not a whole number in 0 .. 4294967295");
    st.have_points = true;
  } else {
    return false;
  }
  return true;
}

PcdHeader checkHeader(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  const auto file_size = std::filesystem::file_size(path);
  if (file_size == 0) throw FileError(path, "file is empty (0 bytes)");
  HeaderState st;
  std::string line;
  std::uint64_t line_no = 0, offset = 0;
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
    checkHeaderLineBytes(line, fail);
    if (key == "DATA") {
      PcdHeader& h = st.h;
      words >> h.data;
      if (h.data != "ascii" && h.data != "binary" && h.data != "binary_compressed")
        fail("unknown DATA type (expected ascii, binary or binary_compressed)");
      h.data_offset = offset;
      h.data_line = line_no + 1;
      checkFields(h, st.have_width, st.have_points, fail);
      checkNoHeaderAfterData(in, path, line_no, offset);
      return h;
    }
    if (!parseKeywordLine(key, words, st, fail)) {
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

}  // namespace

std::uint64_t PcdHeader::recordSize() const {
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i)
    n += static_cast<std::uint64_t>(sizes[i]) * static_cast<std::uint64_t>(counts[i]);
  return n;
}

std::uint64_t PcdHeader::valueCount() const {
  std::uint64_t n = 0;
  for (int c : counts) n += static_cast<std::uint64_t>(c);
  return n;
}

PcdHeader checkPcdFile(const std::filesystem::path& path) {
  PcdHeader header = checkHeader(path);
  checkDataSize(path, header);
  return header;
}

void checkPcdHeader(const std::filesystem::path& path) { checkPcdFile(path); }

}  // namespace plumb
