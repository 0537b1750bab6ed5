#include "ui/network/network_runner.hpp"

#include <QPointer>
#include <QUndoStack>

#include "ui/app_context.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/network/network_report_file.hpp"
#include "ui/network/station_poses_command.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/tasks/task.hpp"

namespace plumb::ui {

NetworkRunner::NetworkRunner(AppContext& app, QObject* parent) : QObject(parent), app_(app) {}

bool NetworkRunner::refuse(const QString& why) {
  app_.log.warning(tr("Network: %1").arg(why));
  return false;
}

void NetworkRunner::setBusy(bool busy) {
  busy_ = busy;
  emit busyChanged(busy);
}

bool NetworkRunner::ready() {
  if (busy_) return refuse(tr("a network task is already running"));
  if (!session_) return refuse(tr("register the stations as a network first"));
  return true;
}

std::optional<NetworkInputs> NetworkRunner::prepare(const Layer* model, const std::string& reference) {
  NetworkInputs inputs;
  try {
    validateNetworkParams(params_);
    inputs = networkInputs(app_.scene, model);
    inputs.reference_station = reference;
    inputs.referenceIndex();  // an unknown name is refused now, not after minutes of features
  } catch (const std::exception& e) {
    refuse(QString::fromUtf8(e.what()));
    return std::nullopt;
  }
  try {
    inputs.control = loadControlSurvey(control_, inputs.stationNames());
  } catch (const std::exception& e) {  // the core's message names the file and the line
    app_.log.error(tr("Network: %1").arg(QString::fromUtf8(e.what())));
    return std::nullopt;
  }
  return inputs;
}

bool NetworkRunner::run(const Layer* model, const std::string& reference) {
  if (busy_) return refuse(tr("a network task is already running"));
  std::optional<NetworkInputs> inputs = prepare(model, reference);
  if (!inputs) return false;
  app_.log.info(tr("Network: registering %1 stations%2")
                    .arg(inputs->stationCount())
                    .arg(inputs->control ? tr(", with %1 control and check points")
                                               .arg(inputs->control->points.size())
                                         : QString()));
  QPointer<NetworkRunner> self(this);
  Task* task = startNetworkRegistration(app_, std::move(*inputs), params_, [self](auto session) {
    if (!self) return;
    self->session_ = std::move(session);
    self->decisions_ = {};  // decisions name the stations of the run they were made on
  });
  connect(task, &Task::finished, this, [this](bool ok, const QString& message) {
    setBusy(false);
    if (ok) app_.log.info(tr("Network: %1").arg(networkSummary(session_->report)));
    else app_.log.error(tr("Network registration: %1").arg(message));
    emit changed();
    emit finished(ok);
  });
  setBusy(true);
  return true;
}

bool NetworkRunner::rerunAdjustment() {
  if (!ready()) return false;
  QPointer<NetworkRunner> self(this);
  Task* task = startNetworkAdjustment(app_, *session_, decisions_, [self, session = session_](auto result) {
    session->setResult(std::move(result));
  });
  connect(task, &Task::finished, this, [this](bool ok, const QString& message) {
    setBusy(false);
    if (ok) app_.log.info(tr("Network adjusted again: %1").arg(networkSummary(session_->report)));
    else app_.log.error(tr("Network adjustment: %1").arg(message));
    emit changed();
    emit adjusted(ok);
  });
  setBusy(true);
  return true;
}

void NetworkRunner::setLinkDecision(std::size_t link, LinkDecision decision) {
  if (!session_ || link >= session_->linkCount()) return;
  const Link& l = session_->result->links[link];
  setDecision(decisions_, {l.a, l.b}, decision);
  emit changed();
}

LinkDecision NetworkRunner::linkDecision(std::size_t link) const {
  if (!session_ || link >= session_->linkCount()) return LinkDecision::None;
  const Link& l = session_->result->links[link];
  return decisionOf(decisions_, {l.a, l.b});
}

bool NetworkRunner::setLocked(std::size_t station, bool locked) {
  if (!session_ || station >= session_->stationCount()) return false;
  const NetworkResult& r = *session_->result;
  if (locked && !r.placed(station))
    return refuse(tr("%1 is not placed: only a placed station can be locked at its pose")
                      .arg(QString::fromStdString((*session_->stations)[station].name)));
  setStationLock(decisions_, station, locked ? r.adjustment.poses[station] : std::nullopt);
  emit changed();
  return true;
}

bool NetworkRunner::applyPoses() {
  if (!ready()) return false;
  auto poses = stationPoses(*session_);
  if (poses.empty()) return refuse(tr("no placed station to apply (or the reference's layer is gone)"));
  app_.undo.push(new StationPosesCommand(app_.scene, std::move(poses)));
  app_.log.info(tr("Network: the adjusted poses applied to the stations' scans (Edit > Undo takes them back)"));
  return true;
}

void NetworkRunner::colourByStation() {
  if (!session_) return;
  for (const auto& s : session_->sources) {
    Layer* layer = s.layer.get();
    if (s.model || !layer) continue;
    auto& dataset = static_cast<DatasetLayer&>(*layer);
    if (dataset.style().mode == PointColorMode::Scan) continue;  // one request per layer
    PointStyle style = dataset.style();
    style.mode = PointColorMode::Scan;
    app_.scene.requestStyle(dataset, style);
  }
  app_.properties.showLayer(app_.layers.currentLayer());  // its style editor and legend follow
}

bool NetworkRunner::saveReport(const QString& path) {
  if (!session_) return refuse(tr("register the stations as a network first"));
  try {
    saveNetworkReport(path.toStdString(), session_->report);
  } catch (const std::exception& e) {
    app_.log.error(tr("Network report: %1").arg(QString::fromUtf8(e.what())));
    return false;
  }
  app_.log.info(tr("Network report written to %1").arg(path));
  return true;
}

}  // namespace plumb::ui
