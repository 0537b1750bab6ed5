#pragma once
// The parameter panel generated from a core ParamSchema (one source of truth for names,
// units, defaults, ranges, tooltips): spin boxes with units for reals and integers, check
// boxes for booleans, combo boxes for choices. Advanced parameters go in a collapsible group.
// The mouse wheel changes an editor only once it has the focus (clicked or tabbed into):
// over an unfocused editor it scrolls the dock. With defaults given, a value that differs
// from its default has a bold label (its tooltip names the default), and "Reset to defaults"
// puts the whole group back.
#include <QWidget>

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

/// A panel editing `params` (which must outlive the panel) through its schema.
template <class P>
ParamPanel* makeParamPanel(const ParamSchema<P>& schema, P& params, QWidget* parent = nullptr) {
  std::vector<ParamSpec> specs;
  for (const auto& f : schema.fields()) specs.push_back(f.spec);
  std::vector<double> defaults;
  for (const auto& f : schema.fields()) defaults.push_back(f.get(P{}));
  auto* panel = new ParamPanel(
      std::move(specs), [&schema, &params](std::size_t i) { return schema.fields()[i].get(params); },
      [&schema, &params](std::size_t i, double v) { schema.fields()[i].set(params, v); }, parent);
  panel->setDefaults(std::move(defaults));
  return panel;
}

}  // namespace plumb::ui
