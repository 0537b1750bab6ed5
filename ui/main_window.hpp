#pragma once
// The Plumb main window: the 3D view in the centre, docks for layers, properties and log,
// menus whose behaviour lives in reactions (ui/actions).
#include <QMainWindow>

#include <memory>

#include "ui/app_context.hpp"

namespace plumb::ui {

class LodController;

class MainWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  AppContext& context() { return *context_; }
  /// Starts loading files in the background (command line, drops, recent files).
  void openFiles(const QStringList& paths);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void createDocks();
  void createMenus();
  std::unique_ptr<AppContext> context_;
  LodController* lod_ = nullptr;  ///< level of detail of the view (child QObject)
};

}  // namespace plumb::ui
