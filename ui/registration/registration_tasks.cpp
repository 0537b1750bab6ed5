#include "ui/registration/registration_tasks.hpp"

#include <variant>

#include "common/error.hpp"
#include "registration/auto/registration_input.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/feature_layer.hpp"
#include "ui/layers/layer_transform.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

LayerData dataOf(const Layer& layer) {
  LayerData d;
  d.name = layer.name();
  d.to_world = layerTransform(layer);
  if (layer.kind() == LayerKind::Dataset)
    d.dataset = static_cast<const DatasetLayer&>(layer).sharedDataset();
  else if (layer.kind() == LayerKind::Model)
    d.model = static_cast<const ModelLayer&>(layer).sharedModel();
  else
    throw InputError("'" + layer.name().toStdString() + "' is not a dataset or a model");
  if (const Layer* f = featureOverlay(layer))
    d.features = static_cast<const FeatureLayer*>(f)->sharedFeatures();
  return d;
}

RegistrationInput inputOf(const LayerData& d, const RigidTransform& to_world) {
  return d.dataset ? makeRegistrationInput(*d.dataset, to_world)
                   : makeRegistrationInput(*d.model, to_world, d.elements);
}

Layer* featureOverlay(const Layer& layer) {
  for (const auto& c : layer.children())
    if (c->kind() == LayerKind::Features) return c.get();
  return nullptr;
}

Task* startFeatureDetection(AppContext& app, Layer& source, Layer& target,
                            const PipelineParams& params, std::function<void()> done,
                            const ModelElementFilter& target_elements) {
  const LayerData s = dataOf(source);
  LayerData t = dataOf(target);
  t.elements = target_elements;
  const LayerRef src(source), tgt(target);
  Task* task = app.tasks.run(QObject::tr("Detecting features"), [&app, s, t, src, tgt, params,
                                                                  done](Progress& progress) {
    std::vector<std::string> log;
    std::shared_ptr<const FeatureSet> fs, ft;
    {
      Progress p = progress.sub(0.0, 0.5);
      const RegistrationInput in = inputOf(s, {});
      fs = std::make_shared<const FeatureSet>(extractFeatures(in.side(), params, true, &log, &p));
    }
    {
      Progress p = progress.sub(0.5, 1.0);
      const RegistrationInput in = inputOf(t, {});
      ft = std::make_shared<const FeatureSet>(extractFeatures(in.side(), params, true, &log, &p));
    }
    return [&app, s, t, src, tgt, fs, ft, log, done] {
      Layer& source = stillThere(src, s.name, "feature detection");
      Layer& target = stillThere(tgt, t.name, "feature detection");
      for (const auto& [layer, features] : {std::pair{&source, fs}, std::pair{&target, ft}}) {
        if (Layer* old = featureOverlay(*layer)) app.scene.removeLayer(old);
        auto& overlay = app.scene.addFeatures(QObject::tr("features"), features, layer);
        overlay.setTransform(layerTransform(*layer));
      }
      for (const auto& line : log) app.log.info(QString::fromStdString(line));
      app.scene.layerChanged(&source);
      if (done) done();
    };
  }, {src, tgt});
  return task;
}

Task* startRegistration(AppContext& app, Layer& source, Layer& target, const PipelineParams& params,
                        bool use_features, RegistrationDone done,
                        const ModelElementFilter& target_elements) {
  const LayerData s = dataOf(source);
  LayerData t = dataOf(target);
  t.elements = target_elements;
  const LayerRef src(source), tgt(target);
  return app.tasks.run(QObject::tr("Registering %1 onto %2").arg(s.name, t.name),
                       [s, t, src, tgt, params, use_features, done](Progress& progress) {
                         RegistrationInput in_s = inputOf(s, s.to_world);
                         RegistrationInput in_t = inputOf(t, t.to_world);
                         if (use_features && s.features && t.features) {
                           in_s.features = *s.features;
                           in_s.features->transform(s.to_world);
                           in_t.features = *t.features;
                           in_t.features->transform(t.to_world);
                         }
                         auto result = std::make_shared<const PipelineResult>(
                             registerData(in_s.side(), in_t.side(), params, &progress));
                         return [s, t, src, tgt, result, done] {
                           Layer& source = stillThere(src, s.name, "the registration");
                           stillThere(tgt, t.name, "the registration");
                           done(result, source, s.to_world);
                         };
                       }, {src, tgt});
}

Task* startDistanceComputation(AppContext& app, Layer& source, Layer& target,
                               const DistanceParams& params, DistancesDone done) {
  if (source.kind() != LayerKind::Dataset)
    throw InputError("distance colouring needs a point dataset as the source");
  const LayerData s = dataOf(source), t = dataOf(target);
  const LayerRef src(source), tgt(target);
  return app.tasks.run(QObject::tr("Distances %1 to %2").arg(s.name, t.name), [s, t, src, tgt, params, done](
                                                                                   Progress& progress) {
    // The target in world as registration sees it: its sensor origins orient the signs.
    auto out = std::make_shared<LayerDistances>();
    out->target = std::make_shared<const RegistrationInput>(inputOf(t, t.to_world));
    out->params = params;
    static_cast<DatasetDistances&>(*out) =
        datasetDistances(*s.dataset, s.to_world, distanceTarget(*out->target), params, &progress);
    return [s, t, src, tgt, out, done] {
      Layer& source = stillThere(src, s.name, "the distance computation");
      Layer& target = stillThere(tgt, t.name, "the distance computation");
      done(out, static_cast<DatasetLayer&>(source), target);
    };
  }, {src, tgt});
}

}  // namespace plumb::ui
