// The model import runs assimp in the plumb-import helper: files that crash assimp, overflow
// its stack or run past the time limit end in a FileError naming the file; Plumb survives. An
// IFC that assimp refuses goes to IFC++; when both refuse, the error gives both reasons.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/mesh/mesh_io.hpp"
#include "support/damaged_models.hpp"
#include "support/scoped_env.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

/// The FileError readMesh throws for `path` (fails the test if it returns a model).
std::string importError(const std::filesystem::path& path, const ImportLimits& limits = {}) {
  try {
    const BimModel m = readMesh(path, nullptr, limits);
    ADD_FAILURE() << path << " imported (" << m.mesh.triangleCount() << " triangles), expected an error";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), path);
    return e.what();
  }
  return {};
}

}  // namespace

TEST(MeshIsolation, DuplexWithoutOneProfileIsAClearErrorNotACrash) {
  // assimp 5.2 dereferences the missing IfcRectangleProfileDef and dies with SIGSEGV.
  const auto path = test::duplexWithout(test::scratchDir("mesh_isolation_8961"), "#8961=", "duplex_no_8961.ifc");
  const std::string msg = importError(path);
  EXPECT_NE(msg.find("duplex_no_8961.ifc"), std::string::npos) << msg;
  EXPECT_NE(msg.find("assimp crashed (SIGSEGV"), std::string::npos) << msg;
  EXPECT_NE(msg.find("refers to #8961, which the file does not define"), std::string::npos) << msg;
  EXPECT_NE(msg.find("glTF/OBJ"), std::string::npos) << msg;
  // The same through the dispatcher the CLI and the GUI use.
  EXPECT_THROW(readFile(path), FileError);
}

TEST(MeshIsolation, DeeplyNestedGltfIsAClearError) {
  const auto path = test::deepGltf(test::scratchDir("mesh_isolation_gltf"), 20000);
  const std::string msg = importError(path);
  EXPECT_NE(msg.find("deep.gltf"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nests too deeply"), std::string::npos) << msg;
}

TEST(MeshIsolation, DeeplyNestedDaeIsAClearError) {
  const auto path = test::deepDae(test::scratchDir("mesh_isolation_dae"), 100000);
  const std::string msg = importError(path);
  EXPECT_NE(msg.find("deep.dae"), std::string::npos) << msg;
  EXPECT_NE(msg.find("nests too deeply"), std::string::npos) << msg;
}

TEST(MeshIsolation, HugeObjPolygonStopsAtTheTimeLimit) {
  const auto path = test::hugePolygonObj(test::scratchDir("mesh_isolation_obj"), 100000);
  ImportLimits limits;
  limits.seconds = 5;
  const auto start = std::chrono::steady_clock::now();
  const std::string msg = importError(path, limits);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(took, 5.0);
  EXPECT_LT(took, 10.0);
  EXPECT_NE(msg.find("huge_polygon.obj"), std::string::npos) << msg;
  EXPECT_NE(msg.find("time limit of 5 s"), std::string::npos) << msg;
  EXPECT_NE(msg.find("PLUMB_IMPORT_TIMEOUT"), std::string::npos) << msg;
}

// Not built into the AddressSanitizer tree: there the helper sets no address-space limit (ASan
// reserves terabytes of shadow memory), so the test would have nothing to check.
#if !defined(__SANITIZE_ADDRESS__)
TEST(MeshIsolation, MemoryLimitIsAClearError) {
  // The helper reads the duplex in ~54 MB (peak RSS); 32 MiB of address space is not enough.
  ImportLimits limits;
  limits.memory_mib = 32;
  const std::string msg = importError(test::sharedData("ifc/duplex.ifc"), limits);
  EXPECT_NE(msg.find("ran out of memory under the limit of 32 MiB"), std::string::npos) << msg;
}
#endif

TEST(MeshIsolation, ParsedIfcErrorsKeepEntityAndLine) {
  // The error assimp reports (not a crash) still names the entity and its line.
  const auto path = test::sharedData("ifc/AC20-FZK-Haus.ifc");
  try {
    readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::assimp);
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("entity #20909 (IfcSpace)"), std::string::npos) << e.what();
    EXPECT_EQ(e.where().line.value_or(0), 11879u);
    EXPECT_EQ(e.file(), path);
  }
}

TEST(MeshIsolation, IfcBothParsersRefuseGivesBothReasons) {
  // assimp 5.2 wants an owner history on IfcBuilding #50; IFC++ cannot parse the arcs of the
  // IfcIndexedPolyCurve profile #308, the only geometry (tests/data/ifc/README.md).
  const auto path = std::filesystem::path(PLUMB_SOURCE_DIR) / "tests/data/ifc/slab-standard-case.ifc";
  try {
    readMesh(path);
    FAIL() << "neither parser is expected to read " << path;
  } catch (const FileError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("entity #50 (IfcRoot)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("IFC++ cannot read it either"), std::string::npos) << msg;
    EXPECT_NE(msg.find("IfcIndexedPolyCurve"), std::string::npos) << msg;
    EXPECT_EQ(e.where().line.value_or(0), 31u);  // assimp's entity keeps its line (grep -n '^#50=')
  }
}

TEST(MeshIsolation, IfcppCrashIsWordedForIfcpp) {
  // The helper's fault hook makes the IFC++ run die as a crashing parser would.
  const auto path = std::filesystem::path(PLUMB_SOURCE_DIR) / "tests/data/ifc/wall-standard-case.ifc";
  std::string msg;
  try {
    test::ScopedEnv fault("PLUMB_IMPORT_HELPER_FAULT", "segv");
    readMesh(path, nullptr, ImportLimits::fromEnvironment(), ModelParser::ifcpp);
  } catch (const FileError& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("IFC++ crashed (SIGSEGV"), std::string::npos) << msg;
}

TEST(MeshIsolation, CancelStopsTheHelper) {
  const auto path = test::hugePolygonObj(test::scratchDir("mesh_isolation_cancel"), 100000);
  Progress progress;
  progress.cancel();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(readMesh(path, &progress), Canceled);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
}
