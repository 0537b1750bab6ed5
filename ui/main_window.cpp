#include "ui/main_window.hpp"

#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QMenuBar>
#include <QMimeData>
#include <QStatusBar>

#include "ui/actions/open_file_reaction.hpp"
#include "ui/actions/recent_files.hpp"
#include "ui/actions/recent_files_reaction.hpp"
#include "ui/actions/remove_layer_reaction.hpp"
#include "ui/actions/reset_camera_reaction.hpp"
#include "ui/actions/screenshot_reaction.hpp"
#include "ui/actions/standard_view_reaction.hpp"
#include "ui/actions/zoom_to_layer_reaction.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/layer_tree_panel.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/panels/task_progress_widget.hpp"
#include "ui/tasks/load_files.hpp"
#include "ui/tasks/task_manager.hpp"
#include "ui/view/lod_controller.hpp"
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
  auto* log = new LogPanel(this);
  auto* tree = new LayerTreePanel(*scene, this);
  auto* properties = new PropertiesPanel(*scene, this);
  auto* recent = new RecentFiles(this);
  context_.reset(new AppContext{*this, *view, *scene, *tasks, *log, *tree, *properties, *recent});
  new LodController(*view, *scene, this);

  connect(scene, &Scene::renderNeeded, view, &VtkViewWidget::requestRender);
  connect(tree, &LayerTreePanel::currentLayerChanged, properties, &PropertiesPanel::showLayer);
  connect(view, &VtkViewWidget::clicked, this, [this](int x, int y) {
    if (auto hit = context_->scene.pick(x, y))
      context_->properties.showRows(hit->layer->name(), hit->rows);
  });
  statusBar()->addPermanentWidget(new TaskProgressWidget(*tasks, this));
  connect(tasks, &TaskManager::taskFinished, this,
          [this](const QString& title, bool ok, const QString& message) {
            statusBar()->showMessage(ok ? tr("%1: done").arg(title)
                                        : tr("%1: %2").arg(title, message),
                                     5000);
          });
  createDocks();
  createMenus();
  resize(1280, 800);
}

MainWindow::~MainWindow() {
  context_->tasks.cancelAll();
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
}

void MainWindow::createMenus() {
  AppContext& app = *context_;
  QMenu* file = menuBar()->addMenu(tr("&File"));
  new OpenFileReaction(file->addAction(tr("&Open..."), QKeySequence::Open), app);
  new RecentFilesReaction(file->addMenu(tr("Recent files")), app);
  file->addSeparator();
  new ScreenshotReaction(file->addAction(tr("Export &screenshot...")), app);
  file->addSeparator();
  connect(file->addAction(tr("&Quit"), QKeySequence::Quit), &QAction::triggered, this,
          &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  new RemoveLayerReaction(edit->addAction(tr("&Remove layer"), QKeySequence::Delete), app);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  const std::pair<QString, StandardView> views[] = {
      {tr("&Top"), StandardView::Top},     {tr("&Front"), StandardView::Front},
      {tr("&Side"), StandardView::Right},  {tr("&Back"), StandardView::Back},
      {tr("&Iso"), StandardView::Iso}};
  for (const auto& [label, v] : views) new StandardViewReaction(view->addAction(label), app, v);
  view->addSeparator();
  new ZoomToLayerReaction(view->addAction(tr("&Zoom to layer")), app);
  new ResetCameraReaction(view->addAction(tr("&Reset camera")), app);
  view->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>()) view->addAction(d->toggleViewAction());
}

void MainWindow::openFiles(const QStringList& paths) { loadFiles(*context_, paths); }

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
  context_->tasks.cancelAll();
  QMainWindow::closeEvent(event);
}

}  // namespace plumb::ui
