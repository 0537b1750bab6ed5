#include "ui/registration/distance_check.hpp"

#include <QLabel>
#include <QObject>

#include "ui/layers/dataset_layer.hpp"
#include "ui/lod/detail_points.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/view/distance_legend.hpp"

namespace plumb::ui {

namespace {
constexpr int kHistogramBins = 40;

/// What was measured, how much matched, the figures of the magnitudes and, for signed
/// distances, the sign convention and the mean signed value (a bias along the normals).
QString statisticsLine(const DistanceResult& a, bool to_model, bool signed_values) {
  const QString what = to_model ? QObject::tr("cloud-to-mesh") : QObject::tr("cloud-to-cloud");
  QString line = QObject::tr("%1: %2 of %3 points matched; mean %4 m, median %5 m, 95%: %6 m, RMS %7 m")
                     .arg(what)
                     .arg(a.matched)
                     .arg(a.distances.size())
                     .arg(a.mean, 0, 'f', 4)
                     .arg(a.median, 0, 'f', 4)
                     .arg(a.p95, 0, 'f', 4)
                     .arg(a.rms, 0, 'f', 4);
  if (signed_values)
    line += QObject::tr("; signed: + in front of the target's surface (%1), - behind; mean signed %2 m")
                .arg(to_model ? QObject::tr("the side its triangles face") : QObject::tr("the scanner's side"))
                .arg(a.mean_signed, 0, 'f', 4);
  return line;
}
}  // namespace

DistanceCheck::DistanceCheck(Scene& scene, vtkRenderer* renderer, HistogramWidget& histogram,
                             QLabel& stats)
    : scene_(scene),
      histogram_(histogram),
      stats_(stats),
      legend_(std::make_unique<DistanceLegend>(renderer)) {}

DistanceCheck::~DistanceCheck() = default;

void DistanceCheck::show(std::shared_ptr<const LayerDistances> d, DatasetLayer& source,
                         const Layer& target, double max) {
  clear();
  distances_ = std::move(d);
  source_ = LayerRef(source);
  target_ = LayerRef(const_cast<Layer&>(target));
  const DistanceScale scale{max, distances_->signed_values};
  source.setDistances(distances_->per_scan, scale);
  if (distances_->target)
    source.setDistanceReference(std::make_shared<const DetailDistances>(
        DetailDistances{distances_->target, distances_->params, scale}));
  scene_.layerChanged(&source);
  legend_->show(scale, scale.signed_values ? QObject::tr("Signed distance (m)\n+ in front, - behind")
                                           : QObject::tr("Distance (m)"));
  histogram_.setHistogram(distanceHistogram(distances_->all.distances, scale.lo(), max, kHistogramBins));
  stats_.setText(statisticsLine(distances_->all, target.kind() == LayerKind::Model, scale.signed_values));
}

void DistanceCheck::clear() {
  if (auto* source = static_cast<DatasetLayer*>(source_.get()); source && source->hasDistances()) {
    source->clearDistances();
    scene_.layerChanged(source);
  }
  source_ = target_ = LayerRef();
  distances_.reset();
  legend_->hide();
  histogram_.setHistogram(DistanceHistogram{});
  stats_.clear();
}

bool DistanceCheck::involves(const Layer* layer) const {
  return layer && (source_.is(layer) || target_.is(layer));
}

bool DistanceCheck::legendVisible() const { return legend_->visible(); }

QString DistanceCheck::statistics() const { return stats_.text(); }

}  // namespace plumb::ui
