#pragma once
// The Registration dock: source and target layers, method, parameter panels generated from the
// core's ParamSchemas, "Detect features" (overlays on both layers), "Register" (background,
// progress and cancel in the status bar), the quality report, before/after, accept/revert, and
// the visual QA (colour the registered source by distance, legend and histogram).
#include <QWidget>

#include <memory>

#include "quality/cloud_distance.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "model/rigid_transform.hpp"
#include "ui/layers/layer.hpp"

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QToolBox;

namespace plumb::ui {

struct AppContext;
class AppliedRegistration;
class DistanceCheck;
class HistogramWidget;
class Layer;
class ParamPanel;
class QualityReportView;
struct LayerDistances;

class RegistrationPanel : public QWidget {
  Q_OBJECT
 public:
  RegistrationPanel(AppContext& app, QWidget* parent = nullptr);
  ~RegistrationPanel() override;

  PipelineParams& params() { return params_; }
  /// Re-reads every parameter editor (after params() changed elsewhere, e.g. a project).
  void refreshParams();
  DistanceParams& distanceParams() { return distance_params_; }

  /// The layers to register; until chosen (here or in the combos), defaultRegistrationPair.
  Layer* sourceLayer() const;
  Layer* targetLayer() const;
  void setSourceLayer(const Layer* layer);
  void setTargetLayer(const Layer* layer);
  void setMethod(RegistrationMethod method);

  /// Start the background work; false (and a log message) when the inputs are not valid.
  bool detectFeatures();
  bool startRegistration();
  bool colourByDistance();
  /// Keep the applied result / undo it.
  void accept();
  void revert();
  /// Before/after: show the source where it was before the last registration.
  void showBefore(bool before);

  std::shared_ptr<const PipelineResult> lastResult() const { return result_; }
  std::shared_ptr<const LayerDistances> lastDistances() const;
  const QualityReportView& report() const { return *report_; }
  const HistogramWidget& histogram() const { return *histogram_; }
  bool legendVisible() const;

 signals:
  void featuresDetected(bool ok);
  void registrationFinished(bool success);
  void distancesComputed(bool ok);

 private:
  void rebuildLayerCombos();
  static void selectLayer(QComboBox& combo, const Layer* layer);
  void updateEnabled();
  void applyResult(std::shared_ptr<const PipelineResult> result, Layer& source,
                   const RigidTransform& start);
  void forgetLayer(Layer* layer);
  void followAppliedResult();
  /// The features shown on the source and target were detected by this dock for these two
  /// layers with the current extraction parameters.
  bool featuresUpToDate() const;
  void updateFeaturesState();
  bool checkInputs(Layer*& source, Layer*& target);

  AppContext& app_;
  PipelineParams params_;
  DistanceParams distance_params_;
  QComboBox* source_;
  QComboBox* target_;
  QComboBox* method_;
  QCheckBox* use_features_;
  QToolBox* groups_;
  std::vector<std::pair<std::string, ParamPanel*>> panels_;
  ParamPanel* distance_panel_;
  QPushButton* detect_;
  QPushButton* register_;
  QPushButton* accept_;
  QPushButton* revert_;
  QPushButton* distance_;
  QCheckBox* before_;
  QualityReportView* report_;
  HistogramWidget* histogram_;
  QLabel* distance_stats_;
  AppliedRegistration* applied_;  ///< the last result applied (child QObject)
  std::unique_ptr<DistanceCheck> check_;
  std::shared_ptr<const PipelineResult> result_;
  /// What the last feature detection ran on and with (extraction parameters as JSON text).
  struct DetectedFeatures {
    LayerRef source, target;
    std::string params;
  } features_;
  bool busy_ = false;
  bool chosen_ = false;  ///< the user (or a project) chose the source/target
};

}  // namespace plumb::ui
