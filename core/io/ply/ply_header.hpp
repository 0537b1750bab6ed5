#pragma once
// PLY header model and parser (http://paulbourke.net/dataformats/ply/). The header is plain
// text ending with "end_header"; every problem is reported with its header line.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace plumb::ply {

enum class Encoding { Ascii, BinaryLittleEndian, BinaryBigEndian };
enum class Type : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::size_t typeSize(Type t);
std::string_view typeName(Type t);  ///< "char", "uchar", ..., "double"

struct Property {
  std::string name;
  Type type = Type::Float32;  ///< value type (list items for lists)
  bool is_list = false;
  Type count_type = Type::UInt8;  ///< lists only
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::uint64_t header_line = 0;  ///< 1-based line of "element ..." in the header
  bool hasLists() const;
  /// Bytes of one binary record (only meaningful when !hasLists()).
  std::size_t recordSize() const;
  int find(std::string_view property) const;  ///< index or -1
};

struct Header {
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  std::vector<std::string> comments;  ///< "comment" and "obj_info" lines, without keyword
  std::size_t data_offset = 0;        ///< first byte after "end_header\n"
  std::uint64_t data_line = 0;        ///< 1-based line where ASCII data starts
  const Element* find(std::string_view name) const;
};

/// Parses the header from the first bytes of a file. Throws FileError (naming `file` and the
/// header line) when the magic, format, an element or a property line is malformed, or when
/// "end_header" is not found within `size` bytes.
Header parseHeader(const char* data, std::size_t size, const std::filesystem::path& file);

/// Checks the element counts against the `data_bytes` that follow the header, before anything
/// is sized from a count: a binary record takes at least its fixed-size properties (a list at
/// least its count), an ASCII value at least one character and a separator. Throws FileError
/// naming the element's header line when an element cannot fit, or when an element with
/// records has no properties.
void checkElementSizes(const Header& h, std::uint64_t data_bytes, const std::filesystem::path& file);

}  // namespace plumb::ply
