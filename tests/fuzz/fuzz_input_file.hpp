#pragma once
// The PLY, PCD and text readers read from a path (PCL's PCDReader only takes a file name), so
// their fuzz targets write each input to one file of this process under /dev/shm (or
// $TMPDIR) and read that: a few microseconds per input.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/error.hpp"
#include "model/dataset.hpp"

namespace plumb::fuzz {

/// Writes data to this process' input file with extension `ext` and returns its path.
inline std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, const char* ext) {
  static const std::filesystem::path path = [ext] {
    const char* tmp = std::getenv("TMPDIR");
    const std::filesystem::path dir = std::filesystem::is_directory("/dev/shm") ? "/dev/shm" : tmp ? tmp : "/tmp";
    return dir / ("plumb_fuzz_" + std::to_string(::getpid()) + ext);
  }();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                                 static_cast<std::streamsize>(size));
  return path;
}

/// The body of a target whose reader returns a Dataset: `read(path)` must give scans with one
/// value per point in every attribute, or raise FileError.
template <class Read>
int readDatasetInput(const std::uint8_t* data, std::size_t size, const char* ext, Read&& read) {
  const auto path = writeInput(data, size, ext);
  try {
    const Dataset d = read(path);
    for (const auto& s : d.scans) s.cloud.validate(true);
    (void)d.bounds();
  } catch (const FileError&) {
  }
  return 0;
}

}  // namespace plumb::fuzz
