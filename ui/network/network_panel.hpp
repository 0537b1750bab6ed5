#pragma once
// The Network dock (issue 15, the project view of a campaign): every scan of every point
// dataset layer a station, optionally a model layer as the reference; "Register network"
// (background, progress and cancel in the status bar), the plan view, the stations and links
// tables, accept / reject / clear a link, lock a station, "Re-run adjustment", "Apply poses"
// (undoable), "Colour by station", "Save report...", the reference by station name, control and
// check points (the Control tab: the files and grid scale, then the georeference and residuals).
// Selecting a station or link in the plan selects it in its table and back. The work is the
// NetworkRunner's.
#include <QWidget>

class QLabel;
class QPushButton;
class QTabWidget;

namespace plumb::ui {

struct AppContext;
enum class LinkDecision;
class ControlBox;
class GeoreferenceView;
class LinkTable;
class NetworkParamsBox;
class NetworkPlanView;
class NetworkRunner;
class ReferenceCombo;
class StationTable;

class NetworkPanel : public QWidget {
  Q_OBJECT
 public:
  NetworkPanel(AppContext& app, QWidget* parent = nullptr);

  NetworkRunner& runner() { return *runner_; }
  NetworkPlanView& plan() { return *plan_; }
  StationTable& stations() { return *stations_; }
  LinkTable& links() { return *links_; }
  ReferenceCombo& reference() { return *reference_; }
  GeoreferenceView& georeference() { return *georeference_; }

  /// The buttons' actions (also for the menu and tests); false when refused (logged).
  bool run();
  bool rerun();
  bool saveReport();

 private:
  QWidget* buildActions();
  QWidget* buildLinkActions();
  QWidget* buildControlPage();
  void connectSignals();
  void showSession();
  void updateEnabled();
  void decideSelectedLink(LinkDecision decision);

  AppContext& app_;
  NetworkRunner* runner_;  ///< child QObject
  ReferenceCombo* reference_;
  NetworkParamsBox* params_;
  ControlBox* control_;
  GeoreferenceView* georeference_;
  NetworkPlanView* plan_;
  StationTable* stations_;
  LinkTable* links_;
  QTabWidget* tabs_;
  QLabel* summary_;
  QPushButton *run_, *rerun_, *apply_, *colour_, *save_, *accept_, *reject_, *clear_;
};

}  // namespace plumb::ui
