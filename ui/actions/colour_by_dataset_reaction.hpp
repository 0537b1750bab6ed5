#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// View > Colour by dataset (D): every dataset in its own colour (the Dataset colour mode, point
/// sizes kept), recoloured in the background; the scene legend names them. Each dataset keeps
/// its own style afterwards (Properties > Colour by).
class ColourByDatasetReaction : public Reaction {
  Q_OBJECT
 public:
  ColourByDatasetReaction(QAction* action, AppContext& app);

 protected:
  void onTriggered() override;
};

}  // namespace plumb::ui
