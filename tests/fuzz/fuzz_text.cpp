// libFuzzer target for the text (xyz/csv/pts) reader (tests/fuzz/CMakeLists.txt explains the
// convention). Any input must either read or raise plumb::FileError; anything else (another
// exception, a sanitizer report, a crash, a hang, > 2 GB RSS) is a bug.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "io/text/text_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return plumb::fuzz::readDatasetInput(data, size, ".xyz", [](const auto& path) { return plumb::readText(path); });
}
