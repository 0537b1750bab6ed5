#pragma once
// The parts of the application that reactions (menu actions) work on. Owned by MainWindow
// (Qt parent ownership); reactions hold a reference to this for their lifetime.
class QMainWindow;

namespace plumb::ui {

class LayerTreePanel;
class LogPanel;
class PropertiesPanel;
class RecentFiles;
class Scene;
class TaskManager;
class VtkViewWidget;

struct AppContext {
  QMainWindow& window;
  VtkViewWidget& view;
  Scene& scene;
  TaskManager& tasks;
  LogPanel& log;
  LayerTreePanel& layers;
  PropertiesPanel& properties;
  RecentFiles& recent;
};

}  // namespace plumb::ui
