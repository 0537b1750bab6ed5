#include "ui/registration/registration_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QToolBox>
#include <QUndoStack>
#include <QVBoxLayout>

#include "registration/auto/pipeline_param_groups.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/param_panel.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/registration/transform_command.hpp"
#include "ui/tasks/task.hpp"
#include "ui/view/distance_legend.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {
constexpr int kHistogramBins = 40;
constexpr const char* kTopLevelGroup = "registration";
const RegistrationMethod kMethods[] = {RegistrationMethod::Auto, RegistrationMethod::Planes,
                                       RegistrationMethod::Openings, RegistrationMethod::Segments,
                                       RegistrationMethod::Icp};
}  // namespace

RegistrationPanel::RegistrationPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      source_(new QComboBox(this)),
      target_(new QComboBox(this)),
      method_(new QComboBox(this)),
      use_features_(new QCheckBox(tr("Use detected features"), this)),
      groups_(new QToolBox(this)),
      detect_(new QPushButton(tr("Detect features"), this)),
      register_(new QPushButton(tr("Register"), this)),
      accept_(new QPushButton(tr("Accept"), this)),
      revert_(new QPushButton(tr("Revert"), this)),
      distance_(new QPushButton(tr("Colour by distance"), this)),
      before_(new QCheckBox(tr("Show before registration"), this)),
      report_(new QualityReportView(this)),
      histogram_(new HistogramWidget(this)),
      distance_stats_(new QLabel(this)),
      legend_(std::make_unique<DistanceLegend>(app.view.renderer())) {
  setObjectName("registrationPanel");
  source_->setObjectName("sourceLayer");
  target_->setObjectName("targetLayer");
  method_->setObjectName("method");
  detect_->setObjectName("detectFeatures");
  register_->setObjectName("register");
  accept_->setObjectName("acceptResult");
  revert_->setObjectName("revertResult");
  distance_->setObjectName("colourByDistance");
  before_->setObjectName("showBefore");
  use_features_->setObjectName("useFeatures");
  use_features_->setChecked(true);
  use_features_->setToolTip(tr("Register with the features shown (detected with the same "
                               "parameters); otherwise features are extracted again"));
  for (auto m : kMethods) method_->addItem(QString::fromStdString(methodName(m)));
  method_->setToolTip(tr("auto: planes for two scans (openings, then segments if planes fail), "
                         "segments for a model; icp: local refinement only"));

  auto* layout = new QVBoxLayout(this);
  auto* form = new QFormLayout;
  form->addRow(tr("Source (moves)"), source_);
  form->addRow(tr("Target (reference)"), target_);
  form->addRow(tr("Method"), method_);
  form->addRow(use_features_);
  layout->addLayout(form);

  auto addGroup = [this](const char* key, const char* label, ParamPanel* panel) {
    auto* scroll = new QScrollArea;
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    groups_->addItem(scroll, tr(label));
    panels_.emplace_back(key, panel);
  };
  // The top-level parameters (the one seed, refine, ...) first; the method has its combo box.
  addGroup(kTopLevelGroup, "Registration", makeParamPanel(PipelineParams::schema(), params_, {"method"}));
  forEachParamGroup(params_, [&addGroup](const char* key, const char* label, const auto& schema, auto& group) {
    addGroup(key, label, makeParamPanel(schema, group));
  });
  groups_->setMinimumHeight(220);
  layout->addWidget(groups_, 1);

  auto* buttons = new QHBoxLayout;
  buttons->addWidget(detect_);
  buttons->addWidget(register_);
  layout->addLayout(buttons);

  auto* result = new QGroupBox(tr("Result"), this);
  auto* rl = new QVBoxLayout(result);
  rl->addWidget(report_, 1);
  rl->addWidget(before_);
  auto* keep = new QHBoxLayout;
  keep->addWidget(accept_);
  keep->addWidget(revert_);
  rl->addLayout(keep);
  layout->addWidget(result, 1);

  auto* qa = new QGroupBox(tr("Visual check"), this);
  auto* ql = new QVBoxLayout(qa);
  distance_panel_ = makeParamPanel(DistanceParams::schema(), distance_params_, qa);
  ql->addWidget(distance_panel_);
  ql->addWidget(distance_);
  ql->addWidget(histogram_);
  distance_stats_->setObjectName("distanceStats");
  distance_stats_->setWordWrap(true);
  ql->addWidget(distance_stats_);
  layout->addWidget(qa);

  connect(method_, &QComboBox::currentIndexChanged, this, [this](int i) {
    params_.method = kMethods[i];
    for (int g = 0; g < groups_->count(); ++g)
      groups_->setItemEnabled(g, paramGroupUsedBy(panels_[std::size_t(g)].first, params_.method));
  });
  connect(detect_, &QPushButton::clicked, this, [this] { detectFeatures(); });
  connect(register_, &QPushButton::clicked, this, [this] { startRegistration(); });
  connect(accept_, &QPushButton::clicked, this, &RegistrationPanel::accept);
  connect(revert_, &QPushButton::clicked, this, &RegistrationPanel::revert);
  connect(distance_, &QPushButton::clicked, this, [this] { colourByDistance(); });
  connect(before_, &QCheckBox::toggled, this, &RegistrationPanel::showBefore);
  connect(&app_.scene, &Scene::layersChanged, this, &RegistrationPanel::rebuildLayerCombos);
  connect(&app_.scene, &Scene::layerAboutToBeRemoved, this, &RegistrationPanel::forgetLayer);
  rebuildLayerCombos();
  updateEnabled();
}

