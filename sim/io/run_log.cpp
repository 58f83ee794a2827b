#include "sim/io/run_log.h"

#include "sim/io/provenance.h"
#include "sim/io/scene_reader.h"

namespace vascsim {

LogMetadata run_log_metadata(const Run& run) {
  const Scene& scene = run.scene();
  LogMetadata m;
  m.title = scene.name;
  m.scene_json = scene_to_json(scene);
  const Provenance provenance = provenance_of(m.scene_json);
  m.vascsim_version = provenance.version;
  m.commit = provenance.commit;
  m.scene_hash = provenance.scene_hash;
  m.rod_outer_radius = scene.rod.outer_radius;
  m.rod_length = scene.rod.length;
  m.output_interval = scene.run.output_interval;
  m.boundary = scene.boundary;
  for (int& i : m.boundary.pinned) i = resolve_node(i, scene.rod.nodes);
  for (SupportSpec& s : m.boundary.supports) s.node = resolve_node(s.node, scene.rod.nodes);
  for (PrescribedMotionSpec& p : m.boundary.prescribed) p.node = resolve_node(p.node, scene.rod.nodes);
  if (const Navigation* nav = run.navigation()) {
    m.bounds = nav->environment.bounds;
    m.walls = nav->environment.walls;
    m.lumen_width = nav->environment.lumen_width;
    m.lumen = nav->environment.lumen;
    m.path = nav->trajectory->sample(1e-4);
    m.start = nav->environment.start;
    m.goal = nav->environment.goal;
  } else {
    const auto& x = run.state().x;
    Box2 b{Vec2(x[0], x[1]), Vec2(x[0], x[1])};
    for (Eigen::Index i = 0; i < x.size(); i += 2) {
      b.min = b.min.cwiseMin(Vec2(x[i], x[i + 1]));
      b.max = b.max.cwiseMax(Vec2(x[i], x[i + 1]));
    }
    const Vec2 pad = Vec2::Constant(0.1 * scene.rod.length);
    m.bounds = {b.min - pad, b.max + pad};
  }
  return m;
}

FrameLogHeader run_log_header(const Run& run) {
  FrameLogHeader header;
  header.node_count = static_cast<std::uint32_t>(run.scene().rod.nodes);
  header.channels = run.channels();
  header.metadata = write_log_metadata(run_log_metadata(run));
  return header;
}

}  // namespace vascsim
