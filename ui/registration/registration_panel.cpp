#include "ui/registration/registration_panel.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/focus_wheel.hpp"
#include "ui/panels/histogram_widget.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/param_panel.hpp"
#include "ui/registration/distance_check.hpp"
#include "ui/registration/layer_pair_combos.hpp"
#include "ui/registration/param_groups_box.hpp"
#include "ui/registration/registration_result_box.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {
const RegistrationMethod kMethods[] = {RegistrationMethod::Auto, RegistrationMethod::Planes,
                                       RegistrationMethod::Openings, RegistrationMethod::Segments,
                                       RegistrationMethod::Icp};
template <class W>
W* named(W* widget, const char* name) {
  widget->setObjectName(name);
  return widget;
}
}  // namespace

RegistrationPanel::RegistrationPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      runner_(new RegistrationRunner(app, this)),
      layers_(new LayerPairCombos(app.scene, this)),
      method_(named(new FocusWheel<QComboBox>(this), "method")),
      use_features_(named(new QCheckBox(this), "useFeatures")),
      groups_(new ParamGroupsBox(runner_->params(), this)),
      detect_(named(new QPushButton(tr("Detect features"), this), "detectFeatures")),
      register_(named(new QPushButton(tr("Register"), this), "register")),
      distance_(named(new QPushButton(tr("Colour by distance"), this), "colourByDistance")),
      result_(new RegistrationResultBox(*runner_, this)),
      histogram_(new HistogramWidget(this)),
      distance_stats_(named(new QLabel(this), "distanceStats")),
      check_(std::make_unique<DistanceCheck>(app.scene, app.view.renderer(), *histogram_,
                                             *distance_stats_)) {
  setObjectName("registrationPanel");
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(buildInputs());
  layout->addWidget(groups_, 1);
  layout->addLayout(buildActions());
  layout->addWidget(result_, 1);
  layout->addWidget(buildVisualCheck());
  connectSignals();
  followInputs();
  updateEnabled();
}

RegistrationPanel::~RegistrationPanel() = default;

QLayout* RegistrationPanel::buildInputs() {
  use_features_->setChecked(true);
  for (auto m : kMethods) method_->addItem(QString::fromStdString(methodName(m)));
  method_->setToolTip(tr("auto: planes for two scans (openings, then segments if planes fail), "
                         "segments for a model; icp: local refinement only"));
  auto* form = new QFormLayout;
  form->addRow(tr("Source (moves)"), &layers_->source());
  form->addRow(tr("Target (reference)"), &layers_->target());
  form->addRow(tr("Method"), method_);
  addModelElementFields(*form);
  form->addRow(use_features_);
  return form;
}

/// One text field per model element option (IFC types, element ids: comma-separated), named
/// by its key; a model target keeps only what they choose.
void RegistrationPanel::addModelElementFields(QFormLayout& form) {
  for (const ModelElementOption& option : modelElementOptions()) {
    auto* edit = new QLineEdit(this);
    edit->setObjectName(QString::fromStdString(option.key));
    edit->setPlaceholderText(tr("all elements"));
    edit->setToolTip(QString::fromStdString(option.help));
    connect(edit, &QLineEdit::textChanged, this, [this, member = option.member](const QString& text) {
      runner_->modelElements().*member = splitNameList(text.toStdString());
      updateFeaturesState();
    });
    form.addRow(QString::fromStdString(option.label), edit);
  }
}

QLayout* RegistrationPanel::buildActions() {
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(detect_);
  buttons->addWidget(register_);
  return buttons;
}

QWidget* RegistrationPanel::buildVisualCheck() {
  auto* qa = new QGroupBox(tr("Visual check"), this);
  auto* layout = new QVBoxLayout(qa);
  distance_panel_ = makeParamPanel(DistanceParams::schema(), runner_->distanceParams(), qa);
  layout->addWidget(distance_panel_);
  layout->addWidget(distance_);
  layout->addWidget(histogram_);
  distance_stats_->setWordWrap(true);
  layout->addWidget(distance_stats_);
  return qa;
}

void RegistrationPanel::connectSignals() {
  connect(layers_, &LayerPairCombos::changed, this, &RegistrationPanel::followInputs);
  connect(method_, &QComboBox::currentIndexChanged, this, [this](int i) {
    runner_->params().method = kMethods[i];
    groups_->enableFor(kMethods[i]);
  });
  connect(groups_, &ParamGroupsBox::changed, this, &RegistrationPanel::updateFeaturesState);
  connect(detect_, &QPushButton::clicked, this, &RegistrationPanel::detectFeatures);
  connect(register_, &QPushButton::clicked, this, &RegistrationPanel::startRegistration);
  connect(distance_, &QPushButton::clicked, this, &RegistrationPanel::colourByDistance);
  // A distance check stops describing what is shown when its layer goes or moves back.
  connect(&app_.scene, &Scene::layerAboutToBeRemoved, this, &RegistrationPanel::withdrawDistanceCheck);
  connect(result_, &RegistrationResultBox::undone, this, &RegistrationPanel::withdrawDistanceCheck);
  connect(runner_, &RegistrationRunner::newResult, this, [this] { check_->clear(); });
  connect(runner_, &RegistrationRunner::busyChanged, this, &RegistrationPanel::updateEnabled);
  connect(runner_, &RegistrationRunner::distancesReady, this, &RegistrationPanel::showDistances);
  connect(runner_, &RegistrationRunner::featuresDetected, this, &RegistrationPanel::featuresDetected);
  connect(runner_, &RegistrationRunner::registrationFinished, this, &RegistrationPanel::registrationFinished);
  connect(runner_, &RegistrationRunner::distancesComputed, this, &RegistrationPanel::distancesComputed);
}

