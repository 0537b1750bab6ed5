#include "features/bim/bim_features.hpp"

#include <chrono>

#include "common/stopwatch.hpp"

namespace plumb {

const ParamSchema<BimFeatureParams>& BimFeatureParams::schema() {
  using P = BimFeatureParams;
  static const auto s =
      ParamSchema<P>("bim-features")
          .real(&P::angle_tolerance_deg, "coplanar-angle", "Coplanar angle", "deg", 0.001, 10,
                "triangles whose normals differ by at most this are coplanar", true)
          .real(&P::distance_tolerance, "coplanar-distance", "Coplanar distance", "m", 1e-6, 0.1,
                "... and whose plane offsets differ by at most this", true)
          .real(&P::min_polygon_area, "min-area", "Minimum polygon area", "m2", 0, 100,
                "smaller merged polygons are dropped")
          .real(&P::vertical_tolerance_deg, "wall-vertical", "Wall verticality", "deg", 0, 45,
                "max tilt of a façade or wall face", true)
          .real(&P::min_facade_area, "facade-area", "Minimum façade area", "m2", 0, 1e6,
                "vertical polygons at least this large may be façades")
          .real(&P::facade_outside_ratio, "facade-outside", "Façade outside ratio", "", 0, 1,
                "share of rays along a façade's normal that must leave the model", true)
          .real(&P::max_wall_thickness, "max-wall-thickness", "Max wall thickness", "m", 0.01, 5,
                "wall faces farther from a window/door element do not host it")
          .real(&P::min_opening_size, "min-opening-size", "Minimum opening size", "m", 0, 100,
                "polygon holes narrower than this are no opening (models without IfcWindow/IfcDoor)", true)
          .real(&P::max_opening_size, "max-opening-size", "Maximum opening size", "m", 0, 1000,
                "polygon holes wider than this are no opening", true);
  return s;
}

BimFeatureResult extractBimFeatures(const BimModel& model, const BimFeatureParams& params,
                                    Progress* progress) {
  const auto t0 = std::chrono::steady_clock::now();
  BimFeatureResult r;
  r.features.planes = bimPlanes(model, params, progress);
  checkCanceled(progress);
  r.features.facades = bimFacades(model, r.features.planes, params);
  BimOpeningResult op = bimOpenings(model, r.features.planes, params);
  r.features.openings = std::move(op.openings);
  r.opening_elements = op.elements;
  r.openings_without_host = op.without_host;
  r.openings_from_holes = op.from_holes;
  r.seconds = secondsSince(t0);
  r.messages.push_back(std::to_string(r.features.planes.size()) + " polygons, " +
                       std::to_string(r.features.facades.size()) + " facades, " +
                       std::to_string(r.features.openings.size()) + " openings " +
                       (op.from_holes ? std::string("(holes of wall polygons: no IfcWindow/IfcDoor)")
                                      : "(from " + std::to_string(op.elements) +
                                            " IfcWindow/IfcDoor elements, " +
                                            std::to_string(op.without_host) + " without a wall face)"));
  reportProgress(progress, 1.0, "BIM features");
  return r;
}

}  // namespace plumb
