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

#include <nlohmann/json.hpp>

#include "registration/auto/pipeline_param_groups.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/param_panel.hpp"
#include "ui/registration/applied_registration.hpp"
#include "ui/registration/default_layers.hpp"
#include "ui/registration/distance_check.hpp"
#include "ui/registration/quality_report_view.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/tasks/task.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {
constexpr const char* kTopLevelGroup = "registration";
const RegistrationMethod kMethods[] = {RegistrationMethod::Auto, RegistrationMethod::Planes,
                                       RegistrationMethod::Openings, RegistrationMethod::Segments,
                                       RegistrationMethod::Icp};
/// The parameters the detected features depend on (the extraction groups), as text.
std::string extractionParams(const PipelineParams& params) {
  const nlohmann::json all = pipelineParamsToJson(params);
  nlohmann::json used;
  for (const char* key : {"plane-extraction", "opening-detection", "segment-detection",
                          "mesh-edges", "model-sample-spacing"})
    if (all.contains(key)) used[key] = all.at(key);
  return used.dump();
}
}  // namespace

RegistrationPanel::RegistrationPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      source_(new FocusWheel<QComboBox>(this)),
      target_(new FocusWheel<QComboBox>(this)),
      method_(new FocusWheel<QComboBox>(this)),
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
      applied_(new AppliedRegistration(app.scene, app.undo, this)),
      check_(std::make_unique<DistanceCheck>(app.scene, app.view.renderer(), *histogram_,
                                             *distance_stats_)) {
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

  for (QComboBox* c : {source_, target_})
    connect(c, &QComboBox::currentIndexChanged, this, &RegistrationPanel::updateFeaturesState);
  connect(method_, &QComboBox::currentIndexChanged, this, [this](int i) {
    params_.method = kMethods[i];
    for (int g = 0; g < groups_->count(); ++g)
      groups_->setItemEnabled(g, paramGroupUsedBy(panels_[std::size_t(g)].first, params_.method));
  });
  for (QComboBox* c : {source_, target_})
    connect(c, &QComboBox::activated, this, [this] { chosen_ = true; });
  connect(detect_, &QPushButton::clicked, this, [this] { detectFeatures(); });
  connect(register_, &QPushButton::clicked, this, [this] { startRegistration(); });
  connect(accept_, &QPushButton::clicked, this, &RegistrationPanel::accept);
  connect(revert_, &QPushButton::clicked, this, &RegistrationPanel::revert);
  connect(distance_, &QPushButton::clicked, this, [this] { colourByDistance(); });
  connect(before_, &QCheckBox::toggled, this, &RegistrationPanel::showBefore);
  connect(&app_.scene, &Scene::layersChanged, this, &RegistrationPanel::rebuildLayerCombos);
  connect(&app_.scene, &Scene::layerAboutToBeRemoved, this, &RegistrationPanel::forgetLayer);
  connect(applied_, &AppliedRegistration::changed, this, &RegistrationPanel::followAppliedResult);
  for (auto& [key, panel] : panels_)
    connect(panel, &ParamPanel::changed, this, &RegistrationPanel::updateFeaturesState);
  rebuildLayerCombos();
  updateEnabled();
}

RegistrationPanel::~RegistrationPanel() = default;

void RegistrationPanel::selectLayer(QComboBox& combo, const Layer* layer) {
  combo.setCurrentIndex(combo.findData(QVariant::fromValue(const_cast<void*>(static_cast<const void*>(layer)))));
}

bool RegistrationPanel::legendVisible() const { return check_->legendVisible(); }
std::shared_ptr<const LayerDistances> RegistrationPanel::lastDistances() const {
  return check_->distances();
}

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
  chosen_ = true;
  selectLayer(*source_, layer);
}
void RegistrationPanel::setTargetLayer(const Layer* layer) {
  chosen_ = true;
  selectLayer(*target_, layer);
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
  if (app_.scene.layers().empty()) chosen_ = false;
  // The user's choice while both are still there; until then (or after) the default pair.
  selectLayer(*source_, s);
  selectLayer(*target_, t);
  if (!chosen_ || !sourceLayer() || !targetLayer() || sourceLayer() == targetLayer()) {
    const LayerPair pair = defaultRegistrationPair(app_.scene.layers());
    selectLayer(*source_, pair.source);
    selectLayer(*target_, pair.target);
  }
  updateEnabled();
}

void RegistrationPanel::forgetLayer(Layer* layer) {
  if (applied_->layer() == layer) {
    applied_->forget();
    result_.reset();
    report_->clear();
  }
  if (check_->involves(layer)) check_->clear();
  updateEnabled();
}

void RegistrationPanel::followAppliedResult() {
  // Undone (Edit > Undo, Revert) or redone: the report and the distance check describe the
  // result only while it is in effect.
  const bool in_effect = applied_->inEffect();
  if (!in_effect) {
    if (before_->isChecked()) {
      before_->blockSignals(true);
      before_->setChecked(false);
      before_->blockSignals(false);
    }
    if (result_ && result_->success()) {
      report_->clear(tr("<i>The registration of %1 was undone.</i>")
                         .arg(applied_->layer() ? applied_->layer()->name() : QString()));
      if (check_->involves(applied_->layer())) check_->clear();
    }
  } else if (result_ && report_->level().isEmpty()) {
    report_->showResult(*result_);  // redone
  }
  updateEnabled();
}

