#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// Registration > Register stations as a network...: shows and raises the Network dock (every
/// scan of every open point dataset a station), where the run starts.
class NetworkReaction : public Reaction {
  Q_OBJECT
 public:
  NetworkReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
