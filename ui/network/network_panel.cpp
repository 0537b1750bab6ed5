#include "ui/network/network_panel.hpp"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QVBoxLayout>

#include "ui/actions/file_dialogs.hpp"
#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/network/control_box.hpp"
#include "ui/network/georeference_view.hpp"
#include "ui/network/link_table.hpp"
#include "ui/network/network_params_box.hpp"
#include "ui/network/network_plan_view.hpp"
#include "ui/network/network_runner.hpp"
#include "ui/network/reference_combo.hpp"
#include "ui/network/station_table.hpp"

namespace plumb::ui {

namespace {
QPushButton* button(const QString& text, const char* name, const QString& tip, QWidget* parent) {
  auto* b = new QPushButton(text, parent);
  b->setObjectName(name);
  b->setToolTip(tip);
  return b;
}
}  // namespace

NetworkPanel::NetworkPanel(AppContext& app, QWidget* parent)
    : QWidget(parent),
      app_(app),
      runner_(new NetworkRunner(app, this)),
      reference_(new ReferenceCombo(this)),
      params_(new NetworkParamsBox(runner_->params(), this)),
      control_(new ControlBox(runner_->control(), this)),
      georeference_(new GeoreferenceView(this)),
      plan_(new NetworkPlanView(this)),
      stations_(new StationTable(this)),
      links_(new LinkTable(this)),
      tabs_(new QTabWidget(this)),
      summary_(new QLabel(tr("Every scan of every open point dataset is a station."), this)) {
  setObjectName("networkPanel");
  summary_->setObjectName("networkSummary");
  summary_->setWordWrap(true);
  auto* links_page = new QWidget(this);
  auto* links_layout = new QVBoxLayout(links_page);
  links_layout->addWidget(links_);
  links_layout->addWidget(buildLinkActions());
  tabs_->addTab(stations_, tr("Stations"));
  tabs_->addTab(links_page, tr("Links"));
  tabs_->addTab(buildControlPage(), tr("Control"));
  tabs_->addTab(params_, tr("Parameters"));
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(plan_);
  split->addWidget(tabs_);
  split->setStretchFactor(1, 2);
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(buildActions());
  layout->addWidget(summary_);
  layout->addWidget(split, 1);
  connectSignals();
  reference_->refresh(app_.scene);
  updateEnabled();
}

QWidget* NetworkPanel::buildActions() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  run_ = button(tr("Register network"), "networkRun",
                tr("Register every station with its candidate neighbours, then adjust the network (as plumb-cli "
                   "network)"), bar);
  rerun_ = button(tr("Re-run adjustment"), "networkRerun",
                  tr("Adjust the registered links again with your decisions (accepted, rejected links, locked "
                     "stations)"), bar);
  apply_ = button(tr("Apply poses"), "networkApply",
                  tr("Give every placed station's scan its adjusted pose in the 3D view (Edit > Undo takes it back)"),
                  bar);
  colour_ = button(tr("Colour by station"), "networkColour", tr("Each station's scan in its own colour"), bar);
  save_ = button(tr("Save report..."), "networkSaveReport", tr("The network report as JSON or HTML"), bar);
  row->addWidget(new QLabel(tr("Reference"), bar));
  row->addWidget(reference_);
  for (QPushButton* b : {run_, rerun_, apply_, colour_, save_}) row->addWidget(b);
  row->addStretch(1);
  return bar;
}

QWidget* NetworkPanel::buildLinkActions() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  accept_ = button(tr("Accept"), "linkAccept",
                   tr("Take the selected link as true whatever its verdict: never dropped (you checked it)"), bar);
  reject_ = button(tr("Reject"), "linkReject", tr("Leave the selected link out of the adjustment"), bar);
  clear_ = button(tr("Clear decision"), "linkClear", tr("The selected link counts as its verdict says"), bar);
  for (QPushButton* b : {accept_, reject_, clear_}) row->addWidget(b);
  row->addStretch(1);
  row->addWidget(new QLabel(tr("then Re-run adjustment"), bar));
  return bar;
}

