#include "ui/registration/manual_align_panel.hpp"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include "ui/app_context.hpp"
#include "ui/inspection/measure_tool.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/pair_markers.hpp"
#include "ui/registration/point_picking.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/transform_command.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {
enum Column { kLabel, kUse, kSource, kTarget, kResidual, kColumns };
}  // namespace

ManualAlignPanel::ManualAlignPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      markers_(std::make_unique<PairMarkers>(app.view.renderer())),
      table_(new QTableWidget(0, kColumns, this)),
      levelled_(new QCheckBox(tr("Levelled (turn about the vertical only)"), this)),
      status_(new QLabel(this)),
      pick_(new QPushButton(tr("Pick pairs"), this)),
      align_(new QPushButton(tr("Align"), this)),
      refine_(new QPushButton(tr("Refine (ICP)"), this)) {
  setObjectName("manualAlignPanel");
  auto* layout = new QVBoxLayout(this);
  auto* help = new QLabel(tr("Source and target are those of the Registration dock. Click a "
                             "point of the source, then the same point on the target; at "
                             "least 3 pairs, spread out (2 when levelled). Untick a pair to "
                             "keep it as a check point."), this);
  help->setWordWrap(true);
  layout->addWidget(help);
  table_->setObjectName("pairsTable");
  table_->setHorizontalHeaderLabels({tr("Pair"), tr("Use"), tr("Source (data frame)"), tr("Target"), tr("Residual (m)")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(table_, 1);
  levelled_->setObjectName("levelledPairs");
  levelled_->setToolTip(tr("For scans levelled by the scanner's tilt compensator: only the heading "
                           "and the shift are fitted"));
  layout->addWidget(levelled_);
  status_->setWordWrap(true);
  status_->setObjectName("manualStatus");
  layout->addWidget(status_);
  auto* buttons = new QHBoxLayout;
  pick_->setCheckable(true);
  pick_->setObjectName("pickPairs");
  align_->setObjectName("alignPairs");
  refine_->setObjectName("refinePairs");
  auto* clear = new QPushButton(tr("Clear"), this);
  for (QPushButton* b : {pick_, align_, refine_, clear}) buttons->addWidget(b);
  layout->addLayout(buttons);
  connect(align_, &QPushButton::clicked, this, [this] { align(); });
  connect(refine_, &QPushButton::clicked, this, [this] { refine(); });
  connect(clear, &QPushButton::clicked, this, &ManualAlignPanel::clearPairs);
  connect(levelled_, &QCheckBox::toggled, this, [this] {
    updateFit();
    refreshTable();
  });
  connect(table_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
    if (!filling_table_ && item->column() == kUse) setPairUsed(item->row(), item->checkState() == Qt::Checked);
  });
  connect(&app_.view, &VtkViewWidget::clicked, this, &ManualAlignPanel::onClicked);
  connect(&app_.undo, &QUndoStack::indexChanged, this, [this] { refreshMarkers(); });  // the source moved
  refreshTable();
}

ManualAlignPanel::~ManualAlignPanel() = default;

bool ManualAlignPanel::picking() const { return pick_->isChecked(); }
void ManualAlignPanel::setPicking(bool on) { pick_->setChecked(on); }

void ManualAlignPanel::addPair(const Eigen::Vector3d& s, const Eigen::Vector3d& t) {
  source_.resize(target_.size());  // a dangling source pick gives way
  source_.push_back(s);
  target_.push_back(t);
  used_.push_back(true);
  have_source_pick_ = false;
  updateFit();
  refreshTable();
}

void ManualAlignPanel::addWorldPair(const Eigen::Vector3d& s, const Eigen::Vector3d& t) {
  Layer* source = app_.registration ? app_.registration->sourceLayer() : nullptr;
  const RigidTransform to_data = source ? layerTransform(*source).inverse() : RigidTransform();
  addPair(to_data.apply(s), t);
}

void ManualAlignPanel::clearPairs() {
  source_.clear();
  target_.clear();
  used_.clear();
  fit_.reset();
  have_source_pick_ = false;
  status_->clear();
  refreshTable();
}

double ManualAlignPanel::residual(int i) const {
  return fit_ && i >= 0 && std::size_t(i) < fit_->residuals.size() ? fit_->residuals[std::size_t(i)] : -1.0;
}

void ManualAlignPanel::setPairUsed(int i, bool used) {
  if (i < 0 || std::size_t(i) >= used_.size() || used_[std::size_t(i)] == used) return;
  used_[std::size_t(i)] = used;
  updateFit();
  refreshTable();
}

bool ManualAlignPanel::pairUsed(int i) const { return i >= 0 && std::size_t(i) < used_.size() && used_[std::size_t(i)]; }

void ManualAlignPanel::setLevelled(bool levelled) { levelled_->setChecked(levelled); }

QStringList ManualAlignPanel::markerLabels() const { return markers_->labels(); }

void ManualAlignPanel::onClicked(int x, int y) {
  if (!picking() || !app_.registration || (app_.measure && app_.measure->active())) return;
  Layer* layer = have_source_pick_ ? app_.registration->targetLayer()
                                   : app_.registration->sourceLayer();
  if (!layer) return;
  const auto p = pickLayerPoint(app_.view.renderer(), app_.scene, *layer, x, y);
  if (!p) {
    status_->setText(tr("No point of %1 under the cursor").arg(layer->name()));
    return;
  }
  if (!have_source_pick_) {
    source_.push_back(layerTransform(*layer).inverse().apply(*p));
    have_source_pick_ = true;
    status_->setText(tr("Source point S%1 picked; now click the same point on %2")
                         .arg(source_.size())
                         .arg(app_.registration->targetLayer()
                                  ? app_.registration->targetLayer()->name()
                                  : tr("the target")));
  } else {
    target_.push_back(*p);
    used_.push_back(true);
    have_source_pick_ = false;
    updateFit();
  }
  refreshTable();
}

PairAlignmentParams ManualAlignPanel::fitParams() const {
  PairAlignmentParams p;
  p.used = used_;
  p.levelled = levelled_->isChecked();
  return p;
}

void ManualAlignPanel::updateFit() {
  fit_.reset();
  const std::size_t n = target_.size();
  if (n == 0) return;
  try {
    fit_ = alignPointPairs(std::span(source_.data(), n), target_, fitParams());
    QString text = tr("Fit of %1 pair(s)%2: RMS %3 m")
                       .arg(fit_->used)
                       .arg(levelled_->isChecked() ? tr(", levelled") : QString())
                       .arg(fit_->rms, 0, 'f', 4);
    if (fit_->used < n) text += tr("; %1 check pair(s): RMS %2 m").arg(n - fit_->used).arg(fit_->check_rms, 0, 'f', 4);
    status_->setText(text);
  } catch (const std::exception& e) {
    status_->setText(tr("%1 pair(s): %2").arg(n).arg(QString::fromUtf8(e.what())));
  }
}

bool ManualAlignPanel::align() {
  Layer* source = app_.registration ? app_.registration->sourceLayer() : nullptr;
  if (!source) {
    app_.log.error(tr("Manual alignment: choose a source in the Registration dock"));
    return false;
  }
  const std::size_t n = target_.size();  // a dangling source pick is ignored
  try {
    fit_ = alignPointPairs(std::span(source_.data(), n), target_, fitParams());
    app_.undo.push(new TransformCommand(app_.scene, *source, layerTransform(*source), fit_->transform,
                                        tr("Manual alignment of %1").arg(source->name())));
    status_->setText(tr("Aligned with %1 pairs: RMS %2 m").arg(fit_->used).arg(fit_->rms, 0, 'f', 4));
    app_.log.info(tr("Manual alignment of %1: %2 pairs%3, RMS %4 m")
                      .arg(source->name())
                      .arg(fit_->used)
                      .arg(levelled_->isChecked() ? tr(" (levelled)") : QString())
                      .arg(fit_->rms, 0, 'f', 4));
  } catch (const std::exception& e) {
    status_->setText(QString::fromUtf8(e.what()));
    app_.log.error(tr("Manual alignment: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
  refreshTable();
  return true;
}

bool ManualAlignPanel::refine() {
  if (!app_.registration) return false;
  app_.registration->setMethod(RegistrationMethod::Icp);
  return app_.registration->startRegistration();
}

void ManualAlignPanel::refreshTable() {
  auto fmt = [](const Eigen::Vector3d& p) {
    return QString("%1, %2, %3").arg(p.x(), 0, 'f', 3).arg(p.y(), 0, 'f', 3).arg(p.z(), 0, 'f', 3);
  };
  filling_table_ = true;
  table_->setRowCount(int(source_.size()));
  for (std::size_t i = 0; i < source_.size(); ++i) {
    const int r = int(i);
    table_->setItem(r, kLabel, new QTableWidgetItem(QString::number(i + 1)));
    auto* use = new QTableWidgetItem;
    use->setFlags(Qt::ItemIsUserCheckable | Qt::ItemIsEnabled);
    use->setCheckState(i >= used_.size() || used_[i] ? Qt::Checked : Qt::Unchecked);
    use->setToolTip(tr("In the fit; unticked: a check point, its residual still shown"));
    table_->setItem(r, kUse, use);
    table_->setItem(r, kSource, new QTableWidgetItem(fmt(source_[i])));
    table_->setItem(r, kTarget, new QTableWidgetItem(i < target_.size() ? fmt(target_[i]) : tr("(pick)")));
    const double e = residual(r);
    table_->setItem(r, kResidual, new QTableWidgetItem(e >= 0 ? QString::number(e, 'f', 4) : QString()));
  }
  filling_table_ = false;
  align_->setEnabled(fit_.has_value());
  refreshMarkers();
}

void ManualAlignPanel::refreshMarkers() {
  Layer* source = app_.registration ? app_.registration->sourceLayer() : nullptr;
  const RigidTransform shown = source ? layerTransform(*source) : RigidTransform();
  std::vector<PairMarker> markers;
  for (std::size_t i = 0; i < source_.size(); ++i) {
    const bool used = i >= used_.size() || used_[i];
    const QString n = QString::number(i + 1);
    markers.push_back({shown.apply(source_[i]), "S" + n, true, used});
    if (i < target_.size()) markers.push_back({target_[i], "T" + n, false, used});
  }
  markers_->show(markers, app_.scene.origin());
  app_.view.requestRender();
}

}  // namespace plumb::ui
