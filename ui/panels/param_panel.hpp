#pragma once
// The parameter panel generated from a core ParamSchema (one source of truth for names,
// units, defaults, ranges, tooltips): spin boxes with units for reals and integers, check
// boxes for booleans, combo boxes for choices. Advanced parameters go in a collapsible group.
// The mouse wheel changes an editor only once it has the focus (clicked or tabbed into):
// over an unfocused editor it scrolls the dock. With defaults given, a value that differs
// from its default has a bold label (its tooltip names the default), and "Reset to defaults"
// puts the whole group back.
#include <QWidget>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "common/params.hpp"

class QLabel;
class QPushButton;

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
  /// The default of each spec (same order): marks modified values, enables the reset.
  void setDefaults(std::vector<double> defaults);
  /// Sets every value back to its default (emits changed() once).
  void resetToDefaults();
  /// The value of `key` differs from its default.
  bool isModified(const std::string& key) const;
  /// The editor of a key (QDoubleSpinBox, QSpinBox, QCheckBox or QComboBox), for tests.
  QWidget* editor(const std::string& key) const;

 signals:
  void changed();

 private:
  QWidget* makeEditor(std::size_t i);
  bool modified(std::size_t i) const;
  void markModified();
  std::vector<ParamSpec> specs_;
  std::vector<QWidget*> editors_;
  std::vector<QLabel*> labels_;
  std::vector<double> defaults_;  ///< empty: none given
  QPushButton* reset_;
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
  std::vector<double> defaults;  // bold labels and "Reset to defaults" compare with these
  for (const std::size_t f : fields) defaults.push_back(schema.fields()[f].get(P{}));
  auto* panel = new ParamPanel(
      std::move(specs),
      [&schema, &params, fields](std::size_t i) { return schema.fields()[fields[i]].get(params); },
      [&schema, &params, fields](std::size_t i, double v) { schema.fields()[fields[i]].set(params, v); },
      parent);
  panel->setDefaults(std::move(defaults));
  return panel;
}

/// A panel editing every parameter of `params` through its schema.
template <class P>
ParamPanel* makeParamPanel(const ParamSchema<P>& schema, P& params, QWidget* parent = nullptr) {
  return makeParamPanel(schema, params, {}, parent);
}

}  // namespace plumb::ui
