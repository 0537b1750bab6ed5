// Frame time of the view with N points (default 20 million): full detail (what is drawn when
// the camera is still) vs the level-of-detail subset (drawn while the camera moves). The
// camera orbits between frames as during interaction. Prints median and max per mode.
#include <QApplication>
#include <QElapsedTimer>

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
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

struct Stats {
  double median, max;
};

Stats measure(plumb::ui::VtkViewWidget& view, int frames) {
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) {
    view.renderer()->GetActiveCamera()->Azimuth(3.0);
    ms.push_back(view.renderNow());
  }
  std::sort(ms.begin(), ms.end());
  return {ms[ms.size() / 2], ms.back()};
}

}  // namespace

int main(int argc, char** argv) {
  plumb::ui::setDefaultSurfaceFormat();
  QApplication app(argc, argv);
  const std::size_t n = argc > 1 ? std::stoull(argv[1]) : 20'000'000;
  const int frames = 15;

  plumb::ui::VtkViewWidget view;
  view.resize(1280, 800);
  view.show();
  QApplication::processEvents();  // benchmark harness only: let the window map once

  QElapsedTimer t;
  t.start();
  auto data = std::make_shared<const plumb::Dataset>(syntheticBuilding(n));
  const double make_ms = static_cast<double>(t.restart());
  plumb::ui::Scene scene(view.renderer());
  scene.addDataset(data);
  const double layer_ms = static_cast<double>(t.restart());
  plumb::ui::resetCamera(view.renderer());
  const double first_ms = view.renderNow();  // includes the upload to the GPU

  const Stats full = measure(view, frames);
  scene.setReducedDetail(true);
  view.renderNow();  // first LOD frame uploads the subset
  const Stats lod = measure(view, frames);

  std::printf("bench_ui: %zu points, %dx%d view, %d frames per mode\n", n, view.width(),
              view.height(), frames);
  std::printf("  synthetic cloud %.0f ms, layer build (LOD subset + colours) %.0f ms, first frame %.0f ms\n",
              make_ms, layer_ms, first_ms);
  std::printf("  full detail : median %.1f ms (%.1f fps), max %.1f ms\n", full.median,
              1000.0 / full.median, full.max);
  std::printf("  LOD (%zu pts): median %.1f ms (%.1f fps), max %.1f ms\n",
              std::min<std::size_t>(n, plumb::ui::DatasetLayer::kLodPointBudget), lod.median,
              1000.0 / lod.median, lod.max);
  return 0;
}
