// Inputs stored under tests/unit/las/regressions/: crashes found by fuzz_las (tests/fuzz)
// and edge cases worth keeping. The name says the expected outcome: "*.error.las" must raise
// a FileError (with a byte offset), "*.ok.las" must read with every attribute sized to the
// point count. regressions/README.md lists where each file came from.
#include <gtest/gtest.h>

#include <string>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"
#include "support/test_support.hpp"

#ifndef PLUMB_LAS_REGRESSIONS_DIR
#error "PLUMB_LAS_REGRESSIONS_DIR must be defined"
#endif

namespace plumb {
namespace {

TEST(LasRegressions, EachStoredInputBehavesAsItsNameSays) {
  std::size_t checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(PLUMB_LAS_REGRESSIONS_DIR)) {
    const std::string name = entry.path().filename().string();
    const bool want_error = name.ends_with(".error.las");
    const bool want_ok = name.ends_with(".ok.las");
    if (!want_error && !want_ok) continue;
    const std::string bytes = test::readAll(entry.path());
    const std::span<const std::uint8_t> span(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                             bytes.size());
    for (bool auxiliary : {false, true}) {  // both decoder paths, like the fuzzer
      LasReadOptions o;
      o.auxiliary_fields = auxiliary;
      try {
        const Dataset d = readLasBuffer(span, name, o);
        EXPECT_TRUE(want_ok) << name << " read but should fail";
        ASSERT_EQ(d.scans.size(), 1u);
        EXPECT_NO_THROW(d.scans[0].cloud.validate(true)) << name;
      } catch (const FileError& e) {
        EXPECT_TRUE(want_error) << name << ": " << e.what();
        EXPECT_TRUE(e.where().byte_offset.has_value()) << e.what();
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 1u);
}

}  // namespace
}  // namespace plumb
