#pragma once
// Status-bar widget: progress of the running tasks with a Cancel button.
#include <QWidget>

class QLabel;
class QProgressBar;
class QPushButton;

namespace plumb::ui {

class TaskManager;

class TaskProgressWidget : public QWidget {
  Q_OBJECT
 public:
  explicit TaskProgressWidget(TaskManager& tasks, QWidget* parent = nullptr);

 private:
  void refresh();
  TaskManager& tasks_;
  QLabel* label_;
  QProgressBar* bar_;
  QPushButton* cancel_;
};

}  // namespace plumb::ui
