// plumb-cli convert IN OUT [--transform T.json] [--split] [--ascii]: between the supported
// formats, chosen by extension. The transform (JSON or 4x4 text, source -> target) is applied in
// world coordinates: scan poses become T * pose (points stay in their scan frames), models are
// transformed directly. --split writes one file per scan: OUT_STEM_<index>_<scan name>.EXT.
// Writes are atomic: on any failure an existing OUT is left untouched. OUT must not be IN
// (also through a symlink, a hard link or another spelling): converting in place is refused.
// The writer's notes (points dropped, intensity rescaled...) are printed after "wrote".
// E57 and LAS inputs written to LAS or PLY are streamed (io/stream/point_convert.hpp): memory
// stays bounded by the chunk size, each scan moved into the output frame as it is written.
// --memory-budget MB (default half the available memory): a file that must be read whole is
// refused when its estimate exceeds the budget, rather than exhausting the machine.
#include <iostream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "cli/written_output.hpp"
#include "common/error.hpp"
#include "io/io.hpp"
#include "io/stream/point_convert.hpp"
#include "io/stream/point_stream.hpp"

namespace plumb::cli {
namespace {

void printConverted(const ConvertResult& r) {
  for (const auto& f : r.files) printWritten(f.path, f.points, f.scans, f.report);
}

}  // namespace

void addConvertCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("convert", "Convert between point cloud / model formats (by extension)");
  struct Args {
    std::string in, out, transform, memory_budget;
    bool split = false, ascii = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("input", a->in, "Input file")->required();
  cmd->add_option("output", a->out, "Output file (format from its extension)")->required();
  cmd->add_option("--transform", a->transform, "Rigid transform file (JSON or 4x4 text) applied in world coordinates");
  cmd->add_flag("--split", a->split, "Write one output file per scan");
  cmd->add_flag("--ascii", a->ascii, "PLY: write ASCII instead of binary");
  cmd->add_option("--memory-budget", a->memory_budget, memoryBudgetHelp());
  cmd->callback([&action, a] {
    action = [a]() {
      ConvertParams params;
      if (!a->transform.empty()) params.transform = readTransformFile(a->transform);
      params.split = a->split;
      params.write.binary = !a->ascii;
      params.memory_budget = memoryBudgetBytes(memoryParamsFromOption(a->memory_budget));
      params.stream = streamOptionsWithin(params.memory_budget);
      const std::filesystem::path out(a->out);
      refuseSameFile(a->in, out);  // split outputs: checked as they are named
      if (streamsInChunks(a->in) && !isModelFormat(formatFromExtension(a->in))) {
        printConverted(convertPointFile(a->in, out, params));
        return 0;
      }
      if (!isModelFormat(formatFromExtension(a->in)))
        checkWholeReadFits(a->in, params.memory_budget, "converting to " + out.filename().string());
      LoadedData data = readFile(a->in);
      if (auto* m = std::get_if<BimModel>(&data)) {
        if (a->split) throw InputError("--split applies to point datasets with several scans, not to models");
        if (!params.transform.isIdentity()) m->transform(params.transform);
        writeModel(out, *m, params.write);
        std::cout << "wrote " << out.string() << " (" << m->mesh.triangleCount() << " triangles)\n";
        return 0;
      }
      auto& d = std::get<Dataset>(data);
      printConverted(convertDataset(d, out, params));
      return 0;
    };
  });
}

}  // namespace plumb::cli
