// Deterministic damage to duplex.ifc (seeded): single entity lines deleted, truncated or with
// one digit changed, each imported through the plumb-import helper. None may crash or hang the
// test process; each ends in a model or a FileError naming the file. The counts (how often
// assimp crashed) are printed and recorded as test properties.
//
// A libFuzzer target does not fit here: the code under test runs in a child process, whose
// coverage libFuzzer cannot see, and each input costs a process and a ~1 s IFC import.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "io/mesh/mesh_io.hpp"
#include "support/sanitized_build.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

std::vector<std::string> duplexLines() {
  std::ifstream in(test::sharedData("ifc/duplex.ifc"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// One damaged copy: an entity line (starting with '#') deleted, cut short or with a digit changed.
std::string mutate(std::vector<std::string> lines, std::mt19937& rng, std::string& what) {
  std::uniform_int_distribution<std::size_t> pick(0, lines.size() - 1);
  std::size_t i = pick(rng);
  while (lines[i].empty() || lines[i][0] != '#') i = pick(rng);
  std::string& line = lines[i];
  const int kind = std::uniform_int_distribution<int>(0, 2)(rng);
  what = "line " + std::to_string(i + 1) + (kind == 0 ? " deleted" : kind == 1 ? " truncated" : " digit changed");
  if (kind == 0) {
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
  } else if (kind == 1) {
    line.resize(std::uniform_int_distribution<std::size_t>(1, line.size() - 1)(rng));
  } else {
    std::vector<std::size_t> digits;
    for (std::size_t k = 0; k < line.size(); ++k)
      if (std::isdigit(static_cast<unsigned char>(line[k]))) digits.push_back(k);
    const std::size_t k = digits[std::uniform_int_distribution<std::size_t>(0, digits.size() - 1)(rng)];
    line[k] = static_cast<char>('0' + (line[k] - '0' + 1 + static_cast<int>(rng() % 9)) % 10);
  }
  std::ostringstream out;
  for (const auto& l : lines) out << l << '\n';
  return out.str();
}

std::string outcomeOf(const std::string& message) {
  for (const char* key : {"crashed", "overflowed its stack", "time limit", "out of memory", "killed"})
    if (message.find(key) != std::string::npos) return key;
  return "error";
}

}  // namespace

TEST(MeshMutations, DamagedDuplexNeverTakesPlumbDown) {
  const char* env = std::getenv("PLUMB_MUTATIONS");
  const int count = env ? std::atoi(env) : test::repetitions(100, 10);  // assimp under ASan: slow
  const auto lines = duplexLines();
  const auto dir = test::scratchDir("mesh_mutations");
  std::mt19937 rng(20261124);
  std::map<std::string, int> outcomes;
  ImportLimits limits;
  limits.seconds = 60;
  for (int n = 0; n < count; ++n) {
    std::string what;
    const auto path = dir / ("duplex_" + std::to_string(n) + ".ifc");
    test::writeAll(path, mutate(lines, rng, what));
    try {
      const BimModel m = readMesh(path, nullptr, limits);
      EXPECT_FALSE(m.mesh.triangles.empty());
      ++outcomes["model"];
    } catch (const FileError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(path.filename().string()), std::string::npos) << msg;
      ++outcomes[outcomeOf(msg)];
      std::cout << path.filename().string() << " (" << what << "): " << msg.substr(0, 240) << "\n";
    }
  }
  for (const auto& [outcome, k] : outcomes) {
    std::cout << "  " << outcome << ": " << k << " of " << count << "\n";
    RecordProperty(outcome, k);
  }
  EXPECT_EQ(outcomes["time limit"], 0);
}
