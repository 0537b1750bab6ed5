#pragma once
// The Registration dock's work without its widgets: the source and target layers (held as
// LayerRefs), "Detect features", "Register" and "Colour by distance" as background Tasks (one
// at a time), whether the features shown were detected for these inputs with the current
// parameters, and the last result, applied to its source through AppliedRegistration (undo,
// accept, revert). The dock forwards the user's actions here and follows the signals.
#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <string>

#include "model/model_element_filter.hpp"
#include "model/rigid_transform.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "ui/layers/layer.hpp"

namespace plumb::ui {

struct AppContext;
class AppliedRegistration;
class DatasetLayer;
class Task;
struct LayerDistances;

/// The last registration with what its report needs: the layers it ran on and where they were
/// when it started (File > Export report rebuilds the inputs from them).
struct RegistrationRecord {
  std::shared_ptr<const PipelineResult> result;  ///< nullptr: none, or withdrawn
  LayerRef source, target;
  RigidTransform source_start, target_start;  ///< data frame -> world when it started
  std::uint64_t seed = 1;
  ModelElementFilter target_elements;  ///< the model target's chosen elements (issue 14)
};

class RegistrationRunner : public QObject {
  Q_OBJECT
 public:
  explicit RegistrationRunner(AppContext& app, QObject* parent = nullptr);

  PipelineParams& params() { return params_; }
  DistanceParams& distanceParams() { return distance_params_; }
  /// A model target's chosen elements (types, ids): features and registration use only them.
  ModelElementFilter& modelElements() { return model_elements_; }

  /// The layers the next task works on (a running task keeps those it started with).
  void setInputs(Layer* source, Layer* target);
  Layer* source() const { return source_.get(); }
  Layer* target() const { return target_.get(); }
  /// A task started here is running.
  bool busy() const { return busy_; }

  /// Start the background work; false (and a log message) when a task runs already or the
  /// inputs are not two different layers. `use_features`: register with the features shown
  /// when they are up to date (otherwise they are extracted again, and the log says so).
  bool detectFeatures();
  bool startRegistration(bool use_features);
  bool computeDistances();

  /// Both inputs show detected features.
  bool featuresShown() const;
  /// ... and they were detected here for these two layers with the current extraction
  /// parameters.
  bool featuresUpToDate() const;
  /// The extraction parameters (JSON text) the features shown were detected with, when they
  /// are up to date; empty otherwise (what a project records).
  std::string featuresDetectedWith() const;
  /// The features shown on both inputs were detected for them with `params` (JSON text of
  /// featuresDetectedWith, e.g. read back from a project). Nothing when they show none.
  void adoptShownFeatures(const std::string& params);

  /// The last result (nullptr: none yet, or withdrawn with its layer).
  std::shared_ptr<const PipelineResult> lastResult() const { return result_; }
  /// The last result with its inputs (result nullptr when there is none).
  RegistrationRecord lastRecord() const;
  AppliedRegistration& applied() { return *applied_; }

 signals:
  void busyChanged(bool busy);
  void featuresDetected(bool ok);
  void registrationFinished(bool success);
  void distancesComputed(bool ok);
  /// A registration ended with `result` (also a failed one): the previous result is gone;
  /// emitted before a successful one is applied.
  void newResult(const plumb::PipelineResult& result);
  /// The last result was dropped: the layer it moved is being removed.
  void resultWithdrawn();
  /// The distances of `source` to `target` (Colour by distance), on a ramp up to `max_distance`.
  void distancesReady(std::shared_ptr<const plumb::ui::LayerDistances> distances,
                      plumb::ui::DatasetLayer& source, plumb::ui::Layer& target,
                      double max_distance);

 private:
  bool checkInputs(Layer*& source, Layer*& target);
  void setBusy(bool busy);
  /// When `task` finishes: not busy any more, a failure logged as `failure` (with %1 the
  /// task's message), then `done(ok)`.
  template <class Done>
  void whenFinished(Task* task, const QString& failure, Done done);
  void applyResult(std::shared_ptr<const PipelineResult> result, Layer& source,
                   const RigidTransform& start);
  void forgetLayer(Layer* layer);

  AppContext& app_;
  PipelineParams params_;
  DistanceParams distance_params_;
  ModelElementFilter model_elements_;
  LayerRef source_, target_;
  AppliedRegistration* applied_;  ///< the last result applied (child QObject)
  std::shared_ptr<const PipelineResult> result_;
  RegistrationRecord pending_;  ///< inputs of the running registration
  RegistrationRecord applied_inputs_;  ///< inputs of result_
  /// What the last feature detection ran on and with (extraction parameters as JSON text).
  struct DetectedFeatures {
    LayerRef source, target;
    std::string params;
  } features_;
  bool busy_ = false;
};

}  // namespace plumb::ui
