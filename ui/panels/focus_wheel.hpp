#pragma once
// An editor (spin box, combo box) that the mouse wheel changes only while it has the focus
// (clicked or tabbed into): over an unfocused editor the wheel is ignored, so it goes on to
// the scroll area around it instead of silently changing a value the user scrolls past.
#include <QWheelEvent>
#include <QWidget>

namespace plumb::ui {

template <class Editor>
class FocusWheel : public Editor {
 public:
  explicit FocusWheel(QWidget* parent = nullptr) : Editor(parent) {
    this->setFocusPolicy(Qt::StrongFocus);  // the wheel does not give the focus
  }

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (this->hasFocus()) Editor::wheelEvent(event);
    else event->ignore();  // propagates to the parent
  }
};

}  // namespace plumb::ui
