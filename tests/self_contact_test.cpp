// Rod self-contact (contact.self): a rod fed into a closed chamber (control.advance) coils round
// it, and on every logged frame no edge may cross another, checked by an independent
// segment-intersection test (orientation signs, not the module's distance code). Without
// self-contact the same run crosses itself (on 26 of its 111 frames when written), so the test sees
// what the module prevents.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sim/contact/contact_params.h"
#include "sim/contact/self_contact.h"
#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#include "sim/step/banded_matrix.h"

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

// The module keeps each search's pairs with a margin (a Verlet list in the run's cache) and
// filters them while no node has moved half the margin. The contract of a cache is "slower
// without, same answer": on a coiled rod moved by random steps from 10 um to 1 mm (within the
// margin, beyond it, and a step cap wider than the list), forces, band, off-band entries and step
// fractions with the cache are those of a fresh search (no cache), bit for bit.
TEST(SelfContact, TheKeptPairListGivesWhatAFreshSearchGives) {
  Scene scene = read_scene_text(chamber_scene(true), "chamber.json");
  scene.rod.nodes = 400;  // edges of 0.75 mm: their chords follow the spiral's turns
  const Model model = *compile(scene);
  const SelfContactModule module(model.rod, resolve_contact_params(scene.contact, model.rod));
  const int n = model.nodes();
  // An Archimedean spiral with turns 2.15 mm apart: the 2 mm thick rod lies within its barrier's
  // reach (0.25 mm) of the next turn along most of its length.
  Eigen::VectorXd x(2 * n);
  double theta = 10.0 * M_PI;  // from a radius of 10.75 mm
  for (int i = 0; i < n; ++i) {
    const double r = 2.15e-3 * theta / (2 * M_PI);
    x.segment<2>(2 * i) = Vec2(r * std::cos(theta), r * std::sin(theta));
    theta += model.rod.rest_length[std::min(i, n - 2)] / r;
  }
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(2 * n);
  const std::unique_ptr<ModuleCache> cache = module.make_cache();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> unit(0.0, 1.0);
  // Rigid moves (which keep every gap) of 10 um to 1 mm, against a list margin whose half is
  // 0.28 mm, and noise of 1 um on each node.
  const double sizes[] = {1e-5, 1e-4, 3e-4, 1e-3};  // m
  const Eigen::VectorXd spiral = x;
  Vec2 shift = Vec2::Zero();
  double turn = 0.0;
  int pairs_seen = 0;
  for (int k = 0; k < 64; ++k) {
    shift += sizes[(k / 2) % 4] * Vec2(unit(rng), unit(rng));
    turn += 1e-3 * unit(rng);
    const Eigen::Rotation2D<double> rotation(turn);
    for (int i = 0; i < n; ++i) x.segment<2>(2 * i) = rotation * Vec2(spiral.segment<2>(2 * i)) + shift + 1e-6 * Vec2(unit(rng), unit(rng));
    ForceContext fresh;
    fresh.x = &x;
    fresh.v = &v;
    fresh.dv_dx = 100.0;
    ForceContext kept = fresh;
    kept.cache = cache.get();
    OffBandEntries off_fresh, off_kept;
    fresh.off_band = &off_fresh;
    kept.off_band = &off_kept;
    Eigen::VectorXd f_fresh = Eigen::VectorXd::Zero(2 * n), f_kept = f_fresh;
    BandedMatrix k_fresh(2 * n), k_kept(2 * n);
    module.add(fresh, f_fresh, &k_fresh);
    module.add(kept, f_kept, &k_kept);
    ASSERT_EQ(f_kept, f_fresh) << "step " << k;
    for (int i = 0; i < 2 * n; ++i)
      for (int j = std::max(0, i - BandedMatrix::kHalfBandwidth); j <= i; ++j) ASSERT_EQ(k_kept.lower(i, j), k_fresh.lower(i, j));
    ASSERT_EQ(off_kept.size(), off_fresh.size());
    for (std::size_t e = 0; e < off_kept.size(); ++e) {
      ASSERT_EQ(off_kept[e].row(), off_fresh[e].row());
      ASSERT_EQ(off_kept[e].col(), off_fresh[e].col());
      ASSERT_EQ(off_kept[e].value(), off_fresh[e].value());
    }
    pairs_seen += f_fresh.cwiseAbs().maxCoeff() > 0.0;
    Eigen::VectorXd dx(2 * n);
    for (int d = 0; d < 2 * n; ++d) dx[d] = sizes[k % 4] * unit(rng);
    ASSERT_EQ(module.max_step_fraction(kept, dx), module.max_step_fraction(fresh, dx)) << "step " << k;
  }
  EXPECT_GT(pairs_seen, 32) << "the spiral should touch itself on most steps";
}

// A rod that starts coiled over itself has no barrier to start from: refused at compile time,
// naming the setting, where it failed at t = 0 as "the rod blew up".
TEST(SelfContact, ARodStartingOverItselfIsRefusedNamingTheShape) {
  const auto scene_with_curvature = [](double curvature) {
    return read_scene_text(R"({"maze": null, "rod": {"length": 0.1, "nodes": 60}, "boundary": {"clamp": "first_edge"},
        "contact": {"self": true}, "shape": {"initial_curvature": )" + std::to_string(curvature) + R"(}, "run": {"duration": 0.01}})",
                           "coiled.json");
  };
  try {
    compile(scene_with_curvature(4 * M_PI / 0.1));  // two turns of one circle
    ADD_FAILURE() << "a rod coiled twice over itself was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("coiled.json: /contact/self: the rod starts overlapping itself (node ", 0), 0u) << what;
    EXPECT_NE(what.find("/shape/initial_curvature"), std::string::npos) << what;
  }
  // Half a circle does not touch itself: it compiles and runs.
  vascsim::Run run(compile(scene_with_curvature(M_PI / 0.1)));
  CrossingCounter counter;
  counter.nodes = 60;
  EXPECT_TRUE(run.run(counter)) << run.statistics().failure;
}

TEST(SelfContact, RefusedInStaticMode) {
  EXPECT_THROW(read_scene_text(R"({"maze": null, "contact": {"self": true}, "solver": {"mode": "static"}})", "s.json"),
               InputError);
}

}  // namespace
}  // namespace vascsim
