#pragma once
// A network run as the Network dock shows it: the stations (built as plumb-cli network builds
// them), the layer and scan each came from, the result and its report (networkReportToJson:
// the one source of the figures shown), and the parameters it ran with.
#include <nlohmann/json.hpp>

#include <QString>

#include <memory>
#include <vector>

#include "registration/network/network_registration.hpp"
#include "ui/layers/layer.hpp"

namespace plumb::ui {

/// Where a station came from: scan `scan` of a dataset layer, or the model layer.
struct StationSource {
  LayerRef layer;
  std::size_t scan = 0;
  bool model = false;
  std::size_t colour_index = 0;  ///< the scan's Scan colour (categoryColor), for the plan view
};

struct NetworkSession {
  std::shared_ptr<const std::vector<Station>> stations;
  std::vector<StationSource> sources;  ///< per station
  /// The network as registered, before any decision: every re-run starts from its links
  /// (readjustNetwork: a link the surveyor rejected, then cleared, is accepted again as its
  /// verdict says).
  std::shared_ptr<const NetworkResult> registered;
  std::shared_ptr<const NetworkResult> result;
  nlohmann::json report;  ///< networkReportToJson(*result, *stations)
  NetworkParams params;   ///< what the links were registered and adjusted with
  std::shared_ptr<const ControlSurvey> control;  ///< the run's control points (null: none)

  /// Replaces the result (a re-run adjustment) and its report.
  void setResult(std::shared_ptr<const NetworkResult> r);
  std::size_t stationCount() const { return stations ? stations->size() : 0; }
  std::size_t linkCount() const { return result ? result->links.size() : 0; }
};

/// "5 of 5 stations placed, 5 links in the adjustment, 0 dropped, 0 flagged": a network report at
/// a glance (the log, the dock's summary).
QString networkSummary(const nlohmann::json& report);

}  // namespace plumb::ui
