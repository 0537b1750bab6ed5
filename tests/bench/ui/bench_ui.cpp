// Frame times of the 3D view, side by side with a peer, at several cloud sizes:
//   plumb full   : Plumb's full-detail scan actor (what is drawn when the camera is still)
//   plumb LOD    : the level-of-detail subset while the camera moves, its size chosen by the
//                  adaptive LodBudget from measured frame times (the budget it settles on is
//                  printed), plus the frame that switches back to full detail
//   plumb still  : the still frames of LodController (the camera stops after a few moving
//                  frames, three times): each still frame's time and the points it drew. The
//                  still budget (target LodController::kStillTargetMs) is learned from them;
//                  larger subsets follow in later frames while a frame was well under target
//   forced full  : "Full detail when still" on: the still frame draws every point
//   add/colour   : adding the layer and a colour mode change. "all on the UI thread": the
//                  synchronous calls (Scene::addDataset(data), DatasetLayer::setStyle). As the
//                  application does them: the display data prepared in a background task
//                  (prepareDataset, timed alone), then only the VTK wrapping on the UI thread;
//                  the colours computed in a TaskManager task (DatasetLayer::requestStyle), the
//                  UI thread's event loop timed by a 5 ms QTimer meanwhile (longest gap
//                  between its ticks = longest UI freeze)
//   switch       : UI-thread time of the switches moving <-> still (LodController::startMoving
//                  and showStill: subset changes, before any frame), and the first frame after
//                  each switch against the next frame (the difference is the upload)
//   peer VTK     : plain vtkPolyDataMapper with default settings on the same points and colours
//                  (vtkPoints + one vertex cell per point + RGB uchar point scalars)
//   peer gauss   : vtkPointGaussianMapper with scale factor 0 (plain points drawn without a
//                  vertex cell index array), same points and colours
// The camera orbits between frames as during interaction; every frame ends with glFinish.
//
// usage: xvfb-run -a -s "-screen 0 1280x1024x24" bench_ui [--sizes 1000000,5000000,20000000]
//                  [--target-ms 50] [--point-size 2] [--seconds 12]
#include <QApplication>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPointData.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/point_style.hpp"
#include "ui/layers/prepared_dataset.hpp"
#include "ui/layers/scene.hpp"
#include "ui/tasks/add_dataset.hpp"
#include "ui/tasks/stall_meter.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/lod_budget.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/standard_view.hpp"
#include "ui/view/surface_format.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace {

/// A synthetic building-like cloud: points on the walls, floor and roof of a 60 x 30 x 12 m box.
plumb::Dataset syntheticBuilding(std::size_t n) {
  plumb::PointCloud cloud;
  cloud.positions.resize(n);
  cloud.colors.resize(n);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (std::size_t i = 0; i < n; ++i) {
    const float a = u(rng), b = u(rng);
    Eigen::Vector3f p;
    switch (i % 6) {
      case 0: p = {a * 60, 0, b * 12}; break;
      case 1: p = {a * 60, 30, b * 12}; break;
      case 2: p = {0, a * 30, b * 12}; break;
      case 3: p = {60, a * 30, b * 12}; break;
      case 4: p = {a * 60, b * 30, 0}; break;
      default: p = {a * 60, b * 30, 12}; break;
    }
    cloud.positions[i] = p;
    cloud.colors[i] = {static_cast<std::uint8_t>(a * 255), static_cast<std::uint8_t>(b * 255), 128};
  }
  return plumb::Dataset::fromCloud(std::move(cloud));
}

struct Timing {
  double first = 0, median = 0, max = 0;
  int frames = 0;
};

double orbitFrame(plumb::ui::VtkViewWidget& view) {
  view.renderer()->GetActiveCamera()->Azimuth(3.0);
  return view.renderNow();
}

/// The first frame (uploads) alone, then up to `max_frames` orbiting frames within `budget_s`.
Timing measure(plumb::ui::VtkViewWidget& view, int max_frames, double budget_s) {
  Timing t;
  t.first = orbitFrame(view);
  std::vector<double> ms;
  double spent = 0;
  while (static_cast<int>(ms.size()) < max_frames && (ms.size() < 3 || spent < budget_s * 1e3)) {
    ms.push_back(orbitFrame(view));
    spent += ms.back();
  }
  std::sort(ms.begin(), ms.end());
  t.median = ms[ms.size() / 2];
  t.max = ms.back();
  t.frames = static_cast<int>(ms.size());
  return t;
}

