#pragma once
#include "ui/actions/reaction.hpp"

namespace plumb::ui {

/// File > Export registered cloud: the registration source (or the current dataset) with its
/// transform applied, as PLY, E57 (scan poses) or LAS, in the background.
class ExportCloudReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

/// File > Export transform: the same layer's transform as JSON or 4x4 text.
class ExportTransformReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

/// File > Export report: the last registration's report to hand over (HTML) or its quality
/// report (JSON), as plumb-cli register --report writes them.
class ExportReportReaction : public Reaction {
  Q_OBJECT
 public:
  using Reaction::Reaction;

 protected:
  void onTriggered() override;
};

/// The layer File > Export acts on: the current root layer of the tree if it is a dataset or
/// model, else the Registration dock's source.
class Layer;
Layer* exportLayer(AppContext& app);

}  // namespace plumb::ui
