#include "ui/network/network_params_box.hpp"

#include <QScrollArea>

#include <string_view>

#include "ui/panels/param_panel.hpp"

namespace plumb::ui {

NetworkParamsBox::NetworkParamsBox(NetworkParams& params, QWidget* parent) : QToolBox(parent) {
  setObjectName("networkParams");
  forEachNetworkParamGroup(params, [this](const char* key, const char* label, const auto& schema, auto& group) {
    if (std::string_view(key) == "mms") return;  // MMS windows are plumb-cli's (network_tasks.cpp)
    ParamPanel* panel = makeParamPanel(schema, group);
    panel->setObjectName(key);
    auto* scroll = new QScrollArea;
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    addItem(scroll, tr(label));
    panels_.push_back(panel);
  });
}

void NetworkParamsBox::refresh() {
  for (ParamPanel* panel : panels_) panel->refresh();
}

}  // namespace plumb::ui
