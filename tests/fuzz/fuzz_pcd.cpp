// libFuzzer target for the PCD reader (tests/fuzz/CMakeLists.txt explains the convention):
// every input goes through readPcd - our header and size checks, then PCL's PCDReader (not
// instrumented: fuzz_pcd.cmake links the installed PCL; its heap corruption shows up later as
// an ASan report on our side) and the conversion. Any input must either read or raise
// plumb::FileError. PLUMB_FUZZ_PCD_HEADER_ONLY=1 fuzzes only our checks (checkPcdHeader).
// Runs so far: tests/unit/pcd/regressions/README.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input_file.hpp"
#include "io/pcd/pcd_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool header_only = std::getenv("PLUMB_FUZZ_PCD_HEADER_ONLY") != nullptr;
  return plumb::fuzz::readDatasetInput(data, size, ".pcd", [](const auto& path) {
    if (!header_only) return plumb::readPcd(path);
    plumb::checkPcdHeader(path);
    return plumb::Dataset();
  });
}
