#include "ui/network/control_box.hpp"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QToolButton>

#include "ui/actions/file_dialogs.hpp"

namespace plumb::ui {

ControlBox::ControlBox(ControlSettings& settings, QWidget* parent) : QWidget(parent), settings_(settings) {
  setObjectName("networkControl");
  auto* control = textField("networkControlFile", tr("name, E, N, H[, control|check] per line"),
                            &ControlSettings::control);
  control->setToolTip(tr("Control and check points in the project's grid; 3 control points seen by the stations "
                         "georeference the network, check points are only reported"));
  auto* targets = textField("networkTargetsFile", tr("station, point, x, y, z per line (station frame)"),
                            &ControlSettings::targets);
  targets->setToolTip(tr("Where the stations saw the points, in each station's own frame (as scanner software "
                         "exports its targets)"));
  auto* grid = textField("networkGridScale", tr("1, a factor (0.99988) or a CRS (EPSG:32632)"), &ControlSettings::grid);
  grid->setToolTip(tr("The grid's scale factor (grid distance / ground distance): a number, or a projected "
                      "coordinate system whose factor PROJ computes at the control points; empty: 1"));
  auto* sigma = new QDoubleSpinBox(this);
  sigma->setObjectName("networkTargetSigma");
  sigma->setRange(0.01, 1000.0);
  sigma->setDecimals(2);
  sigma->setSuffix(tr(" mm"));
  sigma->setValue(settings_.target_sigma * 1000.0);
  sigma->setToolTip(tr("Standard deviation of one coordinate of a target observation"));
  connect(sigma, &QDoubleSpinBox::valueChanged, this, [this](double mm) { settings_.target_sigma = mm / 1000.0; });
  auto* form = new QFormLayout(this);
  form->addRow(tr("Control points"), withBrowse(control, tr("Control and check points")));
  form->addRow(tr("Targets"), withBrowse(targets, tr("Target observations")));
  form->addRow(tr("Grid scale"), grid);
  form->addRow(tr("Target sigma"), sigma);
}

QLineEdit* ControlBox::textField(const char* name, const QString& placeholder, std::string ControlSettings::*field) {
  auto* edit = new QLineEdit(QString::fromStdString(settings_.*field), this);
  edit->setObjectName(name);
  edit->setPlaceholderText(placeholder);
  edit->setClearButtonEnabled(true);
  connect(edit, &QLineEdit::textChanged, this, [this, field](const QString& text) {
    settings_.*field = text.trimmed().toStdString();
  });
  return edit;
}

QWidget* ControlBox::withBrowse(QLineEdit* field, const QString& caption) {
  auto* row = new QWidget(this);
  auto* layout = new QHBoxLayout(row);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(field, 1);
  auto* browse = new QToolButton(row);
  browse->setText("...");
  browse->setObjectName(field->objectName() + "Browse");
  layout->addWidget(browse);
  connect(browse, &QToolButton::clicked, this, [this, field, caption] {
    const QString path = chooseFileToOpen(this, FolderKind::Data, caption, tr("CSV files (*.csv *.txt);;All files (*)"));
    if (!path.isEmpty()) field->setText(path);
  });
  return row;
}

}  // namespace plumb::ui
