#include "ui/lod/detail_cache_task.hpp"

#include <QStandardPaths>

#include <algorithm>
#include <cstdlib>

#include "io/lod/lod_builder.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_layer.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

std::filesystem::path lodCacheRoot() {
  if (const char* dir = std::getenv("PLUMB_LOD_CACHE_DIR"); dir && *dir) return dir;
  return std::filesystem::path(QStandardPaths::writableLocation(QStandardPaths::CacheLocation).toStdString()) / "lod";
}

namespace {

/// What the task found or built.
struct OpenedCache {
  std::shared_ptr<const LodCache> cache;
  bool built = false;
  std::string why_built;  ///< openLodCache's reason when it was rebuilt
  double seconds = 0;
};

OpenedCache openOrBuild(const std::filesystem::path& source, const std::filesystem::path& root,
                        double budget_mb, Progress& progress) {
  LodCacheOpenResult open = openLodCache(source, root);
  OpenedCache out;
  if (!open.valid()) {
    out.built = true;
    out.why_built = open.reason;
    LodCacheParams params;
    params.memory_budget_mb = budget_mb;
    out.seconds = buildLodCache(source, root, params, &progress).seconds;
    open = openLodCache(source, root);
    if (!open.valid()) throw std::runtime_error("the level-of-detail cache just built cannot be opened: " + open.reason);
  }
  out.cache = open.cache;
  return out;
}

}  // namespace

Task* startDetailCache(AppContext& app, DatasetLayer& layer, std::uint64_t budget_share) {
  const std::filesystem::path source = layer.dataset().source;
  const std::filesystem::path root = lodCacheRoot();
  // An eighth of the file's share for the build's buckets (64 MB .. 1 GB): the subsample shown
  // and a registration keep the rest.
  const double budget_mb = std::clamp(double(budget_share) / 8.0 / (1024.0 * 1024.0), 64.0, 1024.0);
  const LayerRef held(layer);
  const QString name = layer.name();
  return app.tasks.run(
      QObject::tr("Building the detail cache of %1").arg(name),
      [&app, source, root, budget_mb, held, name](Progress& progress) -> Task::Apply {
        auto opened = std::make_shared<OpenedCache>(openOrBuild(source, root, budget_mb, progress));
        return [&app, opened, held, name] {
          Layer* target = held.get();
          if (!target) return;  // the dataset was removed meanwhile
          auto& dataset = static_cast<DatasetLayer&>(*target);
          auto detail = std::make_unique<DetailLayer>(opened->cache, app.scene.origin());
          detail->setDatasetTransform(dataset.shownTransform());
          detail->setPointSize(dataset.style().point_size);
          app.scene.addDetail(std::move(detail), dataset);
          const double mb = double(opened->cache->bytesOnDisk()) / 1e6;
          if (opened->built)
            app.log.info(QObject::tr("%1: level-of-detail cache built in %2 s (%3 MB, %4)")
                             .arg(name).arg(opened->seconds, 0, 'f', 1).arg(mb, 0, 'f', 1)
                             .arg(QString::fromStdString(opened->cache->directory().string())));
          else
            app.log.info(QObject::tr("%1: level-of-detail cache reused (%2 MB, %3)")
                             .arg(name).arg(mb, 0, 'f', 1)
                             .arg(QString::fromStdString(opened->cache->directory().string())));
        };
      });
}

}  // namespace plumb::ui
