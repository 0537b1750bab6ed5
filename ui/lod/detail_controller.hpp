#pragma once
// Chooses and loads what each DetailLayer draws (issue 16, out-of-core viewing): after every
// still frame, the nodes of the layer's cache the camera needs (selectLodNodes, within a point
// budget that follows the still frame budget) and the parent dataset's colours; when either
// differs from what is drawn, the nodes are read and coloured in a background task and shown
// when it ends (the next still frame then finds nothing to change). One load per layer at a
// time; the layer may be removed meanwhile (LayerRef).
#include <QObject>

#include <cstddef>
#include <map>

namespace plumb::ui {

struct AppContext;
class DatasetLayer;
class DetailLayer;
class LodController;
class Layer;

class DetailController : public QObject {
  Q_OBJECT
 public:
  /// Fewest and most points a view draws from one cache (the still frame's budget is split
  /// evenly among the visible detail layers, each within these).
  static constexpr std::size_t kMinPoints = 200'000;
  static constexpr std::size_t kMaxPoints = 4'000'000;

  DetailController(AppContext& app, LodController& lod, QObject* parent = nullptr);
  /// Looks at every detail layer now (also after each still frame).
  void refresh();
  /// A load is running for some layer.
  bool loading() const { return !loading_.empty(); }

 signals:
  /// A layer's new detail is drawn (tests wait for it).
  void detailShown();

 private:
  /// One layer's part of the still frame's budget.
  struct Share {
    std::size_t points = 0;
    std::size_t layers = 1;  ///< visible detail layers sharing the budget
  };
  void refreshLayer(DatasetLayer& dataset, DetailLayer& detail, Share share);
  AppContext& app_;
  LodController& lod_;
  std::map<const Layer*, bool> loading_;  ///< detail layers with a load running
};

}  // namespace plumb::ui
