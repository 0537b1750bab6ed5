#include "registration/orientation/orientation_params.hpp"

namespace plumb {

const char* orientationName(SourceOrientation o) {
  switch (o) {
    case SourceOrientation::Auto: return "auto";
    case SourceOrientation::Levelled: return "levelled";
    case SourceOrientation::YUp: return "y-up";
    case SourceOrientation::Any: return "any";
  }
  return "?";
}

const ParamSchema<OrientationParams>& OrientationParams::schema() {
  using P = OrientationParams;
  static const auto s =
      ParamSchema<P>("orientation")
          .choice(&P::source, "source", "Source orientation",
                  {orientationName(SourceOrientation::Auto),
                   orientationName(SourceOrientation::Levelled),
                   orientationName(SourceOrientation::YUp), orientationName(SourceOrientation::Any)},
                  "levelled: Z up, only yaw searched; y-up: +Y up (glTF, handheld, SLAM); any: "
                  "every up direction of the source's planes; auto: levelled when the data says "
                  "so, else any")
          .real(&P::level_tolerance_deg, "level-tolerance", "Level tolerance", "deg", 0.0, 45.0,
                "auto: the source looks levelled when a plane-normal direction lies this close to Z")
          .real(&P::min_axis_share, "min-axis-share", "Min up-axis share", "", 0.0, 1.0,
                "A direction of the source's planes is tried as up when it carries this share of "
                "their weight", true)
          .integer(&P::max_axes, "max-axes", "Max up axes", "", 1, 6,
                   "At most this many directions are tried as up, each with both signs", true)
          .real(&P::min_axis_separation_deg, "min-axis-separation", "Min up-axis separation",
                "deg", 10.0, 90.0, "Directions tried as up are at least this far apart", true);
  return s;
}

}  // namespace plumb
