// libFuzzer target for the PLY reader (tests/fuzz/CMakeLists.txt explains the convention).
// Any input must either read or raise plumb::FileError; anything else (another exception, a
// sanitizer report, a crash, a hang, > 2 GB RSS) is a bug. Inputs go through a file
// (fuzz_input_file.hpp): the reader streams from a path.
#include <cstddef>
#include <cstdint>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "io/ply/ply_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = plumb::fuzz::writeInput(data, size, ".ply");
  try {
    plumb::PlyData d = plumb::readPly(path);
    d.vertices.validate(true);  // every attribute has one value per point
    (void)d.vertices.bounds();
    if (d.has_faces) (void)plumb::plyToModel(std::move(d), path);
  } catch (const plumb::FileError&) {
  }
  return 0;
}
