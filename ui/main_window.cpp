#include "ui/main_window.hpp"

#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QScrollArea>
#include <QStatusBar>
#include <QUndoStack>

#include <tuple>

#include "ui/actions/attach_trajectory_reaction.hpp"
#include "ui/actions/colour_by_dataset_reaction.hpp"
#include "ui/actions/export_cloud_reaction.hpp"
#include "ui/actions/full_detail_reaction.hpp"
#include "ui/actions/open_file_reaction.hpp"
#include "ui/actions/help_reactions.hpp"
#include "ui/actions/inspection_reactions.hpp"
#include "ui/actions/network_reaction.hpp"
#include "ui/actions/project_reactions.hpp"
#include "ui/actions/registration_step_reaction.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/actions/recent_files_reaction.hpp"
#include "ui/actions/remove_layer_reaction.hpp"
#include "ui/actions/reset_camera_reaction.hpp"
#include "ui/actions/screenshot_reaction.hpp"
#include "ui/actions/standard_view_reaction.hpp"
#include "ui/actions/undo_redo_reaction.hpp"
#include "ui/actions/zoom_to_layer_reaction.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_controller.hpp"
#include "ui/network/network_panel.hpp"
#include "ui/inspection/clip_panel.hpp"
#include "ui/inspection/measure_tool.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/memory_status_widget.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/panels/task_progress_widget.hpp"
#include "ui/project/project_file.hpp"
#include "ui/project/unsaved_changes.hpp"
#include "ui/registration/manual_align_panel.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/load_budget.hpp"
#include "ui/tasks/load_files.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/empty_scene_hint.hpp"
#include "ui/view/lod_controller.hpp"
#include "ui/view/scene_legend.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle("Plumb");
  setAcceptDrops(true);
  auto* view = new VtkViewWidget(this);
  view->setObjectName("view");
  setCentralWidget(view);
  auto* scene = new Scene(view->renderer(), this);
  auto* tasks = new TaskManager(this);
  scene->setTaskManager(tasks);  // recolouring runs as a background task
  auto* log = new LogPanel(this);
  auto* tree = new LayerTreePanel(*scene, this);
  auto* properties = new PropertiesPanel(*scene, this);
  auto* recent = new RecentFiles(this);
  auto* undo = new QUndoStack(this);
  context_.reset(
      new AppContext{*this, *view, *scene, *tasks, *log, *tree, *properties, *recent, *undo});
  context_->registration = new RegistrationPanel(*context_, this);
  context_->manual = new ManualAlignPanel(*context_, this);
  context_->network = new NetworkPanel(*context_, this);
  context_->measure = new MeasureTool(*context_, this);
  lod_ = new LodController(*view, *scene, this);
  new DetailController(*context_, *lod_, this);  // full-resolution detail of subsampled files
  new SceneLegend(*scene, view->renderer(), this);  // datasets / scans by colour, in the view
  new EmptySceneHint(*scene, *view);

  connect(scene, &Scene::renderNeeded, view, &VtkViewWidget::requestRender);
  connect(tree, &LayerTreePanel::currentLayerChanged, properties, &PropertiesPanel::showLayer);
  connect(view, &VtkViewWidget::clicked, this, [this](int x, int y) {
    if (context_->manual->picking() || context_->measure->active()) return;
    if (auto hit = context_->scene.pick(x, y)) {
      context_->properties.showRows(hit->layer->name(), hit->rows);
      context_->scene.highlight(&*hit);
    }
  });
  statusBar()->addPermanentWidget(new TaskProgressWidget(*tasks, this));
  // "Showing N of M points" while the view draws a subset (level of detail).
  auto* detail = new QLabel(this);
  detail->setObjectName("detailLabel");
  statusBar()->addPermanentWidget(detail);
  connect(lod_, &LodController::detailTextChanged, detail, &QLabel::setText);
  statusBar()->addPermanentWidget(new MemoryStatusWidget([this] { return memoryBudget(*context_); }, this));
  // A colour mode the data cannot show is said, not silently replaced.
  connect(scene, &Scene::colourFallback, this, [this](const QString& message) {
    context_->log.warning(message);
    statusBar()->showMessage(message, 8000);
  });
  connect(tasks, &TaskManager::taskFinished, this,
          [this](const QString& title, bool ok, const QString& message) {
            statusBar()->showMessage(ok ? tr("%1: done").arg(title)
                                        : tr("%1: %2").arg(title, message),
                                     5000);
          });
  createDocks();
  createMenus();
  resize(1400, 900);
}

MainWindow::~MainWindow() {
  context_->tasks.cancelAll();
  // While the scene and the panels still exist: the stack tells them it empties.
  context_->undo.clear();
}

void MainWindow::createDocks() {
  auto dock = [this](const QString& title, const QString& name, QWidget* content,
                     Qt::DockWidgetArea area) {
    auto* d = new QDockWidget(title, this);
    d->setObjectName(name);
    d->setWidget(content);
    addDockWidget(area, d);
    return d;
  };
  dock(tr("Layers"), "layersDock", &context_->layers, Qt::LeftDockWidgetArea);
  dock(tr("Properties"), "propertiesDock", &context_->properties, Qt::LeftDockWidgetArea);
  dock(tr("Log"), "logDock", &context_->log, Qt::BottomDockWidgetArea);
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(context_->registration);
  scroll->setWidgetResizable(true);
  scroll->setMinimumWidth(340);
  dock(tr("Registration"), "registrationDock", scroll, Qt::RightDockWidgetArea);
  QDockWidget* manual =
      dock(tr("Manual alignment"), "manualDock", context_->manual, Qt::RightDockWidgetArea);
  manual->hide();
  dock(tr("Clipping"), "clipDock", new ClipPanel(*context_, this), Qt::RightDockWidgetArea)->hide();
  dock(tr("Network"), "networkDock", context_->network, Qt::BottomDockWidgetArea)->hide();
}

