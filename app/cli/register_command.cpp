// plumb-cli register SOURCE TARGET [--method auto|planes|openings|segments|icp] [--no-refine]
//   [--orientation auto|levelled|y-up|any]
//   [-o REGISTERED.{e57,ply,las} [--distances [--distance-max M] [--unsigned-distances]]]
//   [--transform T.json] [--report REPORT.{json,html}]... [--seed N]
//   [--params PARAMS.json] [--set GROUP.KEY=VALUE]... [--print-params] [--source-trajectory FILE]
//   [--target-trajectory FILE] [--model-elements IfcWall,IfcSlab] [--model-element-ids ID,...]
// Registers SOURCE onto TARGET (scans or models; a PLY/OBJ with faces or an IFC is a model).
// The inputs are built with makeRegistrationInput, exactly like the desktop app.
// --model-elements / --model-element-ids restrict a model TARGET to chosen IFC types or
// elements (GlobalId or name) before its features and refinement surface are built; the report
// says what the registration rests on (core/model/model_element_filter.hpp).
// --source-trajectory / --target-trajectory: a mobile scan without per-point sensor origins
// (LAS, E57 from other tools) gets them from the vehicle trajectory ("t x y z" per line, in
// that dataset's frame) interpolated at each point's timestamp; the openings method needs them.
// Parameters: the defaults, then --params (the JSON of pipelineParamsToJson, any subset of
// its keys), then each --set GROUP.KEY=VALUE (KEY=VALUE for the top level), then the flags
// given on the command line (--method, --no-refine, --seed, --orientation), in that order; `--print-params` writes the resulting set as JSON to stdout and exits, so
// `plumb-cli register --print-params > p.json` gives a file to edit.
// The seed is taken from that one place (PipelineParams::seed, top-level "seed") for every
// random step; a group "seed" in an older file must equal it (pipelineParamsFromJson).
// Exit codes follow the report's verdict level (core/quality/verdict_level.hpp): 0 usable,
// the results are written; 3 check visually: the results are written and the warnings are
// repeated on stderr; 2 failed or ambiguous (too few features, no hypothesis above threshold,
// ambiguous, degenerate, refinement lost the overlap): it explains why on stderr, writes the
// report if asked (it says FAILED and lists every candidate placement) and writes neither the
// transform nor the registered file, so an existing output stays untouched. 1: an input could
// not be read or the parameters are invalid (one-line error naming the file). Every output (-o with its extension, --transform,
// --report) is checked once the inputs are read and before the registration runs: a bad one
// is exit 1 with nothing written.
// --distances adds to -o the distance of every registered point to TARGET as the per-point
// scalar field "distance" (metres, float32: a PLY vertex property, an E57 prototype field
// "plumb:distance", a LAS extra-bytes field), measured like the desktop's distance colouring
// (quality/cloud_distance.hpp): signed, + in front of the target's surface and - behind it,
// unless --unsigned-distances; NaN where nothing of TARGET lies within --distance-max metres
// (default 0.1). It needs SOURCE to be a point dataset held in memory (within the budget).
// --report R.json writes the quality report's JSON; --report R.html the report to hand over
// (core/report: verdict, every JSON figure with its meaning, distances, per-feature residuals,
// plan and section pictures, sign-off block), also when the registration failed. --report
// may be given more than once (e.g. both files of one registration).
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <vector>

#include <unistd.h>

#include "cli/command.hpp"
#include "cli/written_output.hpp"
#include "cli/option_checks.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "io/io.hpp"
#include "model/trajectory.hpp"
#include "quality/cloud_distance.hpp"
#include "io/stream/point_convert.hpp"
#include "registration/auto/pipeline_param_groups.hpp"
#include "registration/auto/registration_input.hpp"
#include "registration/bounded/bounded_input.hpp"
#include "report/report_file.hpp"

