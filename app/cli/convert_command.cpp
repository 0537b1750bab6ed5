// plumb-cli convert IN OUT [--transform T.json] [--split] [--ascii]: between the supported
// formats, chosen by extension. The transform (JSON or 4x4 text, source -> target) is applied in
// world coordinates: scan poses become T * pose (points stay in their scan frames), models are
// transformed directly. --split writes one file per scan: OUT_STEM_<index>_<scan name>.EXT.
// Writes are atomic: on any failure an existing OUT is left untouched. OUT must not be IN
// (also through a symlink, a hard link or another spelling): converting in place is refused.
// The writer's notes (points dropped, intensity rescaled...) are printed after "wrote".
#include <iostream>

#include "cli/command.hpp"
#include "cli/written_output.hpp"
#include "common/error.hpp"
#include "io/io.hpp"

namespace plumb::cli {
namespace {

std::string safeName(std::string s) {
  for (auto& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return s;
}

void refuseSameFile(const std::filesystem::path& in, const std::filesystem::path& out) {
  std::error_code ec;
  if (std::filesystem::equivalent(in, out, ec))
    throw FileError(out, "is the input file itself; converting in place would rewrite it with "
                         "whatever the output format cannot hold: write to another file");
}

void applyTransform(Dataset& d, const RigidTransform& t) {
  for (auto& s : d.scans) {
    s.pose = t * s.pose;
    s.has_pose = s.has_pose || !t.isIdentity();
  }
}

}  // namespace

void addConvertCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("convert", "Convert between point cloud / model formats (by extension)");
  struct Args {
    std::string in, out, transform;
    bool split = false, ascii = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("input", a->in, "Input file")->required();
  cmd->add_option("output", a->out, "Output file (format from its extension)")->required();
  cmd->add_option("--transform", a->transform, "Rigid transform file (JSON or 4x4 text) applied in world coordinates");
  cmd->add_flag("--split", a->split, "Write one output file per scan");
  cmd->add_flag("--ascii", a->ascii, "PLY: write ASCII instead of binary");
  cmd->callback([&action, a] {
    action = [a]() {
      RigidTransform t;
      if (!a->transform.empty()) t = readTransformFile(a->transform);
      WriteOptions wo;
      wo.binary = !a->ascii;
      const std::filesystem::path out(a->out);
      refuseSameFile(a->in, out);
      LoadedData data = readFile(a->in);
      if (auto* m = std::get_if<BimModel>(&data)) {
        if (a->split) throw InputError("--split applies to point datasets with several scans, not to models");
        if (!t.isIdentity()) m->transform(t);
        writeModel(out, *m, wo);
        std::cout << "wrote " << out.string() << " (" << m->mesh.triangleCount() << " triangles)\n";
        return 0;
      }
      auto& d = std::get<Dataset>(data);
      applyTransform(d, t);
      if (!a->split) {
        WriteReport report;
        wo.report = &report;
        writeDataset(out, d, wo);
        printWritten(out, d, report);
        return 0;
      }
      for (std::size_t k = 0; k < d.scans.size(); ++k) {
        Dataset one;
        one.source = d.source;
        one.format = d.format;
        one.coordinate_system = d.coordinate_system;
        one.scans.push_back(std::move(d.scans[k]));
        const auto path = out.parent_path() / (out.stem().string() + "_" + std::to_string(k) + "_" +
                                               safeName(one.scans[0].name) + out.extension().string());
        refuseSameFile(a->in, path);
        WriteReport report;
        wo.report = &report;
        writeDataset(path, one, wo);
        printWritten(path, one, report);
      }
      return 0;
    };
  });
}

}  // namespace plumb::cli