PipelineParams& RegistrationPanel::params() { return runner_->params(); }
DistanceParams& RegistrationPanel::distanceParams() { return runner_->distanceParams(); }
ModelElementFilter& RegistrationPanel::modelElements() { return runner_->modelElements(); }
std::shared_ptr<const PipelineResult> RegistrationPanel::lastResult() const { return runner_->lastResult(); }
RegistrationRecord RegistrationPanel::lastRecord() const { return runner_->lastRecord(); }
bool RegistrationPanel::legendVisible() const { return check_->legendVisible(); }
std::shared_ptr<const LayerDistances> RegistrationPanel::lastDistances() const { return check_->distances(); }

void RegistrationPanel::refreshParams() {
  groups_->refresh();
  distance_panel_->refresh();
  setMethod(runner_->params().method);
  const ModelElementFilter elements = runner_->modelElements();  // the fields write it back
  for (const ModelElementOption& option : modelElementOptions())
    if (auto* edit = findChild<QLineEdit*>(QString::fromStdString(option.key)))
      edit->setText(QString::fromStdString(joinNameList(elements.*option.member)));
}

Layer* RegistrationPanel::sourceLayer() const { return layers_->sourceLayer(); }
Layer* RegistrationPanel::targetLayer() const { return layers_->targetLayer(); }
void RegistrationPanel::setSourceLayer(const Layer* layer) { layers_->setSourceLayer(layer); }
void RegistrationPanel::setTargetLayer(const Layer* layer) { layers_->setTargetLayer(layer); }

void RegistrationPanel::setMethod(RegistrationMethod method) {
  for (std::size_t i = 0; i < std::size(kMethods); ++i)
    if (kMethods[i] == method) method_->setCurrentIndex(int(i));
}

bool RegistrationPanel::detectFeatures() { return runner_->detectFeatures(); }
bool RegistrationPanel::startRegistration() { return runner_->startRegistration(use_features_->isChecked()); }
bool RegistrationPanel::colourByDistance() { return runner_->computeDistances(); }
void RegistrationPanel::accept() { result_->accept(); }
void RegistrationPanel::revert() { result_->revert(); }
void RegistrationPanel::showBefore(bool before) { result_->showBefore(before); }
const QualityReportView& RegistrationPanel::report() const { return result_->report(); }

void RegistrationPanel::followInputs() {
  runner_->setInputs(sourceLayer(), targetLayer());
  updateEnabled();
}

void RegistrationPanel::withdrawDistanceCheck(Layer* layer) {
  if (check_->involves(layer)) check_->clear();
  updateEnabled();
}

void RegistrationPanel::showDistances(std::shared_ptr<const LayerDistances> distances,
                                      DatasetLayer& source, Layer& target, double max_distance) {
  check_->show(std::move(distances), source, target, max_distance);
  app_.log.info(check_->statistics());
}

void RegistrationPanel::updateEnabled() {
  const bool busy = runner_->busy();
  const bool inputs = layers_->source().count() >= 2;
  // A running task keeps the layers it started with: the choice of them waits.
  layers_->setEnabled(!busy);
  use_features_->setEnabled(!busy);
  detect_->setEnabled(!busy && inputs);
  register_->setEnabled(!busy && inputs);
  distance_->setEnabled(!busy && inputs);
  updateFeaturesState();
}

std::string RegistrationPanel::featuresDetectedWith() const { return runner_->featuresDetectedWith(); }

void RegistrationPanel::adoptShownFeatures(const std::string& params) {
  runner_->adoptShownFeatures(params);
  updateFeaturesState();
}

bool RegistrationPanel::featuresOutOfDate() const {
  return runner_->featuresShown() && !runner_->featuresUpToDate();
}

void RegistrationPanel::updateFeaturesState() {
  if (featuresOutOfDate()) {
    use_features_->setText(tr("Use detected features (out of date: detect again)"));
    use_features_->setToolTip(tr("The features shown were detected with other parameters or "
                                 "layers: registering extracts them again"));
  } else {
    use_features_->setText(tr("Use detected features"));
    use_features_->setToolTip(tr("Register with the features shown (detected with the same "
                                 "parameters); otherwise features are extracted again"));
  }
}

}  // namespace plumb::ui