void MainWindow::createMenus() {
  AppContext& app = *context_;
  QMenu* file = menuBar()->addMenu(tr("&File"));
  new OpenFileReaction(file->addAction(tr("&Open..."), QKeySequence::Open), app);
  new RecentFilesReaction(file->addMenu(tr("Recent files")), app);
  new AttachTrajectoryReaction(file->addAction(tr("Attach t&rajectory...")), app);
  file->addSeparator();
  new OpenProjectReaction(file->addAction(tr("Open &project..."), QKeySequence("Ctrl+Shift+O")), app);
  new SaveProjectReaction(file->addAction(tr("Save project..."), QKeySequence::Save), app);
  file->addSeparator();
  new ExportCloudReaction(file->addAction(tr("Export registered &cloud..."), QKeySequence("Ctrl+E")), app);
  new ExportTransformReaction(file->addAction(tr("Export &transform...")), app);
  new ExportReportReaction(
      file->addAction(tr("Export registration &report..."), QKeySequence("Ctrl+Shift+E")), app);
  new ScreenshotReaction(file->addAction(tr("Export &screenshot...")), app);
  file->addSeparator();
  connect(file->addAction(tr("&Quit"), QKeySequence::Quit), &QAction::triggered, this,
          &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  new UndoRedoReaction(edit->addAction(tr("&Undo")), app, UndoRedoReaction::Step::Undo);
  new UndoRedoReaction(edit->addAction(tr("&Redo")), app, UndoRedoReaction::Step::Redo);
  edit->addSeparator();
  new RemoveLayerReaction(edit->addAction(tr("&Remove layer"), QKeySequence::Delete), app);

  using Step = RegistrationStepReaction::Step;
  QMenu* reg = menuBar()->addMenu(tr("&Registration"));
  const std::tuple<QString, Step, const char*> steps[] = {
      {tr("&Detect features"), Step::DetectFeatures, "Ctrl+D"},
      {tr("&Register"), Step::Register, "Ctrl+R"},
      {tr("Colour by &distance"), Step::ColourByDistance, "Ctrl+Shift+D"},
      {tr("&Accept result"), Step::Accept, "Ctrl+Return"},
      {tr("Re&vert result"), Step::Revert, "Ctrl+Backspace"}};
  for (const auto& [label, step, key] : steps)
    new RegistrationStepReaction(reg->addAction(label, QKeySequence(key)), app, step);
  reg->addSeparator();
  new NetworkReaction(reg->addAction(tr("Register stations as a &network...")), app);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  // Ctrl+1..5: the standard views in menu order.
  const std::tuple<QString, StandardView, const char*> views[] = {
      {tr("&Top"), StandardView::Top, "Ctrl+1"},    {tr("&Front"), StandardView::Front, "Ctrl+2"},
      {tr("&Side"), StandardView::Right, "Ctrl+3"}, {tr("&Back"), StandardView::Back, "Ctrl+4"},
      {tr("&Iso"), StandardView::Iso, "Ctrl+5"}};
  for (const auto& [label, v, key] : views)
    new StandardViewReaction(view->addAction(label, QKeySequence(key)), app, v);
  view->addSeparator();
  new ZoomToLayerReaction(view->addAction(tr("&Zoom to layer"), QKeySequence("Ctrl+L")), app);
  new ResetCameraReaction(view->addAction(tr("&Reset camera"), QKeySequence("Ctrl+0")), app);
  new MeasureReaction(view->addAction(tr("&Measure point / distance")), app);  // M
  new ProjectionReaction(view->addAction(tr("&Orthographic projection")), app);  // O
  new BlinkReaction(view->addAction(tr("&Blink before/after")), app);  // B
  new ColourByDatasetReaction(view->addAction(tr("&Colour by dataset")), app);  // D
  new FullDetailReaction(view->addAction(tr("Full detail when still (may be slow)")), app, *lod_);
  view->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  new HelpReaction(help->addAction(tr("&Getting started"), QKeySequence::HelpContents), app,
                   HelpReaction::Topic::GettingStarted);
  new HelpReaction(help->addAction(tr("&About Plumb")), app, HelpReaction::Topic::About);
}

void MainWindow::openFiles(const QStringList& paths) {
  // A project among the files replaces the scene; other files load as layers.
  QStringList data;
  for (const QString& p : paths) {
    if (p.endsWith(".plumb.json", Qt::CaseInsensitive)) {
      try {
        openProject(*context_, p);
      } catch (const std::exception& e) {
        context_->log.error(QString::fromUtf8(e.what()));
      }
    } else {
      data << p;
    }
  }
  if (!data.isEmpty()) loadFiles(*context_, data);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
  QStringList paths;
  for (const QUrl& url : event->mimeData()->urls())
    if (url.isLocalFile()) paths << url.toLocalFile();
  if (!paths.isEmpty()) {
    openFiles(paths);
    event->acceptProposedAction();
  }
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!confirmClose(*context_)) {
    event->ignore();
    return;
  }
  context_->tasks.cancelAll();
  QMainWindow::closeEvent(event);
}

}  // namespace plumb::ui
