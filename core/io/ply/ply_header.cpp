#include "io/ply/ply_header.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

#include "common/error.hpp"

namespace plumb::ply {
namespace {

bool parseType(std::string_view s, Type& t) {
  struct Name {
    std::string_view a, b;
    Type t;
  };
  static const Name names[] = {
      {"char", "int8", Type::Int8},       {"uchar", "uint8", Type::UInt8},
      {"short", "int16", Type::Int16},    {"ushort", "uint16", Type::UInt16},
      {"int", "int32", Type::Int32},      {"uint", "uint32", Type::UInt32},
      {"float", "float32", Type::Float32}, {"double", "float64", Type::Float64}};
  for (const auto& n : names)
    if (s == n.a || s == n.b) {
      t = n.t;
      return true;
    }
  return false;
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) words.push_back(line.substr(i, j - i));
    i = j;
  }
  return words;
}

/// Fewest bytes one record of `e` takes in the data section: binary, its fixed-size values (a
/// list at least its count); ASCII, one character per value (a realistic minimum, a character
/// and a separator per value, is used only to say where the data would end).
std::uint64_t minRecordBytes(const Element& e, Encoding encoding, std::uint64_t ascii_value_bytes) {
  std::uint64_t n = 0;
  for (const auto& p : e.properties)
    n += encoding == Encoding::Ascii ? ascii_value_bytes : typeSize(p.is_list ? p.count_type : p.type);
  return n;
}

[[noreturn]] void tooManyRecords(const Element& e, std::uint64_t fit, std::uint64_t file_size,
                                 const std::filesystem::path& file) {
  const std::string plural = e.name == "vertex" ? "vertices" : e.name + "s";
  const std::string where = e.name + " " + std::to_string(fit);
  throw FileError(file, "truncated data: expected " + std::to_string(e.count) + " " + plural +
                            ", file ends at byte " +
                            std::to_string(file_size) + " in " + where,
                  atByte(file_size, where));
}

}  // namespace

std::size_t typeSize(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8: return 1;
    case Type::Int16:
    case Type::UInt16: return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 0;
}

std::string_view typeName(Type t) {
  switch (t) {
    case Type::Int8: return "char";
    case Type::UInt8: return "uchar";
    case Type::Int16: return "short";
    case Type::UInt16: return "ushort";
    case Type::Int32: return "int";
    case Type::UInt32: return "uint";
    case Type::Float32: return "float";
    case Type::Float64: return "double";
  }
  return "?";
}

bool Element::hasLists() const {
  for (const auto& p : properties)
    if (p.is_list) return true;
  return false;
}

std::size_t Element::recordSize() const {
  std::size_t n = 0;
  for (const auto& p : properties) n += typeSize(p.type);
  return n;
}

int Element::find(std::string_view property) const {
  for (std::size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return static_cast<int>(i);
  return -1;
}

const Element* Header::find(std::string_view name) const {
  for (const auto& e : elements)
    if (e.name == name) return &e;
  return nullptr;
}

Header parseHeader(const char* data, std::size_t size, const std::filesystem::path& file) {
  const std::string_view text(data, size);
  if (size < 4 || text.substr(0, 3) != "ply" || (text[3] != '\n' && text[3] != '\r'))
    throw FileError(file, "not a PLY file: it does not start with the line \"ply\"", atByte(0));
  Header h;
  bool have_format = false;
  std::size_t pos = 0;
  std::uint64_t line_no = 0;
  while (true) {
    const std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos)
      throw FileError(file, "PLY header has no \"end_header\" line",
                      atByte(pos, "header line " + std::to_string(line_no + 1)));
    ++line_no;
    std::string_view line = text.substr(pos, eol - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    const std::size_t line_start = pos;
    pos = eol + 1;
    if (line_no == 1) continue;  // "ply"
    const auto words = splitWords(line);
    if (words.empty()) continue;
    auto fail = [&](const std::string& what) {
      FileLocation loc = atLine(line_no, "PLY header");
      loc.byte_offset = line_start;
      throw FileError(file, what + ": \"" + std::string(line) + "\"", loc);
    };
    const std::string_view kw = words[0];
    if (kw == "end_header") {
      if (!have_format) fail("PLY header has no \"format\" line");
      h.data_offset = pos;
      h.data_line = line_no + 1;
      return h;
    } else if (kw == "format") {
      if (words.size() != 3) fail("malformed format line");
      if (words[1] == "ascii") h.encoding = Encoding::Ascii;
      else if (words[1] == "binary_little_endian") h.encoding = Encoding::BinaryLittleEndian;
      else if (words[1] == "binary_big_endian") h.encoding = Encoding::BinaryBigEndian;
      else fail("unknown PLY format (expected ascii, binary_little_endian or binary_big_endian)");
      if (words[2] != "1.0") fail("unsupported PLY version (only 1.0 exists)");
      have_format = true;
    } else if (kw == "comment" || kw == "obj_info") {
      std::string_view rest = line.substr(std::min(line.size(), kw.size() + 1));
      h.comments.emplace_back(rest);
    } else if (kw == "element") {
      if (words.size() != 3) fail("malformed element line (expected: element NAME COUNT)");
      Element e;
      e.name = std::string(words[1]);
      auto [p, ec] = std::from_chars(words[2].data(), words[2].data() + words[2].size(), e.count);
      if (ec != std::errc() || p != words[2].data() + words[2].size())
        fail("element count is not a non-negative integer");
      e.header_line = line_no;
      h.elements.push_back(std::move(e));
    } else if (kw == "property") {
      if (h.elements.empty()) fail("property line before any element line");
      Property prop;
      if (words.size() >= 2 && words[1] == "list") {
        if (words.size() != 5) fail("malformed list property (expected: property list COUNTTYPE TYPE NAME)");
        if (!parseType(words[2], prop.count_type)) fail("unknown list count type");
        if (prop.count_type == Type::Float32 || prop.count_type == Type::Float64)
          fail("list count type must be an integer type");
        if (!parseType(words[3], prop.type)) fail("unknown property type");
        prop.is_list = true;
        prop.name = std::string(words[4]);
      } else {
        if (words.size() != 3) fail("malformed property line (expected: property TYPE NAME)");
        if (!parseType(words[1], prop.type)) fail("unknown property type");
        prop.name = std::string(words[2]);
      }
      if (h.elements.back().find(prop.name) >= 0) fail("duplicate property name");
      h.elements.back().properties.push_back(std::move(prop));
    } else {
      fail("unknown PLY header keyword '" + std::string(kw) + "'");
    }
  }
}

void checkElementSizes(const Header& h, std::uint64_t data_bytes, const std::filesystem::path& file) {
  const bool ascii = h.encoding == Encoding::Ascii;
  std::uint64_t left = data_bytes;
  for (const Element& e : h.elements) {
    if (e.count == 0) continue;
    if (e.properties.empty())
      throw FileError(file, "element '" + e.name + "' declares " + std::to_string(e.count) +
                                " records but has no properties",
                      atLine(e.header_line, "PLY header"));
    const std::uint64_t record = minRecordBytes(e, h.encoding, 1);
    const std::uint64_t room = ascii ? left + 1 : left;  // the last ASCII value needs no separator
    if (e.count > room / record)
      tooManyRecords(e, room / (ascii ? minRecordBytes(e, h.encoding, 2) : record),
                     h.data_offset + data_bytes, file);
    left -= std::min(left, e.count * record);
  }
}

}  // namespace plumb::ply
