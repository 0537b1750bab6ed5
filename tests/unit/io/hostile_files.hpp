#pragma once
// Hostile inputs of issue 12 (each one crashed, hung or exhausted memory on main): small
// files whose headers declare far more than the file holds. Generated, so the bytes and the
// reason for each are documented here. Used by test_hostile (the FileError each must give)
// and test_hostile_memory (the peak memory of reading each in a fresh process).
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace plumb::test {

struct HostileFile {
  std::string name;     ///< file name; its extension selects the reader
  std::string bytes;
  std::string problem;  ///< a phrase the FileError message must contain
  std::string element;  ///< FileLocation::element it must give ("" = not checked)
  std::uint64_t line = 0;    ///< FileLocation::line it must give (0 = not checked)
  std::int64_t offset = -1;  ///< FileLocation::byte_offset it must give (-1 = not checked)
  std::string on_main;  ///< what reading it did on main (documentation)
};

/// gtest prints a parameter by its file name.
inline void PrintTo(const HostileFile& h, std::ostream* os) { *os << h.name; }

/// Every hostile file, one per problem of the issue.
std::vector<HostileFile> hostileFiles();

/// An E57 file: the 48-byte header, `section` (logical bytes placed at logical offset 48) and
/// the XML, paged with their CRCs.
std::string e57File(const std::string& section, const std::string& xml);

}  // namespace plumb::test
