#pragma once
// Finding the main window's menu actions the way a user reads them (labels without their '&'
// shortcut markers), so GUI tests trigger the real File/View/... actions.
#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QString>

namespace plumb::test {

inline QString plainLabel(QString text) { return text.remove('&'); }

/// The action `text` of the menu-bar menu `menu`, or nullptr.
inline QAction* menuAction(QMainWindow& window, const QString& menu, const QString& text) {
  for (QAction* top : window.menuBar()->actions()) {
    if (plainLabel(top->text()) != menu || !top->menu()) continue;
    for (QAction* a : top->menu()->actions())
      if (plainLabel(a->text()) == text) return a;
  }
  return nullptr;
}

}  // namespace plumb::test
