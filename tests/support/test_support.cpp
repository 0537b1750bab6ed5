#include "support/test_support.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#ifndef PLUMB_SHARED_DATA_DIR
#error "PLUMB_SHARED_DATA_DIR must be defined"
#endif
#ifndef PLUMB_TEST_SCRATCH_DIR
#error "PLUMB_TEST_SCRATCH_DIR must be defined"
#endif

namespace plumb::test {

std::filesystem::path sharedData(const std::string& relative) {
  auto p = std::filesystem::path(PLUMB_SHARED_DATA_DIR) / relative;
  if (!std::filesystem::exists(p)) throw std::runtime_error("missing test data: " + p.string());
  return p;
}

namespace {
std::string& scratchCase() {
  static std::string current;
  return current;
}
}  // namespace

void setScratchCase(const std::string& test_case) { scratchCase() = test_case; }

std::filesystem::path scratchDir(const std::string& name) {
  auto p = std::filesystem::path(PLUMB_TEST_SCRATCH_DIR) / name;
  if (!scratchCase().empty()) p /= scratchCase();
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void writeAll(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace plumb::test
