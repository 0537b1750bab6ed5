// libFuzzer target for the model import path (tests/fuzz/CMakeLists.txt explains the
// convention; there is no core/io/model, fuzz_model.cmake names the sources). assimp runs in the
// plumb-import helper, where libFuzzer sees nothing (test_mesh_mutations damages duplex.ifc for
// that half); this target gives each input to the code Plumb itself runs on a model's bytes:
//   1. as an .ifc file's text, readMesh's pre-pass: ifc_georef::plan, lengthUnit and
//      readMapConversion, held to what tests/support/ifc_prepass_checks.hpp says they promise,
//      and danglingReference, the scan behind the report of a crashed import;
//   2. as the helper's output, readMesh's decoding (helper_failure::resultOrThrow with
//      model_stream::decode): a model or a FileError; a decoded model encodes back to the same
//      bytes;
//   3. as an assimp node name, elementFromIfcNodeName (run in the helper, but our code).
// Anything else (another exception, a sanitizer report, a crash, a hang, > 2 GB RSS) is a bug.
// Runs so far: tests/unit/model/regressions/README.md (the fuzz module "model", not core/model).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "common/error.hpp"
#include "fuzz_input_file.hpp"
#include "io/isolation/helper_failure.hpp"
#include "io/mesh/import_failure.hpp"
#include "io/mesh/mesh_io.hpp"
#include "io/mesh/model_stream.hpp"
#include "support/ifc_prepass_checks.hpp"

namespace {

/// 1: the pre-pass keeps its promises (support/ifc_prepass_checks.hpp).
void checkPrepass(std::string_view text) {
  const std::string problem = plumb::test::planProblem(text) + plumb::test::mapConversionProblem(text);
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz_model: %s\n", problem.c_str());
    std::abort();
  }
}

/// 2: the input as what the helper wrote on its output.
void decodeHelperOutput(std::string_view bytes) {
  plumb::import_process::Outcome outcome;
  outcome.exited = true;
  outcome.exit_code = 0;
  outcome.output = std::string(bytes);
  try {
    const plumb::BimModel model = plumb::helper_failure::resultOrThrow(
        "model.ifc", outcome, "the model import helper", plumb::model_stream::decode,
        [] { throw plumb::FileError("model.ifc", "no result"); });
    const std::string again =
        plumb::fuzz::writtenBytes([&](int fd) { return plumb::model_stream::writeModel(fd, model); });
    if (again != bytes) std::abort();
    (void)model.mesh.bounds();
    (void)model.elementTypeCounts();
  } catch (const plumb::FileError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  checkPrepass(bytes);
  (void)plumb::ifc_georef::lengthUnit(bytes);
  plumb::FileLocation where;
  (void)plumb::import_failure::danglingReference(plumb::fuzz::writeInput(data, size, ".ifc"), where);
  if (!bytes.empty()) decodeHelperOutput(bytes);  // an empty output is the no-result case
  (void)plumb::elementFromIfcNodeName(std::string(bytes));
  return 0;
}
