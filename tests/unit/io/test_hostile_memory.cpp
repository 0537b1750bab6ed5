// Peak memory of reading each hostile file (hostile_files.cpp) in a fresh process
// (hostile_peak, getrusage ru_maxrss before and after): at most 64 MB each. On main the same
// files took 1.2 GB to 12 GB or died in std::bad_alloc. Prints one line per file.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <sstream>

#include "hostile_files.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

constexpr long kLimitKb = 64 * 1024;

/// Runs hostile_peak on `path`: its "peak_kb N" and the outcome line.
std::pair<long, std::string> peakOf(const std::filesystem::path& path) {
  const std::string cmd = std::string("'") + PLUMB_HOSTILE_PEAK + "' '" + path.string() + "' 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return {-1, "popen failed"};
  std::string out;
  char buf[4096];
  while (const std::size_t n = fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  const int status = pclose(p);
  std::istringstream in(out);
  std::string key, outcome;
  long kb = -1;
  in >> key >> kb;
  std::getline(in >> std::ws, outcome);
  if (status != 0 || key != "peak_kb") return {-1, "hostile_peak failed: " + out};
  return {kb, outcome};
}

// Not built into the AddressSanitizer tree, where resident memory measures the sanitizer's
// shadow pages, not the reader.
#if !defined(__SANITIZE_ADDRESS__)
TEST(HostileMemory, EachFileReadsInAtMost64MB) {
  const auto dir = test::scratchDir("hostile_memory");
  for (const auto& h : test::hostileFiles()) {
    test::writeAll(dir / h.name, h.bytes);
    const auto [kb, outcome] = peakOf(dir / h.name);
    std::cout << "hostile memory: " << h.name << " (" << h.bytes.size() << " bytes): peak +" << kb / 1024.0
              << " MB; on main: " << h.on_main << "\n";
    EXPECT_GE(kb, 0) << h.name << ": " << outcome;
    EXPECT_LE(kb, kLimitKb) << h.name << ": " << outcome;
    EXPECT_EQ(outcome.rfind("error ", 0), 0u) << h.name << ": " << outcome;
  }
}
#endif

}  // namespace
}  // namespace plumb
