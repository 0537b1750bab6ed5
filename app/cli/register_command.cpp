// plumb-cli register SOURCE TARGET [--method auto|planes|openings|segments|icp] [--no-refine]
//   [-o REGISTERED.{e57,ply,las}] [--transform T.json] [--report REPORT.json] [--seed N]
// Registers SOURCE onto TARGET (scans or models; a PLY/OBJ with faces or an IFC is a model).
// On failure (too few features, no hypothesis above threshold, ambiguous, refinement lost the
// overlap) it explains why on stderr, writes the report if asked (it says FAILED) and exits 2
// without writing any transform or registered file.
#include <iostream>
#include <optional>

#include <unistd.h>

#include "cli/command.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/io.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb::cli {
namespace {

struct RegisterOptions {
  std::string source, target, method = "auto", output, transform, report;
  bool no_refine = false;
  std::uint64_t seed = 1;
};

struct Side {
  LoadedData data;
  PointCloud cloud;
  RegistrationSide side;
};

void load(Side& s, const std::string& path) {
  s.data = readFile(path);
  if (auto* d = std::get_if<Dataset>(&s.data)) {
    if (d->pointCount() == 0) throw FileError(path, "holds no points to register");
    s.cloud = d->merged(false);
    s.cloud.removeNonFinite();
    s.side.cloud = &s.cloud;
    // One static scan with a pose: its scanner position orients plane normals.
    if (d->scans.size() == 1 && d->scans[0].has_pose && !d->scans[0].cloud.hasSensorOrigins())
      s.side.viewpoint = d->scans[0].pose.translation();
  } else {
    auto& m = std::get<BimModel>(s.data);
    if (m.mesh.triangles.empty()) throw FileError(path, "model has no triangles to register");
    s.side.model = &m;
  }
}

int run(const RegisterOptions& o) {
  PipelineParams p;
  p.method = methodFromName(o.method);
  p.refine = !o.no_refine;
  p.seed = o.seed;
  Side src, tgt;
  load(src, o.source);
  load(tgt, o.target);
  // Progress on a terminal only (logs stay clean).
  const bool tty = isatty(2);
  Progress progress([tty](double f, std::string_view stage) {
    if (tty) std::cerr << "\r[" << int(f * 100) << "%] " << stage << "\033[K" << std::flush;
  });
  const PipelineResult r = registerData(src.side, tgt.side, p, &progress);
  if (tty) std::cerr << "\r\033[K";
  for (const auto& line : r.log) std::cerr << "  " << line << "\n";
  if (!o.report.empty())
    writeFileAtomically(o.report, [&](std::ostream& out) { out << qualityReportToJson(r.report); });
  if (!r.success()) {
    std::cerr << "plumb-cli: registration failed: " << r.report.verdict << "\n";
    return 2;
  }
  std::cout << qualityReportToText(r.report);
  const RigidTransform& T = r.transform();
  if (!o.transform.empty()) writeTransformFile(o.transform, T);
  if (!o.output.empty()) {
    if (auto* d = std::get_if<Dataset>(&src.data)) {
      Dataset moved = *d;
      for (auto& scan : moved.scans) {
        scan.pose = T * scan.pose;
        scan.has_pose = true;
      }
      writeDataset(o.output, moved);
    } else {
      BimModel m = std::get<BimModel>(src.data);
      m.transform(T);
      writeModel(o.output, m);
    }
  }
  return 0;
}

}  // namespace

void addRegisterCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<RegisterOptions>();
  auto* cmd = app.add_subcommand(
      "register", "Register SOURCE onto TARGET (scan/scan, indoor/outdoor, scan/BIM)");
  cmd->add_option("SOURCE", opts->source, "Moving dataset: scan or model file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("TARGET", opts->target, "Reference dataset: scan or model file")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", opts->method, "auto, planes, openings, segments or icp")
      ->check(CLI::IsMember({"auto", "planes", "openings", "segments", "icp"}));
  cmd->add_flag("--no-refine", opts->no_refine, "Skip the local ICP refinement");
  cmd->add_option("-o,--output", opts->output, "Write the registered SOURCE (e57, ply, las...)");
  cmd->add_option("--transform", opts->transform, "Write the transform (JSON or 4x4 text)");
  cmd->add_option("--report", opts->report, "Write the quality report (JSON)");
  cmd->add_option("--seed", opts->seed, "Random seed (results are deterministic for a seed)");
  cmd->callback([opts, &action] { action = [opts] { return run(*opts); }; });
}

}  // namespace plumb::cli
