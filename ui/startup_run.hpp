#pragma once
// What `plumb` does after start-up, from its command line:
//   plumb FILE...                      load the files (a *.plumb.json among them is a project)
//   plumb --project P.plumb.json       open a project
//   plumb ... --register S,T           then register file S onto file T (0-based indices in
//                                      the order given; for a project, its layer indices)
//   plumb ... --screenshot OUT.png     then render the view into OUT.png and quit (tests,
//                                      documentation); exit 1 on any error; after --register
//                                      the verdict level's code as plumb-cli register: 0
//                                      usable, 3 check visually, 2 failed or ambiguous.
#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>
#include <utility>
#include <vector>

namespace plumb::ui {

class Layer;
class MainWindow;

struct StartupOptions {
  QStringList files;
  QString project;
  std::optional<std::pair<int, int>> register_pair;
  QString screenshot;  ///< empty: stay interactive
  bool whole_window = false;  ///< screenshot of the window with its docks, not just the view
};

/// Parses "S,T" (two non-negative integers); nullopt if malformed.
std::optional<std::pair<int, int>> parseRegisterPair(const QString& text);

class StartupRun : public QObject {
  Q_OBJECT
 public:
  StartupRun(MainWindow& window, StartupOptions options, QObject* parent = nullptr);
  void start();

 private:
  void loaded(bool ok);
  void registerPair();
  void finish(bool ok);
  int exitCode(bool ok) const;
  MainWindow& window_;
  StartupOptions options_;
  std::vector<Layer*> layers_;  ///< per file index, in command-line order
  int remaining_ = 0;
  bool ok_ = true;
};

}  // namespace plumb::ui
