#pragma once
// The Network dock's work without its widgets: runs the network (one task at a time), keeps
// the session and the surveyor's decisions, re-runs the adjustment with them, applies the
// adjusted poses to the layers, colours the stations, saves the report. The dock's widgets
// and the tests drive it.
#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <string>

#include "ui/network/control_settings.hpp"
#include "ui/network/link_decisions.hpp"
#include "ui/network/network_session.hpp"
#include "ui/network/network_tasks.hpp"

namespace plumb::ui {

struct AppContext;
class Layer;

class NetworkRunner : public QObject {
  Q_OBJECT
 public:
  explicit NetworkRunner(AppContext& app, QObject* parent = nullptr);

  NetworkParams& params() { return params_; }
  /// The control survey the next run reads (the dock's ControlBox edits it).
  ControlSettings& control() { return control_; }
  /// The last run (null before one finished); its result follows the re-runs.
  std::shared_ptr<const NetworkSession> session() const { return session_; }
  const NetworkDecisions& decisions() const { return decisions_; }
  bool busy() const { return busy_; }

  /// Registers every scan of every point dataset layer as one network; `model` (a model layer,
  /// or nullptr) is then the reference, else the station named `reference` (empty: the first).
  /// With control points, the network is georeferenced on them. False (and a log message) when
  /// it cannot start: bad parameters, an unknown reference, a control file the core refuses.
  bool run(const Layer* model, const std::string& reference = {});
  /// Re-runs the adjustment of the last run's links with the decisions.
  bool rerunAdjustment();

  /// Decisions on link k of the result (by its station pair) / station i; they apply at the
  /// next rerunAdjustment(). A station is locked at its current adjusted pose (placed only).
  void setLinkDecision(std::size_t link, LinkDecision decision);
  LinkDecision linkDecision(std::size_t link) const;
  bool setLocked(std::size_t station, bool locked);
  bool isLocked(std::size_t station) const { return decisions_.locked.count(station) > 0; }

  /// Each placed station's scan takes its adjusted pose (one undo command); false when nothing
  /// could be applied.
  bool applyPoses();
  /// The stations' dataset layers coloured by scan (each station its colour).
  void colourByStation();
  /// The report as JSON or (".html") HTML, written atomically; false (logged) on failure.
  bool saveReport(const QString& path);

 signals:
  void busyChanged(bool busy);
  /// A run finished (ok) or failed / was cancelled.
  void finished(bool ok);
  /// A re-run of the adjustment finished.
  void adjusted(bool ok);
  /// The session's result or the decisions changed: the views refresh.
  void changed();

 private:
  bool refuse(const QString& why);
  std::optional<NetworkInputs> prepare(const Layer* model, const std::string& reference);
  void setBusy(bool busy);
  bool ready();
  AppContext& app_;
  NetworkParams params_;
  ControlSettings control_;
  std::shared_ptr<NetworkSession> session_;
  NetworkDecisions decisions_;
  bool busy_ = false;
};

}  // namespace plumb::ui
