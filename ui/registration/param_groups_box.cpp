#include "ui/registration/param_groups_box.hpp"

#include <QScrollArea>

#include "registration/auto/pipeline_param_groups.hpp"
#include "ui/panels/param_panel.hpp"

namespace plumb::ui {

namespace {
constexpr const char* kTopLevelGroup = "registration";
}

ParamGroupsBox::ParamGroupsBox(PipelineParams& params, QWidget* parent) : QToolBox(parent) {
  // The top-level parameters (the one seed, refine, ...) first; the method has its combo box.
  addGroup(kTopLevelGroup, "Registration", makeParamPanel(PipelineParams::schema(), params, {"method"}));
  forEachParamGroup(params, [this](const char* key, const char* label, const auto& schema, auto& group) {
    addGroup(key, label, makeParamPanel(schema, group));
  });
  setMinimumHeight(220);
}

void ParamGroupsBox::addGroup(const char* key, const char* label, ParamPanel* panel) {
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  addItem(scroll, tr(label));
  panels_.emplace_back(key, panel);
  connect(panel, &ParamPanel::changed, this, &ParamGroupsBox::changed);
}

void ParamGroupsBox::refresh() {
  for (auto& [key, panel] : panels_) panel->refresh();
}

void ParamGroupsBox::enableFor(RegistrationMethod method) {
  for (int g = 0; g < count(); ++g) setItemEnabled(g, paramGroupUsedBy(panels_[std::size_t(g)].first, method));
}

}  // namespace plumb::ui