namespace plumb::cli {
namespace {

struct RegisterOptions {
  std::string source, target, method, output, transform, params;
  std::vector<std::string> reports;  ///< --report, once per file (.json and/or .html)
  std::string source_trajectory, target_trajectory;
  bool no_refine = false;
  bool print_params = false;
  bool distances = false, unsigned_distances = false;  ///< --distances, --unsigned-distances
  std::string distance_max;  ///< --distance-max; empty: the default
  std::string seed;  ///< empty: not given; range-checked in loadParams
  std::string orientation;  ///< empty: not given; else orientation.source (issue 14)
  std::string memory_budget;  ///< empty: not given; else memory.budget (MB)
  std::vector<std::string> settings;  ///< --set GROUP.KEY=VALUE or KEY=VALUE
  std::vector<std::string> model_elements;  ///< per modelElementOptions(), comma-separated lists
};

/// --model-elements / --model-element-ids as the filter they describe.
ModelElementFilter modelElementFilter(const RegisterOptions& o) {
  ModelElementFilter f;
  const auto& options = modelElementOptions();
  for (std::size_t i = 0; i < options.size(); ++i) f.*options[i].member = splitNameList(o.model_elements[i]);
  return f;
}

PipelineParams loadParams(const RegisterOptions& o) {
  PipelineParams p;
  if (!o.params.empty()) {
    std::ifstream in(o.params);
    if (!in) throw FileError(o.params, "cannot be opened for reading");
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      throw FileError(o.params, std::string("is not valid JSON: ") + e.what(),
                      atByte(e.byte));
    }
    try {
      pipelineParamsFromJson(j, p);
    } catch (const std::exception& e) {  // InputError (schema) or json type_error
      throw FileError(o.params, std::string("invalid registration parameters: ") + e.what());
    }
  }
  applySettings(o.settings, [&](const std::string& path, const std::string& value) { setPipelineParam(p, path, value); });
  if (!o.method.empty()) p.method = methodFromName(o.method);
  if (o.no_refine) p.refine = false;
  if (!o.seed.empty()) p.seed = static_cast<std::uint64_t>(parseOption(seedSpec(), o.seed));
  if (!o.orientation.empty()) setPipelineParam(p, "orientation.source", o.orientation);
  if (!o.memory_budget.empty()) setPipelineParam(p, "memory.budget", o.memory_budget);
  return p;
}

struct Side {
  LoadedData data;  ///< what readFile gave (an empty Dataset when subsampled)
  RegistrationInput input;
  bool subsampled = false;  ///< input is a streamed subsample: write -o by streaming the file
};

/// A file above the memory budget becomes a streamed subsample (not with a trajectory: the
/// origins are set on the whole dataset).
bool loadSubsampled(Side& s, const std::string& path, const std::string& trajectory, const PipelineParams& p) {
  if (!trajectory.empty()) return false;
  auto sub = boundedRegistrationInput(path, p);
  if (!sub) return false;
  std::cerr << "plumb-cli: " << path << ": " << sub->estimated_points << " points exceed the memory budget ("
            << sub->budget_bytes / (1024 * 1024) << " MB): registering a " << sub->voxel * 100
            << " cm voxel subsample of " << sub->points_kept << " of " << sub->points_read << " points\n";
  s.input = std::move(sub->input);
  s.subsampled = true;
  return true;
}

/// The element options choose parts of a model: InputError for a point-cloud target.
void checkElementsOnModel(const Side& s, const std::string& path, const ModelElementFilter& elements) {
  if (!elements.empty() && !s.input.model)
    throw InputError("register: --model-elements / --model-element-ids: TARGET " + path +
                     " is a point cloud; they choose elements of a model target");
}

void load(Side& s, const std::string& path, const std::string& trajectory, const char* option,
          const PipelineParams& p, const ModelElementFilter& elements = {}) {
  if (loadSubsampled(s, path, trajectory, p)) return checkElementsOnModel(s, path, elements);
  s.data = readFile(path);
  if (!trajectory.empty() && !std::holds_alternative<Dataset>(s.data))
    throw InputError(std::string(option) + ": " + path + " is a model, not a scan: a trajectory only "
                     "applies to a mobile scan");
  if (auto* d = std::get_if<Dataset>(&s.data)) {
    if (!trajectory.empty()) setSensorOriginsFromTrajectory(*d, readTrajectory(trajectory), trajectory);
    s.input = makeRegistrationInput(*d, RigidTransform());
  } else {
    s.input = makeRegistrationInput(std::get<BimModel>(s.data), RigidTransform(), elements);
  }
  checkElementsOnModel(s, path, elements);
}

/// The distance parameters of --distances; InputError for a distance option without it, or
/// without -o.
DistanceParams distanceParams(const RegisterOptions& o) {
  DistanceParams d;
  if (!o.distances) {
    if (o.unsigned_distances || !o.distance_max.empty())
      throw InputError("register: --distance-max and --unsigned-distances need --distances");
    return d;
  }
  if (o.output.empty()) throw InputError("register: --distances needs -o (the distances are written with the points)");
  d.signed_distances = !o.unsigned_distances;
  if (!o.distance_max.empty()) {
    ParamSpec spec = DistanceParams::schema().find("max-distance")->spec;
    spec.key = "distance-max";
    d.max_distance = parseOption(spec, o.distance_max);
  }
  return d;
}

/// --distances needs the registered points in memory: a point dataset, not streamed. A
/// streamed target is measured as its subsample (said on stderr).
void checkDistanceInputs(const RegisterOptions& o, const Side& src, const Side& tgt) {
  if (!o.distances) return;
  if (tgt.subsampled)
    std::cerr << "plumb-cli: --distances: measured to the subsample of " << o.target
              << " (it exceeds the memory budget)\n";
  if (src.subsampled)
    throw InputError("register: --distances: " + o.source + " exceeds the memory budget and would be streamed "
                     "to -o; raise --memory-budget");
  if (!std::holds_alternative<Dataset>(src.data))
    throw InputError("register: --distances: " + o.source + " is a model; distances are written for points");
}

void checkOutputs(const RegisterOptions& o, std::optional<bool> model_source) {
  if (!o.output.empty())
    checkOutputPath(o.output, model_source.value_or(isModelFormat(formatFromExtension(o.output))));
  std::vector<const std::string*> all{&o.output, &o.transform};
  for (const auto& r : o.reports) {
    report::checkReportPath(r, "register: --report");
    all.push_back(&r);
  }
  for (const std::string* p : all)
    if (p != &o.output && !p->empty()) checkWritableTarget(*p);
  for (std::size_t a = 0; a < all.size(); ++a)
    for (std::size_t b = a + 1; b < all.size(); ++b) {
      std::error_code ec;
      if (!all[a]->empty() && (*all[a] == *all[b] || std::filesystem::equivalent(*all[a], *all[b], ec)))
        throw InputError("register: '" + *all[a] + "' is given for two outputs");
    }
  for (const std::string* out : all)
    for (const std::string* in : {&o.source, &o.target}) {
      std::error_code ec;
      if (!out->empty() && std::filesystem::equivalent(*out, *in, ec))
        throw InputError("register: the output '" + *out + "' is the input '" + *in + "'");
    }
}

struct Registered {
  const Side& source;
  const Side& target;
  RigidTransform transform;
};
void writeRegistered(const RegisterOptions& o, const Registered& r, const DistanceParams& distances,
                     const MemoryParams& memory);

int run(const RegisterOptions& o) {
  const PipelineParams p = loadParams(o);
  if (o.print_params) {
    std::cout << pipelineParamsToJson(p).dump(2) << "\n";
    return 0;
  }
  const DistanceParams distances = distanceParams(o);
  if (o.source.empty() || o.target.empty())
    throw InputError("register: SOURCE and TARGET are required (or --print-params)");
  const FileFormat source_format = formatFromExtension(o.source);  // checked before the slow part
  checkOutputs(o, source_format == FileFormat::Ply ? std::nullopt
                                                   : std::optional<bool>(isModelFormat(source_format)));
  Side src, tgt;
  load(src, o.source, o.source_trajectory, "--source-trajectory", p);
  load(tgt, o.target, o.target_trajectory, "--target-trajectory", p, modelElementFilter(o));
  checkOutputs(o, std::holds_alternative<BimModel>(src.data));
  if (tgt.input.model_selection)
    std::cerr << "plumb-cli: registering onto " << o.target << " restricted to "
              << selectionSummary(*tgt.input.model_selection) << "\n";
  checkDistanceInputs(o, src, tgt);
  // Progress on a terminal only (logs stay clean).
  const bool tty = isatty(2);
  Progress progress([tty](double f, std::string_view stage) {
    if (tty) std::cerr << "\r[" << int(f * 100) << "%] " << stage << "\033[K" << std::flush;
  });
  const PipelineResult r = registerData(src.input.side(), tgt.input.side(), p, &progress);
  if (tty) std::cerr << "\r\033[K";
  for (const auto& line : r.log) std::cerr << "  " << line << "\n";
  for (const auto& path : o.reports)
    report::writeReportFile(path, src.input, tgt.input, o.source, o.target, r, p.seed);
  std::cout << qualityReportToText(r.report);
  const int code = verdictExitCode(r.report.level);
  if (r.report.level == VerdictLevel::Failed) {
    std::cerr << "plumb-cli: registration failed: " << r.report.verdict
              << (o.output.empty() && o.transform.empty() ? "" : " (no output written)") << "\n";
    return code;
  }
  if (r.report.level == VerdictLevel::CheckVisually) {
    std::cerr << "plumb-cli: check visually (exit " << code << "): the results are written, but";
    for (const auto& w : r.report.warnings) std::cerr << "\n  warning: " << w;
    std::cerr << "\n";
  }
  const RigidTransform& T = r.transform();
  if (!o.transform.empty()) writeTransformFile(o.transform, T);
  if (!o.output.empty()) writeRegistered(o, {src, tgt, T}, distances, p.memory);
  return code;
}

/// -o: the source moved by T. A subsampled source is streamed again from its file at full
/// resolution (convertPointFile: T applied per chunk, or per station for E57), never merged.
/// --distances: each scan gets its "distance" field to the target (checkDistanceInputs).
void writeRegistered(const RegisterOptions& o, const Registered& r, const DistanceParams& distances,
                     const MemoryParams& memory) {
  const Side& src = r.source;
  const RigidTransform& T = r.transform;
  if (src.subsampled) {
    ConvertParams convert;
    convert.transform = T;
    convert.memory_budget = memoryBudgetBytes(memory);
    convert.stream = streamOptionsWithin(convert.memory_budget);
    for (const auto& f : convertPointFile(o.source, o.output, convert).files)
      printWritten(f.path, f.points, f.scans, f.report);
  } else if (auto* d = std::get_if<Dataset>(&src.data)) {
    Dataset moved = *d;
    moved.transform(T);
    if (o.distances)
      attachDistanceField(moved, datasetDistances(moved, {}, distanceTarget(r.target.input), distances).per_scan);
    WriteReport written;
    WriteOptions options;
    options.report = &written;
    writeDataset(o.output, moved, options);
    printWritten(o.output, moved, written);
  } else {
    BimModel m = std::get<BimModel>(src.data);
    m.transform(T);
    writeModel(o.output, m);
  }
}

}  // namespace

