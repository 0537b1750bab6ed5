#pragma once
// The parameter panel generated from a core ParamSchema (one source of truth for names,
// units, defaults, ranges, tooltips): spin boxes with units for reals and integers, check
// boxes for booleans, combo boxes for choices. Advanced parameters go in a collapsible group.
#include <QWidget>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "common/params.hpp"

namespace plumb::ui {

class ParamPanel : public QWidget {
  Q_OBJECT
 public:
  using Getter = std::function<double(std::size_t field)>;
  using Setter = std::function<void(std::size_t field, double value)>;

  /// One editor per spec; `get` gives current values, `set` receives edits.
  ParamPanel(std::vector<ParamSpec> specs, Getter get, Setter set, QWidget* parent = nullptr);
  /// Re-reads every value through the getter (after the params were changed elsewhere).
  void refresh();
  /// The editor of a key (QDoubleSpinBox, QSpinBox, QCheckBox or QComboBox), for tests.
  QWidget* editor(const std::string& key) const;

 signals:
  void changed();

 private:
  QWidget* makeEditor(std::size_t i);
  std::vector<ParamSpec> specs_;
  std::vector<QWidget*> editors_;
  Getter get_;
  Setter set_;
  bool loading_ = false;
};

/// A panel editing `params` (which must outlive the panel) through its schema, without the
/// parameters whose keys are in `skip` (edited by another widget).
template <class P>
ParamPanel* makeParamPanel(const ParamSchema<P>& schema, P& params,
                           const std::vector<std::string>& skip, QWidget* parent = nullptr) {
  std::vector<ParamSpec> specs;
  std::vector<std::size_t> fields;  // schema field of each editor
  for (std::size_t i = 0; i < schema.fields().size(); ++i) {
    const ParamSpec& spec = schema.fields()[i].spec;
    if (std::find(skip.begin(), skip.end(), spec.key) != skip.end()) continue;
    specs.push_back(spec);
    fields.push_back(i);
  }
  return new ParamPanel(
      std::move(specs),
      [&schema, &params, fields](std::size_t i) { return schema.fields()[fields[i]].get(params); },
      [&schema, &params, fields](std::size_t i, double v) { schema.fields()[fields[i]].set(params, v); },
      parent);
}

/// A panel editing every parameter of `params` through its schema.
template <class P>
ParamPanel* makeParamPanel(const ParamSchema<P>& schema, P& params, QWidget* parent = nullptr) {
  return makeParamPanel(schema, params, {}, parent);
}

}  // namespace plumb::ui
