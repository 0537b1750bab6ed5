// main() of Plumb's GoogleTest executables (in place of gtest_main): before each case runs,
// test::scratchDir learns the case's name, so parallel CTest processes of one executable
// never share (and wipe) a scratch folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "support/test_support.hpp"

namespace {

class ScratchPerCase : public testing::EmptyTestEventListener {
  void OnTestStart(const testing::TestInfo& info) override {
    std::string name = std::string(info.test_suite_name()) + "." + info.name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised: Prefix/Suite.Case/0
    plumb::test::setScratchCase(name);
  }
  void OnTestEnd(const testing::TestInfo&) override { plumb::test::setScratchCase(""); }
};

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  testing::UnitTest::GetInstance()->listeners().Append(new ScratchPerCase);
  return RUN_ALL_TESTS();
}