/// The peers: a plain vtkPolyDataMapper with default settings on a copy of the same data, or
/// a vtkPointGaussianMapper drawing plain points (scale factor 0) on the same copy.
vtkSmartPointer<vtkActor> peerActor(const plumb::PointCloud& cloud, double point_size,
                                    bool gaussian) {
  const auto n = static_cast<vtkIdType>(cloud.size());
  vtkNew<vtkPoints> points;  // float by default
  points->SetNumberOfPoints(n);
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const auto& p = cloud.positions[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.x(), p.y(), p.z());
    verts->InsertNextCell(1, &i);
    const auto& c = cloud.colors[static_cast<std::size_t>(i)];
    colors->SetTypedTuple(i, c.data());
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(colors);
  vtkSmartPointer<vtkPolyDataMapper> mapper;
  if (gaussian) {
    auto g = vtkSmartPointer<vtkPointGaussianMapper>::New();
    g->SetScaleFactor(0.0);
    g->EmissiveOff();
    mapper = g;
  } else {
    mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  }
  mapper->SetInputData(poly);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetPointSize(static_cast<float>(point_size));
  return actor;
}

/// Still frames after a camera stop: every frame the view paints (LodController's still
/// frame and its refinements) until no refinement is pending.
struct StillRun {
  std::vector<double> ms;
  std::size_t drawn = 0;
  double switch_ms = 0;  ///< UI thread time to switch to the still subset (subset rebuild)
};

StillRun stopCamera(plumb::ui::VtkViewWidget& view, plumb::ui::LodController& lod,
                    const plumb::ui::Scene& scene) {
  StillRun run;
  auto c = QObject::connect(&view, &plumb::ui::VtkViewWidget::frameRendered,
                            [&run](double ms) { run.ms.push_back(ms); });
  lod.stopMoving();
  QElapsedTimer switching;
  switching.start();
  lod.showStill();
  run.switch_ms = static_cast<double>(switching.nsecsElapsed()) / 1e6;
  QElapsedTimer wall;
  wall.start();
  while (wall.elapsed() < 600000 && (run.ms.empty() || lod.refinementPending()))
    QApplication::processEvents(QEventLoop::AllEvents, 20);
  QObject::disconnect(c);
  run.drawn = scene.drawnPointCount();
  return run;
}

/// "a+b+c" with `decimals` digits after the point.
std::string listMs(const std::vector<double>& ms, int decimals = 0) {
  std::string out;
  char buf[32];
  for (double m : ms) {
    std::snprintf(buf, sizeof buf, "%.*f", decimals, m);
    out += (out.empty() ? "" : "+") + std::string(buf);
  }
  return out.empty() ? "-" : out;
}

std::vector<std::size_t> parseSizes(const char* s) {
  std::vector<std::size_t> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stoull(item));
  return out;
}

/// Resident memory of this process, MB (VmRSS).
double residentMb() {
  FILE* f = std::fopen("/proc/self/status", "r");
  if (!f) return 0;
  char line[256];
  double kb = 0;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "VmRSS: %lf kB", &kb) == 1) break;
  std::fclose(f);
  return kb / 1024.0;
}

std::string glRenderer(plumb::ui::VtkViewWidget& view) {
  view.makeCurrent();
  const auto* r = view.context()->functions()->glGetString(GL_RENDERER);
  const auto* v = view.context()->functions()->glGetString(GL_VERSION);
  std::string out = std::string("OpenGL renderer: ") + (r ? reinterpret_cast<const char*>(r) : "?") +
                    ", " + (v ? reinterpret_cast<const char*>(v) : "?");
  view.doneCurrent();
  return out;
}

/// Longest freeze of the UI thread (5 ms timer) while `busy()`, the event loop running.
template <class Busy>
double longestStallMs(const Busy& busy) {
  plumb::ui::StallMeter meter(5);
  while (busy()) QApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
  return meter.longestMs();
}

double msSince(const QElapsedTimer& t) { return static_cast<double>(t.nsecsElapsed()) / 1e6; }

