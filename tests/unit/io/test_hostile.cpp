// Hostile inputs (issue 12): each file of hostile_files.cpp crashed, hung or exhausted memory
// on main. Read through the dispatcher, each must now raise a FileError naming the file, what
// is wrong and where, at once.
#include <gtest/gtest.h>

#include <chrono>

#include "common/error.hpp"
#include "hostile_files.hpp"
#include "io/io.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

class Hostile : public ::testing::TestWithParam<test::HostileFile> {};

TEST_P(Hostile, IsRejectedWithFileProblemAndPlace) {
  const test::HostileFile& h = GetParam();
  const auto path = test::scratchDir("hostile_" + h.name) / h.name;
  test::writeAll(path, h.bytes);
  const auto start = std::chrono::steady_clock::now();
  try {
    readFile(path);
    ADD_FAILURE() << h.name << " was read (on main: " << h.on_main << ")";
  } catch (const FileError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(h.name), std::string::npos) << what;
    EXPECT_NE(what.find(h.problem), std::string::npos) << what;
    if (!h.element.empty()) {
      EXPECT_EQ(e.where().element, h.element) << what;
    }
    if (h.line) {
      EXPECT_EQ(e.where().line, h.line) << what;
    }
    if (h.offset >= 0) {
      EXPECT_EQ(e.where().byte_offset, static_cast<std::uint64_t>(h.offset)) << what;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 2.0) << h.name;  // the 4 MB zero E57 section was walked for seconds
}

INSTANTIATE_TEST_SUITE_P(Issue12, Hostile, ::testing::ValuesIn(test::hostileFiles()),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (auto& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace plumb
