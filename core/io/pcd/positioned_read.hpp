#pragma once
// Reading a byte range of an open file at a given offset (pread), for the PCD chunk reader
// (pcd_records.cpp) and its LZF decoder (lzf_stream.cpp).
#include <cstdint>
#include <filesystem>

namespace plumb {

/// Reads exactly `n` bytes at `offset` of `fd` into `out`, retrying interrupted and short reads.
/// Throws FileError naming `path`, the offset and `element` on a read error or end of file.
void readFileAt(int fd, const std::filesystem::path& path, std::uint64_t offset, std::uint8_t* out,
                std::uint64_t n, const char* element);

}  // namespace plumb
