#pragma once
// The network's own parameter groups (forEachNetworkParamGroup: candidate pairs, link weights,
// global adjustment), one page each, generated from their schemas and editing `params` in
// place. Each link is registered with the pipeline's parameters (NetworkParams::link) at
// their defaults, as plumb-cli network without --set.
#include <QToolBox>

#include <vector>

#include "registration/network/network_params.hpp"

namespace plumb::ui {

class ParamPanel;

class NetworkParamsBox : public QToolBox {
  Q_OBJECT
 public:
  NetworkParamsBox(NetworkParams& params, QWidget* parent = nullptr);
  void refresh();

 private:
  std::vector<ParamPanel*> panels_;
};

}  // namespace plumb::ui
