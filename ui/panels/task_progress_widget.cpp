#include "ui/panels/task_progress_widget.hpp"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

TaskProgressWidget::TaskProgressWidget(TaskManager& tasks, QWidget* parent)
    : QWidget(parent),
      tasks_(tasks),
      label_(new QLabel(this)),
      bar_(new QProgressBar(this)),
      cancel_(new QPushButton(tr("Cancel"), this)) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(label_);
  layout->addWidget(bar_);
  layout->addWidget(cancel_);
  bar_->setRange(0, 1000);
  bar_->setMaximumWidth(220);
  cancel_->setObjectName("cancelTasks");
  connect(cancel_, &QPushButton::clicked, &tasks_, &TaskManager::cancelAll);
  connect(&tasks_, &TaskManager::taskStarted, this, [this](Task* task) {
    connect(task, &Task::progressed, this, [this] { refresh(); });
    refresh();
  });
  connect(&tasks_, &TaskManager::taskFinished, this, [this] { refresh(); });
  refresh();
}

void TaskProgressWidget::refresh() {
  const auto& running = tasks_.running();
  setVisible(!running.empty());
  if (running.empty()) return;
  double sum = 0.0;
  for (const Task* t : running) sum += t->fraction();
  const Task* first = running.front();
  QString text = first->title();
  if (!first->stage().isEmpty()) text += ": " + first->stage();
  if (running.size() > 1) text += tr(" (+%1 more)").arg(running.size() - 1);
  label_->setText(text);
  bar_->setValue(static_cast<int>(1000.0 * sum / static_cast<double>(running.size())));
}

}  // namespace plumb::ui
