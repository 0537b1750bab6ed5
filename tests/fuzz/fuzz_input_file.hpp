#pragma once
// The PLY, PCD and text readers read from a path (PCL's PCDReader only takes a file name), so
// their fuzz targets write each input to one file of this process under /dev/shm (or
// $TMPDIR) and read that: a few microseconds per input. The helper streams' targets encode
// through a memfd (writtenBytes).
#include <sys/mman.h>
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

/// What `write(fd)` (a helper stream's writer; it must return true) wrote, through a memfd of
/// this process: a pipe would fill up on a large model or cloud.
template <class Write>
std::string writtenBytes(Write&& write) {
  static const int fd = memfd_create("plumb_fuzz_stream", 0);  // one per writer: a few at most
  if (fd < 0 || ftruncate(fd, 0) != 0 || lseek(fd, 0, SEEK_SET) != 0) std::abort();
  if (!write(fd)) std::abort();
  std::string bytes(static_cast<std::size_t>(lseek(fd, 0, SEEK_CUR)), '\0');
  if (pread(fd, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size())) std::abort();
  return bytes;
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
