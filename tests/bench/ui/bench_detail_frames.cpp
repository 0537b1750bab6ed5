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
// usage: xvfb-run -a -s "-screen 0 1600x1200x24" bench_detail_frames FILE [--budget-mb 4096]
//                  [--frames 30] [--rounds 3]   (PLUMB_LOD_CACHE_DIR: where the cache goes)
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

}  // namespace

int main(int argc, char** argv) {
  setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_detail_frames FILE [--budget-mb MB] [--frames N] [--rounds N]\n");
    return 2;
  }
  const QString file = argv[1];
  double budget_mb = 4096;
  int frames = 30, rounds = 3;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--budget-mb")) budget_mb = std::stod(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--frames")) frames = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--rounds")) rounds = std::stoi(argv[i + 1]);
  }
  MainWindow window;
  window.resize(1600, 1000);
  window.show();
  AppContext& ctx = window.context();
  ctx.registration->params().memory.budget_mb = budget_mb;
  auto* lod = window.findChild<LodController*>();
  if (!lod) return 2;
  ctx.view.setFrameTiming(true);

  QElapsedTimer open;
  open.start();
  window.openFiles({file});
  waitUntil([&] { return !ctx.scene.layers().empty(); }, 600);
  const double first_view_s = double(open.elapsed()) / 1000.0;
  auto* layer = ctx.scene.layers().empty() ? nullptr : dynamic_cast<DatasetLayer*>(ctx.scene.layers()[0].get());
  if (!layer) {
    std::fprintf(stderr, "%s did not open:\n%s\n", argv[1], qPrintable(ctx.log.toPlainText()));
    return 1;
  }
  waitUntil([&] { return detailOf(*layer) != nullptr; }, 1800);
  DetailLayer* detail = detailOf(*layer);
  const double cache_s = double(open.elapsed()) / 1000.0;
  if (!detail) {
    std::fprintf(stderr, "no detail layer:\n%s\n", qPrintable(ctx.log.toPlainText()));
    return 1;
  }
  waitUntil([&] { return (ctx.view.requestRender(), detail->drawnPointCount() > 0); }, 120);
  std::printf("bench_detail_frames: %s, budget %.0f MB\n", argv[1], budget_mb);
  std::printf("  opened as a subsample of %zu points, first view %.1f s; detail cache ready at %.1f s; "
              "detail drawn: %zu points\n",
              layer->dataset().pointCount(), first_view_s, cache_s, detail->drawnPointCount());
  std::printf("  %-7s | %-24s | %-30s | %s\n", "round", "moving (LoD)", "still: detail back after",
              "orbit without LoD (whole subsample + detail)");
  for (int r = 0; r < rounds; ++r) {
    lod->startMoving();
    const Frames moving = orbit(ctx.view, ctx.scene, frames);
    lod->stopMoving();
    QElapsedTimer still;
    still.start();
    lod->showStill();
    const std::vector<std::uint32_t> before = detail->drawn().nodes;
    waitUntil([&] { return detail->drawn().nodes != before && detail->drawnPointCount() > 0; }, 120);
    const double still_s = double(still.elapsed()) / 1000.0;
    const std::size_t detail_points = detail->drawnPointCount();
    lod->setFullDetailWhenStill(true);  // the peer: every subsample point (and the detail) each frame
    lod->showStill();
    const Frames full = orbit(ctx.view, ctx.scene, std::max(3, frames / 5));
    lod->setFullDetailWhenStill(false);
    std::printf("  %-7d | %5.1f fps (%4.0f / %4.0f ms) %7zu pts | %5.2f s, %8zu detail points | "
                "%5.1f fps (%5.0f / %5.0f ms) %9zu + %zu pts\n",
                r, moving.fps(), moving.median, moving.worst, moving.drawn, still_s, detail_points,
                full.fps(), full.median, full.worst, full.drawn, detail->drawnPointCount());
  }
  std::printf("  peak RSS %.2f GB\n", double(procKilobytesLine("/proc/self/status", "VmHWM")) / (1024.0 * 1024.0 * 1024.0));
  return 0;
}
