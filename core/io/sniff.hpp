#pragma once
// Content sniffing: what a file's first bytes look like, independent of its extension.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/io.hpp"

namespace plumb {

struct Sniffed {
  FileFormat format = FileFormat::Unknown;
  bool strong = false;     ///< a magic number / unambiguous signature (not a guess)
  std::string description; ///< "a PLY file", "a ZIP archive", "binary data", "text with numbers" ...
};

/// Classifies the first bytes of a file (pass at least 512 bytes when available, plus the
/// total file size for binary STL's size check).
Sniffed sniffContent(std::string_view head, std::uint64_t file_size);
/// Reads the head of a file and classifies it. Throws FileError if it cannot be opened.
Sniffed sniffFile(const std::filesystem::path& path);

}  // namespace plumb
