#include "sim/io/scene_sections.h"

namespace vascsim::io {

using nlohmann::json;

void read_shape(FieldReader& in, ShapeSpec& out) {
  out.start = in.vec2("start", out.start, kMaxCoordinate);
  out.direction = in.number("direction", out.direction, -1e3, 1e3);
  out.initial_curvature = in.number("initial_curvature", out.initial_curvature, -1e6, 1e6);
  out.rest_curvature = in.number("rest_curvature", out.rest_curvature, -1e6, 1e6);
  in.finish();
}

json write_shape(const ShapeSpec& spec) {
  return {{"start", to_json(spec.start)},
          {"direction", spec.direction},
          {"initial_curvature", spec.initial_curvature},
          {"rest_curvature", spec.rest_curvature}};
}

}  // namespace vascsim::io
