#pragma once
// The parts of the application that reactions (menu actions) work on. Owned by MainWindow
// (Qt parent ownership); reactions hold a reference to this for their lifetime.
#include <cstdint>

class QMainWindow;
class QUndoStack;

namespace plumb::ui {

class LayerTreePanel;
class LogPanel;
class PropertiesPanel;
class RegistrationPanel;
class ManualAlignPanel;
class NetworkPanel;
class MeasureTool;
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
  QUndoStack& undo;  ///< every applied transform (Edit > Undo/Redo)
  RegistrationPanel* registration = nullptr;  ///< the Registration dock (set once built)
  ManualAlignPanel* manual = nullptr;         ///< the Manual alignment dock
  NetworkPanel* network = nullptr;            ///< the Network dock (stations as one network)
  MeasureTool* measure = nullptr;             ///< View > Measure (view clicks measure while on)
  /// Memory budget promised to point files still loading (load_budget.hpp, loadShare), bytes.
  std::uint64_t loads_reserved = 0;
};

}  // namespace plumb::ui
