// libFuzzer target for the LAS reader (tests/fuzz/CMakeLists.txt explains the convention).
// Any input must either read or raise plumb::FileError; anything else (another exception, a
// sanitizer report, a crash, a hang, > 2 GB RSS) is a bug.
#include <cstddef>
#include <cstdint>
#include <span>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  plumb::LasReadOptions options;
  options.auxiliary_fields = size % 2 == 0;  // cover both decoder paths
  try {
    const plumb::Dataset d = plumb::readLasBuffer(std::span(data, size), "fuzz.las", options);
    const plumb::PointCloud& c = d.scans.at(0).cloud;
    c.validate(true);  // every attribute has one value per point
    (void)d.bounds();
  } catch (const plumb::FileError&) {
  }
  return 0;
}
