#pragma once
// What readMesh's IFC pre-pass (io/mesh/ifc_georef.hpp, ifc_map_conversion.hpp) promises for
// any text, checked by fuzz_model on every input and by test_fuzz_regressions on the inputs
// stored from it: a planned shift is finite, its rewrite leaves nothing more to take out and
// refers to no entity that is not defined (unless the file already did), and a map conversion
// is finite and moves a vertex to a finite place, or the file is refused with an InputError.
// Header-only: the fuzz tree (clang) includes it too.
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_set>

#include "common/error.hpp"
#include "io/mesh/ifc_georef.hpp"
#include "io/mesh/ifc_map_conversion.hpp"
#include "io/mesh/step_entities.hpp"

namespace plumb::test {

/// The ids `text` refers to without defining them.
inline std::unordered_set<std::uint64_t> undefinedReferences(std::string_view text) {
  std::unordered_set<std::uint64_t> defined, undefined;
  step::forEachEntity(text, [&](const step::Entity& e) { defined.insert(e.id); });
  step::forEachEntity(text, [&](const step::Entity& e) {
    step::forEachReference(e.args, [&](std::uint64_t id) {
      if (!defined.count(id)) undefined.insert(id);
    });
  });
  return undefined;
}

/// "" when the plan keeps its promises on `text`, else what it broke.
inline std::string planProblem(std::string_view text) {
  const auto shift = ifc_georef::plan(text);
  if (!shift) return "";
  if (!shift->metres.allFinite()) return "the planned shift is not finite";
  if (ifc_georef::plan(shift->text)) return "the rewritten text still has a shift to take out";
  const auto before = undefinedReferences(text);
  for (const auto id : undefinedReferences(shift->text))
    if (!before.count(id)) return "the rewritten text refers to #" + std::to_string(id) + ", which it does not define";
  return "";
}

/// "" when the map conversion of `text` is finite or refused, else what is wrong with it.
inline std::string mapConversionProblem(std::string_view text) {
  try {
    const auto m = ifc_georef::readMapConversion(text);
    if (!m) return "";
    if (!m->origin.allFinite() || !std::isfinite(m->rotation_rad) || !std::isfinite(m->scale) || !(m->scale > 0))
      return "the map conversion is not finite";
    TriangleMesh mesh;
    mesh.vertices = {{10.0, -20.0, 3.0}};
    ifc_georef::applyMapConversion(*m, mesh);
    return mesh.vertices[0].allFinite() ? "" : "the map conversion moves a vertex to infinity";
  } catch (const InputError&) {
    return "";
  }
}

}  // namespace plumb::test