void addRegisterCommand(CLI::App& app, Action& action) {
  auto opts = std::make_shared<RegisterOptions>();
  auto* cmd = app.add_subcommand(
      "register", "Register SOURCE onto TARGET (scan/scan, indoor/outdoor, scan/BIM)");
  cmd->add_option("SOURCE", opts->source, "Moving dataset: scan or model file")
      ->check(CLI::ExistingFile);
  cmd->add_option("TARGET", opts->target, "Reference dataset: scan or model file")
      ->check(CLI::ExistingFile);
  cmd->add_option("--method", opts->method, "auto, planes, openings, segments or icp")
      ->check(CLI::IsMember({"auto", "planes", "openings", "segments", "icp"}));
  cmd->add_flag("--no-refine", opts->no_refine, "Skip the local ICP refinement");
  cmd->add_option("--orientation", opts->orientation,
                  "The source's orientation: auto (default), levelled (Z up), y-up (glTF, "
                  "handheld, SLAM) or any; same as --set orientation.source=...")
      ->check(CLI::IsMember({"auto", "levelled", "y-up", "any"}));
  cmd->add_option("--memory-budget", opts->memory_budget, memoryBudgetHelp() + "; same as --set memory.budget=MB");
  opts->model_elements.resize(modelElementOptions().size());
  for (std::size_t i = 0; i < modelElementOptions().size(); ++i)
    cmd->add_option("--" + modelElementOptions()[i].key, opts->model_elements[i], modelElementOptions()[i].help);
  cmd->add_option("-o,--output", opts->output, "Write the registered SOURCE (e57, ply, las...)");
  cmd->add_flag("--distances", opts->distances,
                "With -o: add each point's distance to TARGET as the scalar field 'distance' (metres; "
                "signed: + in front of the target's surface, - behind; NaN beyond --distance-max)");
  cmd->add_option("--distance-max", opts->distance_max,
                  "--distances: search radius, metres (default 0.1); farther points get NaN");
  cmd->add_flag("--unsigned-distances", opts->unsigned_distances, "--distances: unsigned (all >= 0)");
  cmd->add_option("--transform", opts->transform, "Write the transform (JSON or 4x4 text)");
  cmd->add_option("--report", opts->reports,
                  "Write the quality report: R.json (every figure) or R.html (the report to hand over); "
                  "give it twice for both");
  cmd->add_option("--seed", opts->seed,
                  "Random seed of every step, 0 .. 9e15 (default 1; results are deterministic for a seed)");
  cmd->add_option("--params", opts->params,
                  "Registration parameters (JSON as written by --print-params; any subset of "
                  "its keys); --set, --method, --no-refine and --seed override it")
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", opts->settings,
                  "One parameter, GROUP.KEY=VALUE (planes.max-tilt=5) or KEY=VALUE for the top "
                  "level (agreement-rotation=1); keys as in --print-params; repeatable");
  cmd->add_option("--source-trajectory", opts->source_trajectory,
                  "Sensor trajectory of a mobile SOURCE scan without sensor origins (t x y z per line)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--target-trajectory", opts->target_trajectory,
                  "Sensor trajectory of a mobile TARGET scan without sensor origins (t x y z per line)")
      ->check(CLI::ExistingFile);
  cmd->add_flag("--print-params", opts->print_params,
                "Write the parameters (defaults, --params, flags) as JSON to stdout and exit");
  cmd->callback([opts, &action] { action = [opts] { return run(*opts); }; });
}

}  // namespace plumb::cli
