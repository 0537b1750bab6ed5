// libFuzzer target for the PCD reader (tests/fuzz/CMakeLists.txt explains the convention).
// By default it fuzzes our header and size checks (checkPcdHeader: everything readPcd decides
// before PCL reads the file); any input must pass them or raise plumb::FileError.
// With PLUMB_FUZZ_PCD_PCL=1 every input goes through readPcd, i.e. also through PCL's
// PCDReader, which is not instrumented (fuzz_pcd.cmake links the installed PCL). A 4-minute
// run of that mode ended, after 103,839 inputs, in an AddressSanitizer CHECK in its
// quarantine (a freed chunk overwritten: a write into freed memory by uninstrumented code)
// that replaying the corpus does not reproduce: kept out of the CTest run until understood.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz_input_file.hpp"
#include "io/pcd/pcd_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool through_pcl = std::getenv("PLUMB_FUZZ_PCD_PCL") != nullptr;
  return plumb::fuzz::readDatasetInput(data, size, ".pcd", [](const auto& path) {
    if (through_pcl) return plumb::readPcd(path);
    plumb::checkPcdHeader(path);
    return plumb::Dataset();
  });
}