RegistrationPanel::~RegistrationPanel() = default;

bool RegistrationPanel::legendVisible() const { return legend_->visible(); }

void RegistrationPanel::refreshParams() {
  for (auto& [key, panel] : panels_) panel->refresh();
  distance_panel_->refresh();
  for (std::size_t i = 0; i < std::size(kMethods); ++i)
    if (kMethods[i] == params_.method) method_->setCurrentIndex(int(i));
}

Layer* RegistrationPanel::sourceLayer() const {
  return static_cast<Layer*>(source_->currentData().value<void*>());
}
Layer* RegistrationPanel::targetLayer() const {
  return static_cast<Layer*>(target_->currentData().value<void*>());
}

void RegistrationPanel::setSourceLayer(const Layer* layer) {
  source_->setCurrentIndex(source_->findData(QVariant::fromValue(const_cast<void*>(static_cast<const void*>(layer)))));
}
void RegistrationPanel::setTargetLayer(const Layer* layer) {
  target_->setCurrentIndex(target_->findData(QVariant::fromValue(const_cast<void*>(static_cast<const void*>(layer)))));
}

void RegistrationPanel::setMethod(RegistrationMethod method) {
  for (std::size_t i = 0; i < std::size(kMethods); ++i)
    if (kMethods[i] == method) method_->setCurrentIndex(int(i));
}

void RegistrationPanel::rebuildLayerCombos() {
  Layer* s = sourceLayer();
  Layer* t = targetLayer();
  for (QComboBox* c : {source_, target_}) {
    c->blockSignals(true);
    c->clear();
    for (const auto& l : app_.scene.layers())
      if (isRegistrable(l.get()))
        c->addItem(l->name() + " (" + layerKindName(l->kind()) + ")",
                   QVariant::fromValue(static_cast<void*>(l.get())));
    c->blockSignals(false);
  }
  // Defaults: the first layer moves onto the second.
  if (s) setSourceLayer(s);
  if (t) setTargetLayer(t);
  else if (target_->count() > 1) target_->setCurrentIndex(1);
  updateEnabled();
}

void RegistrationPanel::forgetLayer(Layer* layer) {
  if (layer == result_layer_) {
    result_layer_ = nullptr;
    pushed_ = nullptr;
    before_->setChecked(false);
  }
  if (layer == sourceLayer() || layer == targetLayer()) legend_->hide();
  updateEnabled();
}

void RegistrationPanel::updateEnabled() {
  const bool inputs = source_->count() >= 2;
  detect_->setEnabled(!busy_ && inputs);
  register_->setEnabled(!busy_ && inputs);
  distance_->setEnabled(!busy_ && inputs);
  const bool has_result = result_layer_ && result_ && result_->success();
  accept_->setEnabled(has_result && pushed_);
  revert_->setEnabled(has_result && pushed_);
  before_->setEnabled(has_result);
}

bool RegistrationPanel::checkInputs(Layer*& source, Layer*& target) {
  source = sourceLayer();
  target = targetLayer();
  if (busy_) {
    app_.log.warning(tr("Registration: a task is already running"));
    return false;
  }
  if (!source || !target) {
    app_.log.error(tr("Registration: open a source and a target first"));
    return false;
  }
  if (source == target) {
    app_.log.error(tr("Registration: the source and the target are the same layer"));
    return false;
  }
  return true;
}

bool RegistrationPanel::detectFeatures() {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  busy_ = true;
  updateEnabled();
  app_.log.info(tr("Detecting features on %1 and %2").arg(s->name(), t->name()));
  Task* task = startFeatureDetection(app_, *s, *t, params_);
  connect(task, &Task::finished, this, [this](bool ok, const QString& message) {
    busy_ = false;
    updateEnabled();
    if (!ok) app_.log.error(tr("Feature detection failed: %1").arg(message));
    emit featuresDetected(ok);
  });
  return true;
}

