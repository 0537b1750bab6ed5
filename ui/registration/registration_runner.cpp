#include "ui/registration/registration_runner.hpp"

#include <nlohmann/json.hpp>

#include "registration/auto/pipeline_param_groups.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/applied_registration.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/tasks/task.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

namespace {
/// The parameters the detected features depend on (the extraction groups), as text.
std::string extractionParams(const PipelineParams& params, const ModelElementFilter& elements) {
  const nlohmann::json all = pipelineParamsToJson(params);
  nlohmann::json used;
  for (const char* key : {"plane-extraction", "opening-detection", "segment-detection",
                          "mesh-edges", "model-sample-spacing"})
    if (all.contains(key)) used[key] = all.at(key);
  if (!elements.empty()) used["model-elements"] = elements.describe();
  return used.dump();
}
}  // namespace

RegistrationRunner::RegistrationRunner(AppContext& app, QObject* parent)
    : QObject(parent),
      app_(app),
      applied_(new AppliedRegistration(app.scene, app.undo, app.log, this)) {
  connect(&app_.scene, &Scene::layerAboutToBeRemoved, this, &RegistrationRunner::forgetLayer);
}

void RegistrationRunner::setInputs(Layer* source, Layer* target) {
  source_ = source ? LayerRef(*source) : LayerRef();
  target_ = target ? LayerRef(*target) : LayerRef();
}

bool RegistrationRunner::featuresShown() const {
  const Layer* s = source();
  const Layer* t = target();
  return s && t && featureOverlay(*s) && featureOverlay(*t);
}

bool RegistrationRunner::featuresUpToDate() const {
  return featuresShown() && features_.source.is(source()) && features_.target.is(target()) &&
         features_.params == extractionParams(params_, model_elements_);
}

std::string RegistrationRunner::featuresDetectedWith() const {
  return featuresUpToDate() ? features_.params : std::string();
}

void RegistrationRunner::adoptShownFeatures(const std::string& params) {
  if (featuresShown()) features_ = {source_, target_, params};
}

bool RegistrationRunner::checkInputs(Layer*& source, Layer*& target) {
  source = this->source();
  target = this->target();
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

void RegistrationRunner::setBusy(bool busy) {
  busy_ = busy;
  emit busyChanged(busy);
}

template <class Done>
void RegistrationRunner::whenFinished(Task* task, const QString& failure, Done done) {
  connect(task, &Task::finished, this, [this, failure, done](bool ok, const QString& message) {
    setBusy(false);
    if (!ok) app_.log.error(failure.arg(message));
    done(ok);
  });
}

bool RegistrationRunner::detectFeatures() {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  setBusy(true);
  app_.log.info(tr("Detecting features on %1 and %2").arg(s->name(), t->name()));
  const std::string params = extractionParams(params_, model_elements_);
  Task* task = startFeatureDetection(app_, *s, *t, params_, [this, s, t, params] {
    features_ = {LayerRef(*s), LayerRef(*t), params};  // called only while both exist
  }, model_elements_);
  whenFinished(task, tr("Feature detection failed: %1"), [this](bool ok) { emit featuresDetected(ok); });
  return true;
}

bool RegistrationRunner::startRegistration(bool use_features) {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  if (use_features && featuresShown() && !featuresUpToDate()) {
    app_.log.warning(tr("The features shown were detected with other parameters or layers: "
                        "extracting them again"));
    use_features = false;
  }
  setBusy(true);
  app_.log.info(tr("Registering %1 onto %2 (%3)")
                    .arg(s->name(), t->name(), QString::fromStdString(methodName(params_.method))));
  pending_ = RegistrationRecord{nullptr, LayerRef(*s), LayerRef(*t), layerTransform(*s),
                                layerTransform(*t), params_.seed, model_elements_};
  Task* task = ui::startRegistration(
      app_, *s, *t, params_, use_features,
      [this](std::shared_ptr<const PipelineResult> r, Layer& source, const RigidTransform& start) {
        applyResult(std::move(r), source, start);
      }, model_elements_);
  whenFinished(task, tr("Registration stopped: %1"), [this](bool ok) {
    emit registrationFinished(ok && result_ && result_->success());
  });
  return true;
}

RegistrationRecord RegistrationRunner::lastRecord() const {
  RegistrationRecord r = applied_inputs_;
  r.result = result_;
  return r;
}

void RegistrationRunner::applyResult(std::shared_ptr<const PipelineResult> result, Layer& source,
                                     const RigidTransform& start) {
  // A new result: the previous one (and the dock's distance check) no longer describe what is
  // shown.
  applied_->forget();
  result_ = std::move(result);
  applied_inputs_ = pending_;
  emit newResult(*result_);
  for (const auto& line : result_->log) app_.log.info(QString::fromStdString(line));
  if (!result_->success()) {
    app_.log.error(tr("Registration failed: %1").arg(QString::fromStdString(result_->report.verdict)));
    return;
  }
  // The layer the task started with (not the one selected now), from where it was then.
  applied_->apply(source, start, result_->transform() * start,
                  tr("Register %1 (%2)").arg(source.name(), QString::fromStdString(result_->method_used)));
  if (result_->report.level == VerdictLevel::CheckVisually)
    app_.log.warning(tr("Check visually: %1").arg(QString::fromStdString(result_->report.verdict)));
  else
    app_.log.info(QString::fromStdString(result_->report.verdict));
  app_.view.requestRender();
}

bool RegistrationRunner::computeDistances() {
  Layer *s, *t;
  if (!checkInputs(s, t)) return false;
  if (s->kind() != LayerKind::Dataset) {
    app_.log.error(tr("Colour by distance: the source must be a point dataset"));
    return false;
  }
  setBusy(true);
  const double max = distance_params_.max_distance;
  Task* task = startDistanceComputation(
      app_, *s, *t, distance_params_,
      [this, max](std::shared_ptr<const LayerDistances> d, DatasetLayer& source, Layer& target) {
        emit distancesReady(std::move(d), source, target, max);
      });
  whenFinished(task, tr("Distance computation failed: %1"), [this](bool ok) { emit distancesComputed(ok); });
  return true;
}

void RegistrationRunner::forgetLayer(Layer* layer) {
  if (applied_->layer() != layer) return;
  applied_->forget();
  result_.reset();
  emit resultWithdrawn();
}

}  // namespace plumb::ui