/// Adding and recolouring a layer as the application does it (background tasks).
struct AddTimes {
  double prepare = 0, wrap = 0;               ///< background preparation, UI-thread wrapping
  double bg_add_total = 0, bg_add_stall = 0;  ///< addDatasetInBackground
  double bg_style_total = 0, bg_style_request = 0, bg_style_stall = 0;  ///< requestStyle
};

AddTimes measureAdding(vtkRenderer* renderer, const std::shared_ptr<const plumb::Dataset>& data) {
  AddTimes t;
  plumb::ui::PointStyle elevation;
  elevation.mode = plumb::ui::PointColorMode::Elevation;
  {
    plumb::ui::Scene scene(renderer);
    QElapsedTimer clock;
    clock.start();
    plumb::ui::PreparedDataset prepared = plumb::ui::prepareDataset(data);
    t.prepare = msSince(clock);
    clock.restart();
    scene.addDataset(data, std::move(prepared));
    t.wrap = msSince(clock);
  }
  {
    plumb::ui::Scene scene(renderer);
    plumb::ui::TaskManager tasks;
    scene.setTaskManager(&tasks);
    plumb::ui::DatasetLayer* layer = nullptr;
    QElapsedTimer clock;
    clock.start();
    plumb::ui::addDatasetInBackground(tasks, scene, data,
                                      [&layer](plumb::ui::DatasetLayer& l) { layer = &l; });
    t.bg_add_stall = longestStallMs([&] { return tasks.runningCount() > 0; });
    t.bg_add_total = msSince(clock);
    if (!layer) return t;
    clock.restart();
    scene.requestStyle(*layer, elevation);
    t.bg_style_request = msSince(clock);
    t.bg_style_stall = longestStallMs([&] { return layer->coloringPending(); });
    t.bg_style_total = msSince(clock);
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  plumb::ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  std::vector<std::size_t> sizes{1'000'000, 5'000'000, 20'000'000};
  plumb::ui::LodBudget::Params budget_params;
  double point_size = 2.0, seconds = 12.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--sizes")) sizes = parseSizes(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--target-ms")) budget_params.target_ms = std::stod(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--point-size")) point_size = std::stod(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seconds")) seconds = std::stod(argv[i + 1]);
  }

  plumb::ui::VtkViewWidget view;
  view.resize(1280, 800);
  view.show();
  QApplication::processEvents();  // benchmark harness only: let the window map once
  view.renderNow();

  std::printf("bench_ui: %dx%d view, point size %.0f px, target %.0f ms per moving frame, "
              "%.0f ms per still frame\n",
              view.width(), view.height(), point_size, budget_params.target_ms,
              plumb::ui::LodController::kStillTargetMs);
  std::printf("  %s\n", glRenderer(view).c_str());
  {
    plumb::ui::Scene empty(view.renderer());
    const Timing e = measure(view, 10, 2.0);
    std::printf("  empty scene: median %.1f ms per frame (background + blit)\n", e.median);
  }
  std::printf("  %10s | %-27s | %-36s | %-10s | %-27s\n", "points", "plumb full first/median/max",
              "plumb LOD budget: median/max", "to full", "peer VTK first/median/max");
  for (const std::size_t n : sizes) {
    auto data = std::make_shared<const plumb::Dataset>(syntheticBuilding(n));
    Timing full, lod, peer, gauss;
    std::vector<StillRun> stills;
    std::vector<double> to_moving_ms, moving_first_ms, moving_next_ms;
    StillRun forced;
    double back_to_full = 0;
    const double rss_data = residentMb();
    double rss_layer = 0, add_ms = 0, style_ms = 0;
    std::size_t budget_points = 0;
    {
      plumb::ui::Scene scene(view.renderer());
      QElapsedTimer adding;
      adding.start();
      auto& layer = scene.addDataset(data);
      add_ms = static_cast<double>(adding.nsecsElapsed()) / 1e6;
      plumb::ui::PointStyle style = layer.style();
      style.point_size = point_size;
      style.mode = plumb::ui::PointColorMode::Elevation;  // a colour change: every point
      adding.restart();
      layer.setStyle(style);
      style_ms = static_cast<double>(adding.nsecsElapsed()) / 1e6;
      plumb::ui::resetCamera(view.renderer());
      full = measure(view, 15, seconds);
      rss_layer = residentMb();

      // Moving: the budget adapts from the frame times, as LodController does.
      plumb::ui::LodBudget budget(budget_params);
      scene.setLodBudget(budget.points());
      scene.setMovingDetail(true);
      orbitFrame(view);  // switch frame (subset upload), not measured
      for (int frame = 0; frame < 30; ++frame) {
        if (budget.addFrame(scene.drawnPointCount(), orbitFrame(view))) {
          scene.setLodBudget(budget.points());
          orbitFrame(view);  // the frame after a change uploads the new subset
        }
      }
      budget_points = scene.drawnPointCount();
      lod = measure(view, 15, seconds);
      scene.setMovingDetail(false);
      back_to_full = orbitFrame(view);

      // The application's controller: move (a few frames), stop, still frames; three times,
      // then once with "Full detail when still".
      plumb::ui::LodController controller(view, scene);
      for (int stop = 0; stop < 4; ++stop) {
        if (stop == 3) controller.setFullDetailWhenStill(true);
        QElapsedTimer switching;
        switching.start();
        controller.startMoving();
        to_moving_ms.push_back(static_cast<double>(switching.nsecsElapsed()) / 1e6);
        moving_first_ms.push_back(orbitFrame(view));
        moving_next_ms.push_back(orbitFrame(view));
        for (int frame = 0; frame < 4; ++frame) orbitFrame(view);
        (stop == 3 ? forced : stills.emplace_back()) = stopCamera(view, controller, scene);
      }
    }
    {
      auto actor = peerActor(data->scans[0].cloud, point_size, false);
      view.renderer()->AddActor(actor);
      peer = measure(view, 15, seconds);
      view.renderer()->RemoveActor(actor);
    }
    {
      auto actor = peerActor(data->scans[0].cloud, point_size, true);
      view.renderer()->AddActor(actor);
      gauss = measure(view, 15, seconds);
      view.renderer()->RemoveActor(actor);
    }
    std::printf("  %10zu | %8.0f %8.1f %8.1f ms | %8zu pts: %8.1f %8.1f ms | %7.0f ms | %8.0f %8.1f %8.1f ms\n",
                n, full.first, full.median, full.max, budget_points, lod.median, lod.max,
                back_to_full, peer.first, peer.median, peer.max);
    std::printf("  %10s | peer gauss first/median/max: %8.0f %8.1f %8.1f ms\n", "", gauss.first,
                gauss.median, gauss.max);
    for (std::size_t i = 0; i < stills.size(); ++i)
      std::printf("  %10s | still, stop %zu: frames %s ms, drawn %zu of %zu points (switch %.0f ms)\n",
                  "", i + 1, listMs(stills[i].ms).c_str(), stills[i].drawn, n, stills[i].switch_ms);
    std::printf("  %10s | memory: %.0f MB resident with the cloud, +%.0f MB with its layer after "
                "a full frame\n", "", rss_data, rss_layer - rss_data);
    {
      const AddTimes a = measureAdding(view.renderer(), data);
      std::printf("  %10s | add layer: all on the UI thread %.0f ms; background prepare %.0f ms + "
                  "UI-thread wrap %.1f ms; addDatasetInBackground total %.0f ms, longest UI "
                  "stall %.1f ms\n", "", add_ms, a.prepare, a.wrap, a.bg_add_total,
                  a.bg_add_stall);
      std::printf("  %10s | colour mode: all on the UI thread %.0f ms; requestStyle total %.0f ms, "
                  "UI thread %.1f ms to request, longest UI stall %.1f ms\n", "", style_ms,
                  a.bg_style_total, a.bg_style_request, a.bg_style_stall);
    }
    std::vector<double> to_still_ms;
    for (const auto& s : stills) to_still_ms.push_back(s.switch_ms);
    std::printf("  %10s | switch to moving: %s ms UI (first moving frame %s ms, next %s ms); "
                "to still: %s ms UI\n",
                "", listMs(to_moving_ms, 1).c_str(), listMs(moving_first_ms).c_str(),
                listMs(moving_next_ms).c_str(), listMs(to_still_ms, 1).c_str());
    std::printf("  %10s | still, forced full detail: frames %s ms, drawn %zu of %zu points\n", "",
                listMs(forced.ms).c_str(), forced.drawn, n);
    std::fflush(stdout);
  }
  return 0;
}