QWidget* NetworkPanel::buildControlPage() {
  auto* page = new QWidget(this);
  page->setObjectName("networkControlPage");
  auto* layout = new QVBoxLayout(page);
  layout->addWidget(control_);
  layout->addWidget(georeference_, 1);
  return page;
}

void NetworkPanel::connectSignals() {
  connect(run_, &QPushButton::clicked, this, &NetworkPanel::run);
  connect(rerun_, &QPushButton::clicked, this, &NetworkPanel::rerun);
  connect(apply_, &QPushButton::clicked, runner_, &NetworkRunner::applyPoses);
  connect(colour_, &QPushButton::clicked, runner_, &NetworkRunner::colourByStation);
  connect(save_, &QPushButton::clicked, this, &NetworkPanel::saveReport);
  connect(accept_, &QPushButton::clicked, this, [this] { decideSelectedLink(LinkDecision::Accept); });
  connect(reject_, &QPushButton::clicked, this, [this] { decideSelectedLink(LinkDecision::Reject); });
  connect(clear_, &QPushButton::clicked, this, [this] { decideSelectedLink(LinkDecision::None); });
  connect(runner_, &NetworkRunner::changed, this, &NetworkPanel::showSession);
  connect(runner_, &NetworkRunner::busyChanged, this, &NetworkPanel::updateEnabled);
  connect(stations_, &StationTable::lockToggled, this, [this](int station, bool locked) {
    if (!runner_->setLocked(std::size_t(station), locked)) showSession();  // refused: the box goes back
  });
  // One selection across the plan and the tables.
  connect(plan_, &NetworkPlanView::stationClicked, this, [this](int i) {
    stations_->selectStation(i);
    tabs_->setCurrentWidget(stations_);
  });
  connect(plan_, &NetworkPlanView::linkClicked, this, [this](int k) {
    links_->selectLink(k);
    tabs_->setCurrentIndex(1);
    updateEnabled();
  });
  connect(stations_, &StationTable::stationSelected, plan_, &NetworkPlanView::selectStation);
  connect(links_, &LinkTable::linkSelected, this, [this](int k) {
    plan_->selectLink(k);
    updateEnabled();
  });
  connect(&app_.scene, &Scene::layersChanged, this, [this] { reference_->refresh(app_.scene); });
}

bool NetworkPanel::run() { return runner_->run(reference_->model(app_.scene), reference_->station()); }

bool NetworkPanel::rerun() { return runner_->rerunAdjustment(); }

bool NetworkPanel::saveReport() {
  const QString path = chooseFileToSave(this, FolderKind::Export, tr("Save network report"), "network-report.html",
                                        tr("HTML report (*.html);;JSON report (*.json)"));
  return !path.isEmpty() && runner_->saveReport(path);
}

void NetworkPanel::decideSelectedLink(LinkDecision decision) {
  const int k = links_->selectedLink();
  if (k >= 0) runner_->setLinkDecision(std::size_t(k), decision);
}

void NetworkPanel::showSession() {
  const auto session = runner_->session();
  plan_->setSession(session);
  stations_->setSession(session, runner_->decisions());
  links_->setSession(session, runner_->decisions());
  if (session) georeference_->setReport(session->report);
  else georeference_->clear();
  if (session)
    summary_->setText(tr("%1 (exit code %2 as plumb-cli)")
                          .arg(networkSummary(session->report))
                          .arg(session->report.value("exit_code", 0)));
  updateEnabled();
}

void NetworkPanel::updateEnabled() {
  const bool busy = runner_->busy(), done = runner_->session() != nullptr;
  run_->setEnabled(!busy);
  reference_->setEnabled(!busy);
  params_->setEnabled(!busy);
  control_->setEnabled(!busy);
  for (QPushButton* b : {rerun_, apply_, colour_, save_}) b->setEnabled(!busy && done);
  const bool link = !busy && links_->selectedLink() >= 0;
  for (QPushButton* b : {accept_, reject_, clear_}) b->setEnabled(link);
}

}  // namespace plumb::ui
