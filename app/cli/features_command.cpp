// plumb-cli features FILE --planes|--openings|--segments [-o features.json|.ply] [--set k=v]...
//   [--seed N]
// Extracts features from a point dataset (all scans merged in the dataset frame) or a model
// (segments = exact sharp edges of the mesh; planes/openings from a Poisson-disk sampling).
// Openings use ray tracing only when every scan has a pose or points carry sensor origins;
// otherwise the command says so and uses holes of wall polygons.
#include <iostream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "common/error.hpp"
#include "features/export/feature_export.hpp"
#include "features/facades/opening_detection.hpp"
#include "features/mesh_edges/mesh_edges.hpp"
#include "features/mesh_edges/poisson_disk.hpp"
#include "features/planes/plane_extraction.hpp"
#include "features/segments/segment_detection.hpp"
#include "io/io.hpp"

namespace plumb::cli {
namespace {

struct FeatureArgs {
  std::string input, output;
  bool planes = false, openings = false, segments = false;
  std::vector<std::string> settings;  // key=value
  std::string seed;                   ///< empty: kDefaultSeed (that of plumb-cli register)
};

/// Applies key=value to whichever schema knows the key; unknown keys are errors.
void applySettings(const std::vector<std::string>& settings, PlaneExtractionParams& pp,
                   OpeningDetectionParams& op, SegmentDetectionParams& sp, MeshEdgeParams& mp) {
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw InputError("--set expects key=value, got '" + s + "'");
    const std::string key = s.substr(0, eq), value = s.substr(eq + 1);
    bool known = setParam(PlaneExtractionParams::schema(), pp, key, value);
    known = setParam(OpeningDetectionParams::schema(), op, key, value) || known;
    known = setParam(SegmentDetectionParams::schema(), sp, key, value) || known;
    known = setParam(MeshEdgeParams::schema(), mp, key, value) || known;
    if (!known) throw InputError("unknown feature parameter '" + key + "'");
  }
}

int run(const FeatureArgs& a) {
  PlaneExtractionParams pp;
  OpeningDetectionParams op;
  SegmentDetectionParams sp;
  MeshEdgeParams mp;
  applySettings(a.settings, pp, op, sp, mp);
  const std::uint64_t seed =
      a.seed.empty() ? kDefaultSeed : static_cast<std::uint64_t>(parseOption(seedSpec(), a.seed));
  LoadedData data = readFile(a.input);
  FeatureSet fs;
  PointCloud cloud;
  if (auto* m = std::get_if<BimModel>(&data)) {
    if (a.segments) {
      fs.segments = extractSharpEdges(m->mesh, mp).segments;
      std::cout << "segments: " << fs.segments.size() << " sharp edges of the model\n";
    }
    if (a.planes || a.openings) cloud = samplePoissonDisk(m->mesh, {});
  } else {
    const auto& d = std::get<Dataset>(data);
    bool origins = !d.scans.empty();
    for (const auto& s : d.scans) origins = origins && (s.has_pose || s.cloud.hasSensorOrigins());
    cloud = d.merged(origins);
    if (a.segments) {
      const auto r = detectSegments(cloud, sp);
      fs.segments = r.segments;
      std::cout << "segments: " << fs.segments.size() << " from " << r.patches.size() << " patches in " << r.seconds
                << " s\n";
    }
  }
  if (a.planes || a.openings) {
    const auto r = extractPlanes(cloud, pp, seed);
    fs.planes = r.planes;
    std::cout << "planes: " << r.planes.size() << " polygons (" << r.planes_detected << " planes, "
              << detectorName(r.detector_used) << ", t = " << r.distance_threshold_used << " m) in " << r.seconds
              << " s\n";
  }
  if (a.openings) {
    const auto r = detectOpenings(cloud, fs.planes, op);
    for (const auto& msg : r.messages) std::cout << "openings: " << msg << "\n";
    fs.facades = r.facades;
    fs.openings = r.openings;
    std::cout << "openings: " << r.openings.size() << " on " << r.facades.size() << " facades, "
              << r.interior_points.size() << " interior points\n";
  }
  if (!a.output.empty()) {
    writeFeatureSet(a.output, fs);
    std::cout << "wrote " << a.output << "\n";
  }
  return 0;
}

}  // namespace

void addFeaturesCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("features", "Extract planar polygons, openings or 3D segments");
  auto a = std::make_shared<FeatureArgs>();
  cmd->add_option("input", a->input, "Point dataset or model file")->required();
  cmd->add_flag("--planes", a->planes, "Planar polygons (MSAC + alpha shapes)");
  cmd->add_flag("--openings", a->openings, "Façades and openings (ray tracing / wall holes)");
  cmd->add_flag("--segments", a->segments, "3D line segments (scans) or sharp edges (models)");
  cmd->add_option("-o,--output", a->output, "Write features.json or features.ply");
  cmd->add_option("--set", a->settings, "Parameter key=value (e.g. distance-threshold=0.03), repeatable");
  cmd->add_option("--seed", a->seed,
                  "Random seed of the plane detection, 0 .. 9e15 (default 1, as plumb-cli register)");
  cmd->callback([&action, a] {
    if (!a->planes && !a->openings && !a->segments)
      throw CLI::ValidationError("features", "choose at least one of --planes, --openings, --segments");
    action = [a]() { return run(*a); };
  });
}

}  // namespace plumb::cli
