#pragma once
// Helpers shared by the LAS tests: reading a shared file into bytes, patching header fields,
// and the expected facts of each file in shared/data/las.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace plumb::test::las {

std::vector<std::uint8_t> bytesOf(const std::string& shared_relative);

template <class T>
void poke(std::vector<std::uint8_t>& b, std::size_t at, T v) {
  std::memcpy(b.data() + at, &v, sizeof v);
}
template <class T>
T peek(const std::vector<std::uint8_t>& b, std::size_t at) {
  T v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

}  // namespace plumb::test::las
