// plumb-cli features FILE --planes|--openings|--segments [-o features.json|.ply] [--set k=v]...
//   [--seed N]
// Extracts features from a point dataset (all scans merged in the dataset frame) or a model
// (the model's own, exact: segments = sharp edges of the mesh; planes = coplanar faces merged
// into polygons; openings = façades and the IfcWindow/IfcDoor rectangles on their wall faces,
// features/bim).
// Openings use ray tracing only when every scan has a pose or points carry sensor origins;
// otherwise the command says so and uses holes of wall polygons.
#include <iostream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "common/error.hpp"
#include "features/bim/bim_features.hpp"
#include "features/export/feature_export.hpp"
#include "features/facades/opening_detection.hpp"
#include "features/mesh_edges/mesh_edges.hpp"
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
struct FeatureParams {
  PlaneExtractionParams planes;
  OpeningDetectionParams openings;
  SegmentDetectionParams segments;
  MeshEdgeParams mesh_edges;
  BimFeatureParams bim;
};

void applySettings(const std::vector<std::string>& settings, FeatureParams& fp) {
  for (const auto& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos) throw InputError("--set expects key=value, got '" + s + "'");
    const std::string key = s.substr(0, eq), value = s.substr(eq + 1);
    bool known = setParam(PlaneExtractionParams::schema(), fp.planes, key, value);
    known = setParam(OpeningDetectionParams::schema(), fp.openings, key, value) || known;
    known = setParam(SegmentDetectionParams::schema(), fp.segments, key, value) || known;
    known = setParam(MeshEdgeParams::schema(), fp.mesh_edges, key, value) || known;
    known = setParam(BimFeatureParams::schema(), fp.bim, key, value) || known;
    if (!known) throw InputError("unknown feature parameter '" + key + "'");
  }
}

/// The model's own features (exact, no sampling).
FeatureSet modelFeatures(const FeatureArgs& a, const BimModel& m, const FeatureParams& fp) {
  FeatureSet fs;
  if (a.segments) {
    fs.segments = extractSharpEdges(m.mesh, fp.mesh_edges).segments;
    std::cout << "segments: " << fs.segments.size() << " sharp edges of the model\n";
  }
  if (!a.planes && !a.openings) return fs;
  BimFeatureResult r = extractBimFeatures(m, fp.bim);
  fs.planes = std::move(r.features.planes);
  std::cout << "planes: " << fs.planes.size() << " polygons of the model (coplanar faces merged) in "
            << r.seconds << " s\n";
  if (a.openings) {
    fs.facades = std::move(r.features.facades);
    fs.openings = std::move(r.features.openings);
    std::cout << "openings: " << r.messages.back() << "\n";
    std::cout << "openings: " << fs.openings.size() << " on " << fs.facades.size() << " facades\n";
  }
  return fs;
}

/// Features detected on the points of a dataset (all scans merged).
FeatureSet scanFeatures(const FeatureArgs& a, const Dataset& d, const FeatureParams& fp,
                        std::uint64_t seed) {
  FeatureSet fs;
  bool origins = !d.scans.empty();
  for (const auto& s : d.scans) origins = origins && (s.has_pose || s.cloud.hasSensorOrigins());
  const PointCloud cloud = d.merged(origins);
  if (a.segments) {
    const auto r = detectSegments(cloud, fp.segments);
    fs.segments = r.segments;
    std::cout << "segments: " << fs.segments.size() << " from " << r.patches.size() << " patches in " << r.seconds
              << " s\n";
  }
  if (a.planes || a.openings) {
    const auto r = extractPlanes(cloud, fp.planes, seed);
    fs.planes = r.planes;
    std::cout << "planes: " << r.planes.size() << " polygons (" << r.planes_detected << " planes, "
              << detectorName(r.detector_used) << ", t = " << r.distance_threshold_used << " m) in " << r.seconds
              << " s\n";
  }
  if (a.openings) {
    const auto r = detectOpenings(cloud, fs.planes, fp.openings);
    for (const auto& msg : r.messages) std::cout << "openings: " << msg << "\n";
    fs.facades = r.facades;
    fs.openings = r.openings;
    std::cout << "openings: " << r.openings.size() << " on " << r.facades.size() << " facades, "
              << r.interior_points.size() << " interior points\n";
  }
  return fs;
}

int run(const FeatureArgs& a) {
  FeatureParams fp;
  applySettings(a.settings, fp);
  const std::uint64_t seed =
      a.seed.empty() ? kDefaultSeed : static_cast<std::uint64_t>(parseOption(seedSpec(), a.seed));
  const LoadedData data = readFile(a.input);
  const FeatureSet fs = std::holds_alternative<BimModel>(data)
                            ? modelFeatures(a, std::get<BimModel>(data), fp)
                            : scanFeatures(a, std::get<Dataset>(data), fp, seed);
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
  cmd->add_flag("--planes", a->planes,
                "Planar polygons (scans: MSAC + alpha shapes; models: coplanar faces merged)");
  cmd->add_flag("--openings", a->openings,
                "Façades and openings (scans: ray tracing / wall holes; models: IfcWindow/IfcDoor)");
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