bool RegistrationPanel::startRegistration() {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  busy_ = true;
  updateEnabled();
  app_.log.info(tr("Registering %1 onto %2 (%3)")
                    .arg(s->name(), t->name(), QString::fromStdString(methodName(params_.method))));
  Task* task = ui::startRegistration(app_, *s, *t, params_, use_features_->isChecked(),
                                 [this](std::shared_ptr<const PipelineResult> r) { applyResult(r); });
  connect(task, &Task::finished, this, [this](bool ok, const QString& message) {
    busy_ = false;
    updateEnabled();
    if (!ok) {
      app_.log.error(tr("Registration stopped: %1").arg(message));
      emit registrationFinished(false);
      return;
    }
    emit registrationFinished(result_ && result_->success());
  });
  return true;
}

void RegistrationPanel::applyResult(std::shared_ptr<const PipelineResult> result) {
  result_ = std::move(result);
  report_->showResult(*result_);
  for (const auto& line : result_->log) app_.log.info(QString::fromStdString(line));
  if (!result_->success()) {
    app_.log.error(tr("Registration failed: %1").arg(QString::fromStdString(result_->report.verdict)));
    return;
  }
  Layer* s = sourceLayer();
  if (!s) return;
  before_->blockSignals(true);
  before_->setChecked(false);
  before_->blockSignals(false);
  result_layer_ = s;
  before_transform_ = layerTransform(*s);
  after_transform_ = result_->transform() * before_transform_;
  auto* command = new TransformCommand(app_.scene, *s, before_transform_, after_transform_,
                                       tr("Register %1 (%2)").arg(s->name(),
                                                                  QString::fromStdString(result_->method_used)));
  app_.undo.push(command);  // applies it
  pushed_ = command;
  legend_->hide();
  if (result_->report.level == VerdictLevel::CheckVisually)
    app_.log.warning(tr("Check visually: %1").arg(QString::fromStdString(result_->report.verdict)));
  else
    app_.log.info(QString::fromStdString(result_->report.verdict));
  app_.view.requestRender();
}

void RegistrationPanel::accept() {
  if (!pushed_) return;
  app_.log.info(tr("Registration of %1 accepted").arg(result_layer_ ? result_layer_->name() : QString()));
  pushed_ = nullptr;
  updateEnabled();
}

void RegistrationPanel::revert() {
  if (!pushed_ || !result_layer_) return;
  showBefore(false);
  const int i = app_.undo.index();
  if (i > 0 && app_.undo.command(i - 1) == pushed_) {
    app_.undo.undo();
  } else {
    app_.undo.push(new TransformCommand(app_.scene, *result_layer_, layerTransform(*result_layer_),
                                        before_transform_, tr("Revert %1").arg(result_layer_->name())));
  }
  app_.log.info(tr("Registration of %1 reverted").arg(result_layer_->name()));
  pushed_ = nullptr;
  updateEnabled();
}

void RegistrationPanel::showBefore(bool before) {
  if (before_->isChecked() != before) {
    before_->setChecked(before);  // re-enters through toggled
    return;
  }
  if (!result_layer_) return;
  setLayerTransform(app_.scene, *result_layer_, before ? before_transform_ : after_transform_);
}

bool RegistrationPanel::colourByDistance() {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  if (s->kind() != LayerKind::Dataset) {
    app_.log.error(tr("Colour by distance: the source must be a point dataset"));
    return false;
  }
  busy_ = true;
  updateEnabled();
  const double max = distance_params_.max_distance;
  auto* source = static_cast<DatasetLayer*>(s);
  const QString what = t->kind() == LayerKind::Model ? tr("cloud-to-mesh") : tr("cloud-to-cloud");
  Task* task = startDistanceComputation(
      app_, *s, *t, distance_params_,
      [this, source, max, what](std::shared_ptr<const LayerDistances> d) {
        distances_ = d;
        source->setDistances(d->per_scan, max);
        app_.scene.layerChanged(source);
        legend_->show(max, tr("Distance (m)"));
        histogram_->setHistogram(distanceHistogram(d->all.distances, 0.0, max, kHistogramBins));
        const DistanceResult& a = d->all;
        distance_stats_->setText(tr("%1: %2 of %3 points matched; mean %4 m, median %5 m, "
                                    "95%: %6 m, RMS %7 m")
                                     .arg(what)
                                     .arg(a.matched)
                                     .arg(a.distances.size())
                                     .arg(a.mean, 0, 'f', 4)
                                     .arg(a.median, 0, 'f', 4)
                                     .arg(a.p95, 0, 'f', 4)
                                     .arg(a.rms, 0, 'f', 4));
        app_.log.info(distance_stats_->text());
      });
  connect(task, &Task::finished, this, [this](bool ok, const QString& message) {
    busy_ = false;
    updateEnabled();
    if (!ok) app_.log.error(tr("Distance computation failed: %1").arg(message));
    emit distancesComputed(ok);
  });
  return true;
}

}  // namespace plumb::ui
