#pragma once
// Registration on chosen elements (issue 14): Scan-to-BIM looks for where the building departs
// from its model, and a fit to every element hides those departures. A ModelElementFilter keeps
// the model side to chosen elements (IFC types, or single elements by GlobalId or name);
// filterModelElements applies it before any feature or refinement surface is built, and the
// ModelSelection it returns says what the registration rests on (the report shows it).
// Storeys are not offered: the readers do not carry IfcBuildingStorey containment yet.
#include <cstddef>
#include <string>
#include <vector>

#include "model/bim_model.hpp"

namespace plumb {

struct ModelElementFilter {
  std::vector<std::string> types;     ///< IFC types to keep ("IfcColumn"); any case
  std::vector<std::string> elements;  ///< elements to keep, by IFC GlobalId or by name
  /// Storeys (IfcBuildingStorey names in any case, or GlobalIds) the kept elements must belong to: with types
  /// or elements, only those on these storeys; alone, every element on them.
  std::vector<std::string> storeys;
  bool empty() const { return types.empty() && elements.empty() && storeys.empty(); }
  /// "types IfcWall, IfcSlab; elements 2O2Fr$t4X7Zf8NOew3FLOH; storeys Level 1", or "all elements".
  std::string describe() const;
};

/// One text option of the filter: its CLI flag (--KEY), UI label and help, and the member it
/// fills from a comma-separated list. The CLI flags and the desktop's fields come from this list.
struct ModelElementOption {
  std::string key, label, help;
  std::vector<std::string> ModelElementFilter::*member;
};
const std::vector<ModelElementOption>& modelElementOptions();

/// "a, b,,c" -> {"a", "b", "c"}: blanks around the commas and empty items dropped.
std::vector<std::string> splitNameList(const std::string& text);
/// {"a", "b"} -> "a, b": what splitNameList reads back (the desktop's fields, messages).
std::string joinNameList(const std::vector<std::string>& items);

/// Elements and triangles of one IFC type ("" for untyped elements).
struct ElementTypeUse {
  std::string type;
  std::size_t elements = 0, triangles = 0;
};

/// What a registration's model side rests on: the filter and what it kept, per type.
struct ModelSelection {
  ModelElementFilter filter;
  std::vector<ElementTypeUse> used;  ///< sorted by type
  std::size_t elements_in_model = 0, triangles_in_model = 0;
};

/// "types IfcWall, IfcSlab: 78 of 215 elements, 3120 of 25489 triangles".
std::string selectionSummary(const ModelSelection& s);

/// Elements (that own at least one triangle) and triangles per type, sorted by type.
std::vector<ElementTypeUse> elementTypeUse(const BimModel& model);

struct FilteredModel {
  BimModel model;  ///< only the kept elements' triangles (vertices compacted)
  ModelSelection selection;
};

/// Keeps the elements of `filter` (a type in `types` or an id/name in `elements`). Throws
/// InputError naming the model file when a type is not in the model (listing the types that
/// are), when an element id matches nothing, or when nothing with triangles is left.
FilteredModel filterModelElements(const BimModel& model, const ModelElementFilter& filter);

}  // namespace plumb
