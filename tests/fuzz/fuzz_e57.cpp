// libFuzzer target for the E57 reader (tests/fuzz/CMakeLists.txt explains the convention).
// Any input must either read or raise plumb::FileError; anything else (another exception, a
// sanitizer report, a crash, a hang, > 2 GB RSS) is a bug.
// Random mutations almost always break a page CRC, which the reader rejects first; so for
// half of the inputs the page CRCs are recomputed before reading, letting the fuzzer reach
// the header, XML, section, packet and bit-pack code behind the checksums.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/error.hpp"
#include "io/e57/crc32c.hpp"
#include "io/e57/e57_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> bytes(data, data + size);
  if (size % 2 == 0) {
    for (std::size_t page = 0; page + 1024 <= size; page += 1024) {
      const std::uint32_t crc = plumb::e57::crc32c(bytes.data() + page, 1020);
      bytes[page + 1020] = static_cast<std::uint8_t>(crc >> 24);
      bytes[page + 1021] = static_cast<std::uint8_t>(crc >> 16);
      bytes[page + 1022] = static_cast<std::uint8_t>(crc >> 8);
      bytes[page + 1023] = static_cast<std::uint8_t>(crc);
    }
  }
  plumb::E57ReadOptions options;
  options.keep_direction_only = (size / 2) % 2 == 0;  // cover both invalid-state paths
  try {
    const plumb::Dataset d = plumb::readE57FromMemory(bytes.data(), bytes.size(), "fuzz.e57", options);
    for (const auto& s : d.scans) s.cloud.validate(true);  // one value per point everywhere
    (void)d.bounds();
  } catch (const plumb::FileError&) {
  }
  return 0;
}
