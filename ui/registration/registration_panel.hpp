#pragma once
// The Registration dock: source and target layers, method, parameter panels generated from the
// core's ParamSchemas, "Detect features" (overlays on both layers), "Register" (background,
// progress and cancel in the status bar), the quality report, before/after, accept/revert, and
// the visual QA (colour the registered source by distance, legend and histogram).
#include <QWidget>

#include <memory>

#include "model/model_element_filter.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/auto/registration_pipeline.hpp"

class QCheckBox;
class QFormLayout;
class QComboBox;
class QLabel;
class QLayout;
class QPushButton;

namespace plumb::ui {

struct AppContext;
class DatasetLayer;
class DistanceCheck;
class HistogramWidget;
class Layer;
class LayerPairCombos;
class ParamGroupsBox;
class ParamPanel;
class QualityReportView;
class RegistrationResultBox;
class RegistrationRunner;
struct RegistrationRecord;
struct LayerDistances;

/// The widgets; the work is the RegistrationRunner's.
class RegistrationPanel : public QWidget {
  Q_OBJECT
 public:
  RegistrationPanel(AppContext& app, QWidget* parent = nullptr);
  ~RegistrationPanel() override;

  PipelineParams& params();
  /// Re-reads every parameter editor (after params() changed elsewhere, e.g. a project).
  void refreshParams();
  DistanceParams& distanceParams();
  /// The model target's chosen elements (issue 14); refreshParams() shows them in their fields.
  ModelElementFilter& modelElements();

  /// The layers to register; until chosen (here or in the combos), defaultRegistrationPair.
  Layer* sourceLayer() const;
  Layer* targetLayer() const;
  void setSourceLayer(const Layer* layer);
  void setTargetLayer(const Layer* layer);
  void setMethod(RegistrationMethod method);

  /// RegistrationRunner::featuresDetectedWith / adoptShownFeatures (project files); adopting
  /// updates "Use detected features".
  std::string featuresDetectedWith() const;
  void adoptShownFeatures(const std::string& params);
  /// The features shown are out of date ("Use detected features" would extract them again).
  bool featuresOutOfDate() const;

  /// Start the background work; false (and a log message) when the inputs are not valid.
  bool detectFeatures();
  bool startRegistration();
  bool colourByDistance();
  /// Keep the applied result / undo it.
  void accept();
  void revert();
  /// Before/after: show the source where it was before the last registration.
  void showBefore(bool before);

  std::shared_ptr<const PipelineResult> lastResult() const;
  /// The last result with the layers it ran on (File > Export report).
  RegistrationRecord lastRecord() const;
  std::shared_ptr<const LayerDistances> lastDistances() const;
  const QualityReportView& report() const;
  const HistogramWidget& histogram() const { return *histogram_; }
  bool legendVisible() const;

 signals:
  void featuresDetected(bool ok);
  void registrationFinished(bool success);
  void distancesComputed(bool ok);

 private:
  QLayout* buildInputs();
  QLayout* buildActions();
  void addModelElementFields(QFormLayout& form);
  QWidget* buildVisualCheck();
  void connectSignals();
  void followInputs();
  void updateEnabled();
  void updateFeaturesState();
  void withdrawDistanceCheck(Layer* layer);
  void showDistances(std::shared_ptr<const LayerDistances> distances, DatasetLayer& source,
                     Layer& target, double max_distance);

  AppContext& app_;
  RegistrationRunner* runner_;  ///< child QObject
  LayerPairCombos* layers_;     ///< child QObject
  QComboBox* method_;
  QCheckBox* use_features_;
  ParamGroupsBox* groups_;
  ParamPanel* distance_panel_ = nullptr;
  QPushButton* detect_;
  QPushButton* register_;
  QPushButton* distance_;
  RegistrationResultBox* result_;
  HistogramWidget* histogram_;
  QLabel* distance_stats_;
  std::unique_ptr<DistanceCheck> check_;
};

}  // namespace plumb::ui
