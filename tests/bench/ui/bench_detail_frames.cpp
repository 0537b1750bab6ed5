// Frames of the desktop on a point file above the memory budget (issue 16: "camera motion
// keeps >= 5 frames/s under Xvfb software rendering"). The real main window opens FILE with
// the given budget (Registration dock "memory", as --memory-budget): the file opens as a
// subsample, its level-of-detail cache is built or reused, and the detail is drawn after a
// still frame (DetailController). Then, `rounds` times:
//   moving : the camera orbits for `frames` frames with LodController moving (what a drag
//            does): each frame timed (renderNow: render + glFinish);
//   still  : the camera stops: the still frame, then the detail for the new view read and
//            swapped in (time until the detail is drawn again, points drawn).
// Side by side, the same orbit without level of detail: still frames all along (the whole
// subsample and the detail drawn in every frame), so the gain is visible.
// Prints the open time, the frames per second (median and worst frame) and the peak RSS.
//
// Several files open together, as a campaign does: they share the budget (loadShare) and the
// still frame's detail budget; the figures are summed over them.
//
// usage: xvfb-run -a -s "-screen 0 1600x1200x24" bench_detail_frames FILE... [--budget-mb 4096]
//                  [--frames 30] [--rounds 3]   (PLUMB_LOD_CACHE_DIR: where the caches go)
#include <QApplication>
#include <QElapsedTimer>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "common/process_memory.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_controller.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/surface_format.hpp"
#include "ui/view/vtk_view_widget.hpp"

using namespace plumb;
using namespace plumb::ui;

namespace {

struct Frames {
  double median = 0, worst = 0;
  std::size_t drawn = 0;
  double fps() const { return median > 0 ? 1000.0 / median : 0; }
};

Frames orbit(VtkViewWidget& view, Scene& scene, int frames) {
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    view.renderer()->GetActiveCamera()->Azimuth(3.0);
    ms.push_back(view.renderNow());
  }
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], ms.back(), scene.drawnPointCount()};
}

/// Processes events until `done` or `seconds` passed; returns the seconds spent.
template <class F>
double waitUntil(F done, double seconds) {
  QElapsedTimer t;
  t.start();
  while (!done() && t.elapsed() < seconds * 1000) QApplication::processEvents(QEventLoop::AllEvents, 20);
  return double(t.elapsed()) / 1000.0;
}

DetailLayer* detailOf(DatasetLayer& layer) {
  for (const auto& c : layer.children())
    if (c->kind() == LayerKind::Detail) return static_cast<DetailLayer*>(c.get());
  return nullptr;
}

struct Options {
  QStringList files;
  double budget_mb = 4096;
  int frames = 30, rounds = 3;
};

Options parse(int argc, char** argv) {
  Options o;
  int i = 1;
  for (; i < argc && std::strncmp(argv[i], "--", 2) != 0; ++i) o.files << argv[i];
  for (; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--budget-mb")) o.budget_mb = std::stod(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--frames")) o.frames = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--rounds")) o.rounds = std::stoi(argv[i + 1]);
  }
  return o;
}

/// The opened files' layers and their detail layers (one each once their caches are ready).
struct Opened {
  std::vector<DatasetLayer*> layers;
  std::vector<DetailLayer*> details;
  std::size_t subsample_points() const {
    std::size_t n = 0;
    for (const DatasetLayer* l : layers) n += l->dataset().pointCount();
    return n;
  }
  std::size_t detail_points() const {
    std::size_t n = 0;
    for (const DetailLayer* d : details) n += d->drawnPointCount();
    return n;
  }
  std::vector<std::vector<std::uint32_t>> drawn_nodes() const {
    std::vector<std::vector<std::uint32_t>> v;
    for (const DetailLayer* d : details) v.push_back(d->drawn().nodes);
    return v;
  }
};

std::vector<DatasetLayer*> datasetLayers(Scene& scene) {
  std::vector<DatasetLayer*> out;
  for (const auto& l : scene.layers())
    if (auto* d = dynamic_cast<DatasetLayer*>(l.get())) out.push_back(d);
  return out;
}

bool allDetailed(const std::vector<DatasetLayer*>& layers) {
  return std::all_of(layers.begin(), layers.end(), [](DatasetLayer* l) { return detailOf(*l) != nullptr; });
}

}  // namespace

