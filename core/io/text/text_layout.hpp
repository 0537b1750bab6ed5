#pragma once
// The steps of readText (text_reader.cpp) that decide a text file's layout before any point
// is read: the header (a CSV header line or a "// x y z" / "# x y z" comment), the delimiter,
// the column count, a sample of data rows and the role of each column. Internal to io/text;
// declared here so the unit tests can check each step alone. The rules are in text_io.hpp.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace plumb::text {

/// Role of a column. X, Y and Z come first: `role <= Col::Z` means a coordinate.
enum class Col { X, Y, Z, R, G, B, I, NX, NY, NZ, Scalar };

/// ',' ';' or ' ' (whitespace runs) for a line.
char detectDelimiter(std::string_view line);

/// Role of a header name (case-insensitive, quotes and a leading "//" ignored).
Col columnFromName(std::string name);

/// The column names of a comment line ("# x y z ..." or "// x,y,z,...") when it names three
/// coordinate columns and at most the accepted number of columns; nullopt for any other comment.
std::optional<std::vector<std::string>> commentHeaderNames(std::string_view comment);

/// Column roles guessed from the column count and a sample of rows (see text_io.hpp).
std::vector<Col> guessColumns(std::size_t ncols, const std::vector<std::vector<double>>& sample);

/// Column roles named by a header of `names`, checked against the `ncols` values of the data
/// lines (the first at `data_line`): exactly one x, y and z; colour and normal triples only
/// when complete, one intensity; every other column a scalar field. Throws FileError.
std::vector<Col> rolesFromHeader(const std::vector<std::string>& names, std::size_t ncols,
                                 std::uint64_t data_line, const std::filesystem::path& path);

/// What the first pass over the file found.
struct TextLayout {
  std::vector<std::string> names;  ///< header names; empty when the file has no header
  char delim = 0;                  ///< of the first data line
  std::size_t ncols = 0;           ///< values on the first data line
  std::size_t data_pos = std::string::npos;  ///< byte offset of the first data line
  std::uint64_t data_line = 0;               ///< its 1-based line number
  std::vector<std::vector<double>> sample;   ///< up to 1000 rows of ncols numbers
};

/// First pass over the whole text of `path`: header, delimiter, column count and the sampled
/// rows. Throws FileError when no data line holds at least x y z.
TextLayout scanLayout(const std::string& text, const std::filesystem::path& path);

}  // namespace plumb::text
