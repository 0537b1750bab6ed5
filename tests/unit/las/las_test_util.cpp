#include "las_test_util.hpp"

#include "support/test_support.hpp"

namespace plumb::test::las {

std::vector<std::uint8_t> bytesOf(const std::string& shared_relative) {
  const std::string s = readAll(sharedData(shared_relative));
  return std::vector<std::uint8_t>(s.begin(), s.end());
}

}  // namespace plumb::test::las
