// Inputs stored under tests/unit/{ply,pcd,text}/regressions/: crashes found by fuzz_ply,
// fuzz_pcd and fuzz_text (tests/fuzz). The name says the expected outcome: "*.error.<ext>"
// must raise a FileError, "*.ok.<ext>" must read with every attribute sized to the point
// count. The undefined behaviour some of them hit (a NaN converted to an integer) is caught
// when this test runs under UBSan (the sanitize label).
// Each folder's README.md lists where each file came from. fuzz_model's inputs (IFC text
// for readMesh's pre-pass) are under tests/unit/model/regressions/.
#include <gtest/gtest.h>

#include <string>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/mesh/ifc_map_conversion.hpp"
#include "support/ifc_prepass_checks.hpp"
#include "support/test_support.hpp"

#ifndef PLUMB_IO_REGRESSIONS_DIR
#error "PLUMB_IO_REGRESSIONS_DIR must be defined"
#endif

namespace plumb {
namespace {

/// A file of the regressions: read, check, and tell whether it read.
bool readsAndValidates(const std::filesystem::path& path) {
  try {
    const LoadedData data = readFile(path);
    if (const auto* d = std::get_if<Dataset>(&data))
      for (const auto& s : d->scans) s.cloud.validate(true);
    return true;
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find(path.filename().string()), std::string::npos) << e.what();
    return false;
  }
}

TEST(IoFuzzRegressions, EachStoredInputBehavesAsItsNameSays) {
  std::size_t checked = 0;
  for (const char* module : {"ply", "pcd", "text"}) {
    const std::filesystem::path dir = std::filesystem::path(PLUMB_IO_REGRESSIONS_DIR) / module / "regressions";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      const bool want_ok = name.find(".ok.") != std::string::npos;
      if (!want_ok && name.find(".error.") == std::string::npos) continue;
      EXPECT_EQ(readsAndValidates(entry.path()), want_ok) << name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 1u);
}

/// "*.ok.ifc": the pre-pass accepts the file and keeps its promises; "*.error.ifc": it refuses
/// the map conversion (InputError), and readFile refuses the file naming it, before the helper.
TEST(IoFuzzRegressions, ModelInputsBehaveAsTheirNamesSay) {
  const std::filesystem::path dir = std::filesystem::path(PLUMB_IO_REGRESSIONS_DIR) / "model" / "regressions";
  std::size_t checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".ifc") continue;
    const std::string text = test::readAll(entry.path());
    EXPECT_EQ(test::planProblem(text), "") << name;
    EXPECT_EQ(test::mapConversionProblem(text), "") << name;
    if (name.find(".ok.") != std::string::npos) {
      EXPECT_NO_THROW(ifc_georef::readMapConversion(text)) << name;
    } else {
      EXPECT_THROW(ifc_georef::readMapConversion(text), InputError) << name;
      EXPECT_FALSE(readsAndValidates(entry.path())) << name;
    }
    ++checked;
  }
  EXPECT_GE(checked, 3u);
}

}  // namespace
}  // namespace plumb
