#pragma once
// Help menu: Getting started (F1) and About Plumb. Each opens a non-modal message box (the
// window stays usable, and tests can read and close it).
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

class HelpReaction : public Reaction {
  Q_OBJECT
 public:
  enum class Topic {
    GettingStarted,  ///< the steps of a registration in the desktop, in field terms
    About,           ///< version, what Plumb does, the libraries it is built on
  };
  HelpReaction(QAction* action, AppContext& app, Topic topic);

 protected:
  void onTriggered() override;

 private:
  Topic topic_;
};

}  // namespace plumb::ui