int main(int argc, char** argv) {
  setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  const Options o = parse(argc, argv);
  if (o.files.isEmpty()) {
    std::fprintf(stderr, "usage: bench_detail_frames FILE... [--budget-mb MB] [--frames N] [--rounds N]\n");
    return 2;
  }
  MainWindow window;
  window.resize(1600, 1000);
  window.show();
  AppContext& ctx = window.context();
  ctx.registration->params().memory.budget_mb = o.budget_mb;
  auto* lod = window.findChild<LodController*>();
  auto* details = window.findChild<DetailController*>();
  if (!lod || !details) return 2;
  ctx.view.setFrameTiming(true);

  QElapsedTimer open;
  open.start();
  window.openFiles(o.files);
  const auto files = static_cast<std::size_t>(o.files.size());
  waitUntil([&] { return !ctx.scene.layers().empty(); }, 1800);
  const double first_view_s = double(open.elapsed()) / 1000.0;
  waitUntil([&] { return datasetLayers(ctx.scene).size() == files || ctx.tasks.runningCount() == 0; }, 3600);
  const double all_open_s = double(open.elapsed()) / 1000.0;
  Opened opened{datasetLayers(ctx.scene), {}};
  if (opened.layers.size() != files) {
    std::fprintf(stderr, "%zu of %zu files opened:\n%s\n", opened.layers.size(), files, qPrintable(ctx.log.toPlainText()));
    return 1;
  }
  waitUntil([&] { return allDetailed(opened.layers); }, 7200);
  const double cache_s = double(open.elapsed()) / 1000.0;
  if (!allDetailed(opened.layers)) {
    std::fprintf(stderr, "a file has no detail layer:\n%s\n", qPrintable(ctx.log.toPlainText()));
    return 1;
  }
  for (DatasetLayer* l : opened.layers) opened.details.push_back(detailOf(*l));
  waitUntil([&] { return (ctx.view.requestRender(), opened.detail_points() > 0 && !details->loading()); }, 120);
  std::printf("bench_detail_frames: %zu file(s) (%s ...), budget %.0f MB\n", files, qPrintable(o.files.front()), o.budget_mb);
  std::printf("  opened as subsamples of %zu points in all; first view %.1f s, every file open %.1f s; "
              "detail caches ready at %.1f s; detail drawn: %zu points\n",
              opened.subsample_points(), first_view_s, all_open_s, cache_s, opened.detail_points());
  std::printf("  %-7s | %-24s | %-30s | %s\n", "round", "moving (LoD)", "still: detail back after",
              "orbit without LoD (whole subsample + detail)");
  for (int r = 0; r < o.rounds; ++r) {
    lod->startMoving();
    const Frames moving = orbit(ctx.view, ctx.scene, o.frames);
    lod->stopMoving();
    QElapsedTimer still;
    still.start();
    lod->showStill();
    const auto before = opened.drawn_nodes();
    waitUntil([&] { return opened.drawn_nodes() != before && !details->loading() && opened.detail_points() > 0; }, 120);
    const double still_s = double(still.elapsed()) / 1000.0;
    const std::size_t detail_points = opened.detail_points();
    lod->setFullDetailWhenStill(true);  // the peer: every subsample point (and the detail) each frame
    lod->showStill();
    const Frames full = orbit(ctx.view, ctx.scene, std::max(3, o.frames / 5));
    lod->setFullDetailWhenStill(false);
    std::printf("  %-7d | %5.1f fps (%4.0f / %4.0f ms) %7zu pts | %5.2f s, %8zu detail points | "
                "%5.1f fps (%5.0f / %5.0f ms) %9zu + %zu pts\n",
                r, moving.fps(), moving.median, moving.worst, moving.drawn, still_s, detail_points,
                full.fps(), full.median, full.worst, full.drawn, opened.detail_points());
  }
  std::printf("  peak RSS %.2f GB\n", double(procKilobytesLine("/proc/self/status", "VmHWM")) / (1024.0 * 1024.0 * 1024.0));
  std::fprintf(stderr, "desktop log:\n%s\n", qPrintable(ctx.log.toPlainText()));
  return 0;
}
