#include "ui/view/empty_scene_hint.hpp"

#include <QEvent>

#include <algorithm>

#include "ui/layers/scene.hpp"

namespace plumb::ui {

EmptySceneHint::EmptySceneHint(Scene& scene, QWidget& view)
    : QLabel(&view), scene_(scene), view_(view) {
  setObjectName("emptySceneHint");
  setText(tr("<b>Open scans or a BIM model</b>: File &gt; Open (Ctrl+O) or drag files here.<br>"
             "Reopen your work: File &gt; Open project (Ctrl+Shift+O).<br>"
             "F1: Getting started"));
  setAlignment(Qt::AlignCenter);
  setWordWrap(true);
  setMargin(14);
  setAttribute(Qt::WA_TransparentForMouseEvents);  // drops and clicks reach the view
  setStyleSheet("QLabel { color: #e8e8e8; background: rgba(0, 0, 0, 120); border-radius: 6px; }");
  view_.installEventFilter(this);
  connect(&scene_, &Scene::layersChanged, this, &EmptySceneHint::follow);
  follow();
}

bool EmptySceneHint::eventFilter(QObject* watched, QEvent* event) {
  if (watched == &view_ && event->type() == QEvent::Resize) centre();
  return QLabel::eventFilter(watched, event);
}

void EmptySceneHint::follow() {
  const bool empty = scene_.layers().empty();
  setVisible(empty);
  if (empty) centre();
}

void EmptySceneHint::centre() {
  const int width = std::min(520, std::max(200, view_.width() - 40));
  setFixedWidth(width);
  adjustSize();
  move((view_.width() - this->width()) / 2, (view_.height() - height()) / 2);
}

}  // namespace plumb::ui
