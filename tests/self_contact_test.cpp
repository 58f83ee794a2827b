// Rod self-contact (contact.self): a rod fed into a closed chamber (control.advance) coils round
// it, and on every logged frame no edge may cross another, checked by an independent
// segment-intersection test (orientation signs, not the module's distance code). Without
// self-contact the same run crosses itself (on 26 of its 111 frames when written), so the test sees
// what the module prevents.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"

namespace vascsim {
namespace {

// A vessel that widens from 6 mm to 35 mm radius over 6 cm and ends closed: fed 0.275 m, a thin
// rod runs round the wide end and its tip comes back into the neck, past the part still entering.
std::string chamber_scene(bool self) {
  return std::string(R"({
  "name": "chamber",
  "vessels": {"nodes": {"in": [0.1, 0.5], "end": [0.16, 0.5]}, "segments": [{"from": "in", "to": "end", "radius": [0.006, 0.035]}],
              "start": "in", "goal": "end"},
  "rod": {"nodes": 40, "length": 0.3, "outer_radius": 0.001, "inner_radius": 0.0005},
  "loads": {"drag": {"enabled": true, "area": "nodes"}, "damping": {"enabled": true, "coefficient": 0.05}},
  "control": {"mode": "none", "disturbance": {"amplitude": 0}, "advance": {"speed": 0.05, "start": 0, "stop": 5.5}},
  "contact": {"self": )") + (self ? "true" : "false") + R"(},
  "run": {"duration": 5.5, "output_interval": 0.05}
})";
}

double cross(const Vec2& a, const Vec2& b, const Vec2& c) { return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x(); }

// Proper intersection of segments pq and rs (touching end to end does not count).
bool segments_cross(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const double d1 = cross(p, q, r), d2 = cross(p, q, s), d3 = cross(r, s, p), d4 = cross(r, s, q);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

struct CrossingCounter : FrameSink {
  int nodes = 0;
  int frames_with_crossings = 0, frames = 0;
  void write(double, const std::vector<double>& v) override {
    ++frames;
    auto at = [&](int i) { return Vec2(v[2 * i], v[2 * i + 1]); };
    for (int a = 0; a + 1 < nodes; ++a)
      for (int b = a + 2; b + 1 < nodes; ++b)
        if (segments_cross(at(a), at(a + 1), at(b), at(b + 1))) {
          ++frames_with_crossings;
          return;
        }
  }
};

CrossingCounter run_chamber(bool self, RunStatistics* stats = nullptr) {
  Run run(compile(read_scene_text(chamber_scene(self), "chamber.json")));
  CrossingCounter counter;
  counter.nodes = run.scene().rod.nodes;
  const bool ok = run.run(counter);
  EXPECT_TRUE(ok) << run.statistics().failure;
  if (stats) *stats = run.statistics();
  return counter;
}

TEST(SelfContact, ARodFedIntoAClosedChamberCoilsWithoutCrossingItself) {
  RunStatistics stats;
  const CrossingCounter with = run_chamber(true, &stats);
  EXPECT_EQ(with.frames, 111);
  EXPECT_EQ(with.frames_with_crossings, 0) << "an edge crossed another";
  EXPECT_GT(stats.feed_force_max, 0.0);
  const CrossingCounter without = run_chamber(false);
  EXPECT_GT(without.frames_with_crossings, 0) << "without self-contact the rod should pass through itself here";
}

// Edges much shorter than the rod's thickness (400 nodes over 0.5 m: 1.25 mm edges, 4 mm thick):
// points a few edges apart are closer than the thickness and must not be pairs, or the straight
// rod would start inside its own barrier (it did: "the rod blew up" at t = 0).
TEST(SelfContact, AFineMeshDoesNotStartInsideItsOwnBarrier) {
  const Scene scene = read_scene_text(R"({"maze": null, "rod": {"nodes": 400}, "boundary": {"clamp": "first_edge"},
      "contact": {"self": true}, "loads": {"point": [{"node": -1, "force": [0, -1e-4]}]}, "run": {"duration": 0.02}})",
                                      "fine.json");
  vascsim::Run run(compile(scene));
  CrossingCounter counter;
  counter.nodes = 400;
  EXPECT_TRUE(run.run(counter)) << run.statistics().failure;
  EXPECT_EQ(counter.frames_with_crossings, 0);
}

TEST(SelfContact, RefusedInStaticMode) {
  EXPECT_THROW(read_scene_text(R"({"maze": null, "contact": {"self": true}, "solver": {"mode": "static"}})", "s.json"),
               InputError);
}

}  // namespace
}  // namespace vascsim
