#include "ui/registration/manual_align_panel.hpp"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QVBoxLayout>

#include "registration/common/pair_alignment.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/point_picking.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/registration/transform_command.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

ManualAlignPanel::ManualAlignPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      table_(new QTableWidget(0, 3, this)),
      status_(new QLabel(this)),
      pick_(new QPushButton(tr("Pick pairs"), this)),
      align_(new QPushButton(tr("Align"), this)),
      refine_(new QPushButton(tr("Refine (ICP)"), this)) {
  setObjectName("manualAlignPanel");
  auto* layout = new QVBoxLayout(this);
  auto* help = new QLabel(tr("Source and target are those of the Registration dock. Click a "
                             "point of the source, then the same point on the target; at "
                             "least 3 pairs, spread out."), this);
  help->setWordWrap(true);
  layout->addWidget(help);
  table_->setObjectName("pairsTable");
  table_->setHorizontalHeaderLabels({tr("Source (data frame)"), tr("Target"), tr("Residual (m)")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  layout->addWidget(table_, 1);
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
  connect(&app_.view, &VtkViewWidget::clicked, this, &ManualAlignPanel::onClicked);
  refreshTable();
}

bool ManualAlignPanel::picking() const { return pick_->isChecked(); }
void ManualAlignPanel::setPicking(bool on) { pick_->setChecked(on); }

void ManualAlignPanel::addPair(const Eigen::Vector3d& s, const Eigen::Vector3d& t) {
  source_.push_back(s);
  target_.push_back(t);
  residuals_.clear();
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
  residuals_.clear();
  have_source_pick_ = false;
  refreshTable();
}

double ManualAlignPanel::residual(int i) const {
  return i >= 0 && std::size_t(i) < residuals_.size() ? residuals_[std::size_t(i)] : -1.0;
}

void ManualAlignPanel::onClicked(int x, int y) {
  if (!picking() || !app_.registration) return;
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
    status_->setText(tr("Source point picked; now click the same point on %1")
                         .arg(app_.registration->targetLayer()
                                  ? app_.registration->targetLayer()->name()
                                  : tr("the target")));
  } else {
    target_.push_back(*p);
    have_source_pick_ = false;
    residuals_.clear();
    status_->setText(tr("%1 pair(s)").arg(target_.size()));
  }
  refreshTable();
}

bool ManualAlignPanel::align() {
  Layer* source = app_.registration ? app_.registration->sourceLayer() : nullptr;
  if (!source) {
    app_.log.error(tr("Manual alignment: choose a source in the Registration dock"));
    return false;
  }
  const std::size_t n = target_.size();  // a dangling source pick is ignored
  try {
    const PairAlignmentResult r = alignPointPairs(std::span(source_.data(), n), target_);
    residuals_ = r.residuals;
    app_.undo.push(new TransformCommand(app_.scene, *source, layerTransform(*source), r.transform,
                                        tr("Manual alignment of %1").arg(source->name())));
    status_->setText(tr("Aligned with %1 pairs: RMS %2 m").arg(n).arg(r.rms, 0, 'f', 4));
    app_.log.info(tr("Manual alignment of %1: %2 pairs, RMS %3 m")
                      .arg(source->name())
                      .arg(n)
                      .arg(r.rms, 0, 'f', 4));
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
  table_->setRowCount(int(source_.size()));
  for (std::size_t i = 0; i < source_.size(); ++i) {
    const int r = int(i);
    table_->setItem(r, 0, new QTableWidgetItem(fmt(source_[i])));
    table_->setItem(r, 1, new QTableWidgetItem(i < target_.size() ? fmt(target_[i]) : tr("(pick)")));
    table_->setItem(r, 2, new QTableWidgetItem(i < residuals_.size()
                                                   ? QString::number(residuals_[i], 'f', 4)
                                                   : QString()));
  }
  align_->setEnabled(target_.size() >= 3);
}

}  // namespace plumb::ui