void RegistrationPanel::updateEnabled() {
  const bool inputs = source_->count() >= 2;
  // A running task keeps the layers it started with: the choice of them waits.
  source_->setEnabled(!busy_);
  target_->setEnabled(!busy_);
  use_features_->setEnabled(!busy_);
  detect_->setEnabled(!busy_ && inputs);
  register_->setEnabled(!busy_ && inputs);
  distance_->setEnabled(!busy_ && inputs);
  accept_->setEnabled(applied_->undecided());
  revert_->setEnabled(applied_->undecided());
  before_->setEnabled(applied_->inEffect());
  updateFeaturesState();
}

bool RegistrationPanel::featuresUpToDate() const {
  const Layer* s = sourceLayer();
  const Layer* t = targetLayer();
  return s && t && featureOverlay(*s) && featureOverlay(*t) && features_.source.is(s) &&
         features_.target.is(t) && features_.params == extractionParams(params_);
}

void RegistrationPanel::updateFeaturesState() {
  const Layer* s = sourceLayer();
  const Layer* t = targetLayer();
  const bool shown = s && t && featureOverlay(*s) && featureOverlay(*t);
  if (shown && !featuresUpToDate()) {
    use_features_->setText(tr("Use detected features (out of date: detect again)"));
    use_features_->setToolTip(tr("The features shown were detected with other parameters or "
                                 "layers: registering extracts them again"));
  } else {
    use_features_->setText(tr("Use detected features"));
    use_features_->setToolTip(tr("Register with the features shown (detected with the same "
                                 "parameters); otherwise features are extracted again"));
  }
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
  const std::string params = extractionParams(params_);
  Task* task = startFeatureDetection(app_, *s, *t, params_, [this, s, t, params] {
    features_ = {LayerRef(*s), LayerRef(*t), params};  // called only while both exist
  });
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
  bool use_features = use_features_->isChecked();
  if (use_features && featureOverlay(*s) && featureOverlay(*t) && !featuresUpToDate()) {
    app_.log.warning(tr("The features shown were detected with other parameters or layers: "
                        "extracting them again"));
    use_features = false;
  }
  busy_ = true;
  updateEnabled();
  app_.log.info(tr("Registering %1 onto %2 (%3)")
                    .arg(s->name(), t->name(), QString::fromStdString(methodName(params_.method))));
  Task* task = ui::startRegistration(
      app_, *s, *t, params_, use_features,
      [this](std::shared_ptr<const PipelineResult> r, Layer& source, const RigidTransform& start) {
        applyResult(std::move(r), source, start);
      });
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

void RegistrationPanel::applyResult(std::shared_ptr<const PipelineResult> result, Layer& source,
                                    const RigidTransform& start) {
  // A new result: the previous one and its distance check no longer describe what is shown.
  check_->clear();
  applied_->forget();
  result_ = std::move(result);
  report_->showResult(*result_);
  for (const auto& line : result_->log) app_.log.info(QString::fromStdString(line));
  if (!result_->success()) {
    app_.log.error(tr("Registration failed: %1").arg(QString::fromStdString(result_->report.verdict)));
    return;
  }
  before_->blockSignals(true);
  before_->setChecked(false);
  before_->blockSignals(false);
  // The layer the task started with (not the one selected now), from where it was then.
  applied_->apply(source, start, result_->transform() * start,
                  tr("Register %1 (%2)").arg(source.name(), QString::fromStdString(result_->method_used)));
  if (result_->report.level == VerdictLevel::CheckVisually)
    app_.log.warning(tr("Check visually: %1").arg(QString::fromStdString(result_->report.verdict)));
  else
    app_.log.info(QString::fromStdString(result_->report.verdict));
  app_.view.requestRender();
}

void RegistrationPanel::accept() {
  if (!applied_->undecided()) return;
  app_.log.info(tr("Registration of %1 accepted").arg(applied_->layer()->name()));
  applied_->accept();
}

void RegistrationPanel::revert() {
  if (!applied_->undecided()) return;
  const QString name = applied_->layer()->name();
  before_->setChecked(false);
  applied_->revert();
  app_.log.info(tr("Registration of %1 reverted").arg(name));
}

void RegistrationPanel::showBefore(bool before) {
  if (before_->isChecked() != before) {
    before_->setChecked(before);  // re-enters through toggled
    return;
  }
  applied_->showBefore(before);
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
  Task* task = startDistanceComputation(
      app_, *s, *t, distance_params_,
      [this, max](std::shared_ptr<const LayerDistances> d, DatasetLayer& source, Layer& target) {
        check_->show(std::move(d), source, target, max);
        app_.log.info(check_->statistics());
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
