#pragma once
// The control survey's inputs in the Network dock, editing the runner's ControlSettings in
// place (as NetworkParamsBox edits its parameters): the control points file, the targets file
// (each typed or chosen with "..."), the grid's scale (a factor, or a CRS whose factor PROJ
// computes at the control points) and the target sigma in mm. Nothing is read here: the run
// reads the files, so an error is reported where the run is refused.
#include <QWidget>

#include "ui/network/control_settings.hpp"

class QDoubleSpinBox;
class QLineEdit;

namespace plumb::ui {

class ControlBox : public QWidget {
  Q_OBJECT
 public:
  ControlBox(ControlSettings& settings, QWidget* parent = nullptr);

 private:
  QLineEdit* textField(const char* name, const QString& placeholder, std::string ControlSettings::*field);
  QWidget* withBrowse(QLineEdit* field, const QString& caption);
  ControlSettings& settings_;
};

}  // namespace plumb::ui
