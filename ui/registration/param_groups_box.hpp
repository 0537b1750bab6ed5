#pragma once
// The Registration dock's parameter editors: one page per parameter group of the pipeline
// (forEachParamGroup), after the top-level parameters, each a ParamPanel generated from the
// group's schema and editing `params` in place. The groups the chosen method does not use are
// disabled.
#include <QToolBox>

#include <string>
#include <utility>
#include <vector>

#include "registration/auto/registration_pipeline.hpp"

namespace plumb::ui {

class ParamPanel;

class ParamGroupsBox : public QToolBox {
  Q_OBJECT
 public:
  ParamGroupsBox(PipelineParams& params, QWidget* parent = nullptr);

  /// Re-reads every editor (after the params changed elsewhere, e.g. a project).
  void refresh();
  /// Enables the groups `method` uses.
  void enableFor(RegistrationMethod method);

 signals:
  /// A value was edited.
  void changed();

 private:
  void addGroup(const char* key, const char* label, ParamPanel* panel);

  std::vector<std::pair<std::string, ParamPanel*>> panels_;
};

}  // namespace plumb::ui
