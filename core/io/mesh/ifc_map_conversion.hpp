#pragma once
// IfcMapConversion (IFC4): where a model's engineering coordinates sit in a map (projected)
// coordinate system. assimp 5.2 ignores it, so Plumb applies it after the import, in double:
//   E = Eastings  + k (x cos(a) - y sin(a))
//   N = Northings + k (x sin(a) + y cos(a))
//   H = OrthogonalHeight + z
// with a = atan2(XAxisOrdinate, XAxisAbscissa) and k = Scale / u: IFC's Scale converts project
// length units to map units, and the imported model is already in metres (project unit u,
// e.g. 0.001 for millimetres). The conversion is read from the first IfcMapConversion of the
// file whose source is a geometric representation context (the model context in practice);
// the target IfcProjectedCRS's Name (e.g. "EPSG:2154") says which grid the result is in.
#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>

#include "model/bim_model.hpp"

namespace plumb::ifc_georef {

struct MapConversion {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< Eastings, Northings, OrthogonalHeight
  double rotation_rad = 0.0;                          ///< a, from the x axis abscissa/ordinate
  double scale = 1.0;                                 ///< k, map metres per imported metre
  std::string crs;                                    ///< IfcProjectedCRS Name ("" when absent)
  std::uint64_t line = 0;                             ///< line of the IfcMapConversion
};

/// The file's map conversion, or nullopt when it has none (u above is the project's length
/// unit, ifc_georef::lengthUnit, looked up only when there is a conversion). Throws InputError
/// naming the entity's line when it is unusable (zero x axis, k outside 1e-6..1e6).
std::optional<MapConversion> readMapConversion(std::string_view ifc_text);

/// Moves every vertex of `mesh` from engineering to map coordinates (formulas above).
void applyMapConversion(const MapConversion& conversion, TriangleMesh& mesh);

}  // namespace plumb::ifc_georef
