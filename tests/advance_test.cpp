// Proximal advancement (control.advance): the drive holds the rod's first two nodes and feeds
// them along the inlet. References the code did not produce: in a straight vessel, with no tip
// actuation and nothing touching the wall, the whole rod slides as one, so its tip advances by
// the fed length less its elastic shortening, and at constant speed v the drive pushes against
// the axial resistance alone: viscous damping c L v plus the cross-flow drag's tangential part
// 1/2 rho Cd_t (2 r_o) L v^2 (docs/references.md section 4; the nodes' Voronoi lengths sum to
// L). The drive holds the first edge rigid; past it the axial force falls linearly from
// F L' / L to zero at the free tip (L' = L - dl), so the rod is shorter by F L'^2 / (2 L EA).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"

namespace vascsim {
namespace {

const char* kStraightVessel = R"({
  "name": "straight",
  "vessels": {"nodes": {"in": [0.1, 0.5], "out": [1.9, 0.5]}, "segments": [{"from": "in", "to": "out", "radius": 0.05}],
              "start": "in", "goal": "out"},
  "rod": {"nodes": 21},
  "loads": {"drag": {"enabled": true, "area": "nodes", "tangential_coefficient": 1.0},
            "damping": {"enabled": true, "coefficient": 0.1}},
  "control": {"mode": "none", "disturbance": {"amplitude": 0},
              "advance": {"points": [[0, 0], [0.5, 0.0125], [3, 0.1375]]}},
  "run": {"duration": 3, "output_interval": 0.1}
})";

struct Frames : FrameSink {
  std::vector<double> times;
  std::vector<std::vector<double>> values;
  void write(double t, const std::vector<double>& v) override {
    times.push_back(t);
    values.push_back(v);
  }
};

TEST(Advance, InAStraightVesselTheRodSlidesAsOneAndTheDrivePushesAgainstItsAxialDrag) {
  const Scene scene = read_scene_text(kStraightVessel, "advance.json");
  vascsim::Run run(compile(scene));
  Frames frames;
  ASSERT_TRUE(run.run(frames)) << run.statistics().failure;
  const auto& channels = run.channels();
  int feed = -1, fed = -1;
  std::size_t offset = 0, feed_offset = 0, fed_offset = 0;
  for (std::size_t k = 0; k < channels.size(); ++k) {
    if (channels[k].name == "feed/force") feed = static_cast<int>(k), feed_offset = offset;
    if (channels[k].name == "feed/length") fed = static_cast<int>(k), fed_offset = offset;
    offset += channels[k].count;
  }
  ASSERT_GE(feed, 0) << "no feed/force channel";
  ASSERT_GE(fed, 0) << "no feed/length channel";
  const int n = scene.rod.nodes, tip_x = 2 * (n - 1);
  const auto& first = frames.values.front();
  const auto& last = frames.values.back();
  const RodSpec& rod = run.scene().rod;
  const double v = 0.05;  // m/s after 0.5 s; the axial ringing the start excites has decayed by 3 s
  const double l = rod.length;
  const double expected = scene.loads.damping.coefficient * l * v +
                          0.5 * scene.loads.drag.fluid_density * scene.loads.drag.tangential_coefficient *
                              2 * rod.outer_radius * l * v * v;
  EXPECT_NEAR(last[feed_offset], expected, 2e-3 * expected) << "steady push = axial damping and drag";
  const double ea = rod.youngs_modulus * M_PI * (rod.outer_radius * rod.outer_radius - rod.inner_radius * rod.inner_radius);
  EXPECT_NEAR(last[fed_offset], 0.1375, 1e-12);
  const double free = l - l / (n - 1);
  const double shortening = expected * free * free / (2 * l * ea);
  EXPECT_NEAR(last[tip_x] - first[tip_x], 0.1375 - shortening, 5e-3 * shortening)
      << "the tip advances with the root, less the rod's elastic shortening";
  EXPECT_NEAR(last[tip_x + 1], first[tip_x + 1], 1e-9) << "and stays on the axis";
  EXPECT_GT(run.statistics().feed_force_max, 0.99 * expected);
  EXPECT_LT(run.statistics().feed_force_mean, run.statistics().feed_force_max);
}

// A rod only pushed from its root (control.mode "none") logs the drive's push and the fed
// length, and no magnetic force, target or tracking error: nothing steers its tip, so they would
// be zeros and the distance to a target the tip does not follow (the video showed a "tip error"
// of 95 mm for the coil chamber). The same scene with its tip steered logs all of them.
TEST(Advance, ARodOnlyPushedFromItsRootLogsItsFeedAndNoTipControl) {
  const auto channel_names = [](const std::string& text) {
    vascsim::Run run(compile(read_scene_text(text, "advance.json")));
    std::vector<std::string> names;
    for (const auto& c : run.channels()) names.push_back(c.name);
    return names;
  };
  const auto has = [](const std::vector<std::string>& names, const char* name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  const std::vector<std::string> pushed = channel_names(kStraightVessel);
  for (const char* name : {"feed/force", "feed/length", "position"}) EXPECT_TRUE(has(pushed, name)) << name;
  for (const char* name : {"force/actuation", "tip/reference", "tip/error"}) EXPECT_FALSE(has(pushed, name)) << name;

  std::string steered_text = kStraightVessel;
  const std::string none = R"("mode": "none")";
  steered_text.replace(steered_text.find(none), none.size(), R"("mode": "force")");
  const std::vector<std::string> steered = channel_names(steered_text);
  for (const char* name : {"feed/force", "feed/length", "force/actuation", "tip/reference", "tip/error"})
    EXPECT_TRUE(has(steered, name)) << name;
}

// The feed force of a frame inside a step is interpolated between the step's solved ends, as the
// force channels are, not held at the step's end: a held value makes a staircase that jumps
// at every step's end. Seen from the frames alone: the line through a step's frames, carried to
// the step's end, meets the line through the next step's frames there.
TEST(Advance, FeedForceIsContinuousAcrossStepEnds) {
  std::string text = kStraightVessel;
  const std::string run_section = R"("run": {"duration": 3, "output_interval": 0.1})";
  text.replace(text.find(run_section), run_section.size(),
               R"("run": {"duration": 1.5, "output_interval": 0.0005}, "solver": {"preset": "balanced"})");
  const Scene scene = read_scene_text(text, "advance.json");
  vascsim::Run run(compile(scene));
  std::size_t feed_offset = 0;
  for (const auto& c : run.channels()) {
    if (c.name == "feed/force") break;
    feed_offset += c.count;
  }
  // Frames grouped by the step they fall in (the run's step count and end time when written).
  struct Step {
    int index = 0;
    double end = 0.0;                               // s
    std::vector<std::pair<double, double>> frames;  // (t, feed force)
  };
  struct BySteps : FrameSink {
    const vascsim::Run* run = nullptr;
    std::size_t offset = 0;
    std::vector<Step> steps;
    void write(double t, const std::vector<double>& v) override {
      const RunStatistics& s = run->statistics();
      if (steps.empty() || steps.back().index != s.steps) steps.push_back({s.steps, s.simulated_time, {}});
      steps.back().frames.emplace_back(t, v.at(offset));
    }
  } sink;
  sink.run = &run;
  sink.offset = feed_offset;
  ASSERT_TRUE(run.run(sink)) << run.statistics().failure;
  const auto line_at = [](const Step& s, double t) {
    const auto& [t0, f0] = s.frames.front();
    const auto& [t1, f1] = s.frames.back();
    return f0 + (f1 - f0) * (t - t0) / (t1 - t0);
  };
  double peak = 0.0;
  for (const Step& s : sink.steps)
    for (const auto& frame : s.frames) peak = std::max(peak, std::abs(frame.second));
  int compared = 0;
  for (std::size_t k = 1; k + 1 < sink.steps.size(); ++k) {
    const Step& step = sink.steps[k];
    const Step& next = sink.steps[k + 1];
    if (next.index != step.index + 1 || step.frames.size() < 2 || next.frames.size() < 2) continue;
    EXPECT_NEAR(line_at(step, step.end), line_at(next, step.end), 1e-7 * peak) << "at the step ending at t = " << step.end;
    ++compared;
  }
  EXPECT_GT(compared, 100) << "steps several frames long, back to back";
}

TEST(Advance, AFeedThatStopsAsTheReferenceRampEndsRunsOn) {
  // Both jump at t = 1 s (the end of the path's 1 s ramp, the feed's last point): one breakpoint,
  // where two once asked for a step of length 0 and failed the run ("rod blew up", dt = 0).
  std::string text = kStraightVessel;
  const std::string feed = R"("advance": {"points": [[0, 0], [0.5, 0.0125], [3, 0.1375]]})";
  text.replace(text.find(feed), feed.size(), R"("advance": {"points": [[0, 0], [1, 0.01]]})");
  const std::string run_section = R"("run": {"duration": 3, "output_interval": 0.1})";
  text.replace(text.find(run_section), run_section.size(),
               R"("run": {"duration": 1.5, "output_interval": 0.1}, "path": {"ramp_time": 1})");
  const Scene scene = read_scene_text(text, "advance.json");
  vascsim::Run run(compile(scene));
  Frames frames;
  ASSERT_TRUE(run.run(frames)) << run.statistics().failure;
  EXPECT_NEAR(run.statistics().simulated_time, 1.5, 1e-9);
}

// A drive that pulls the rod back draws its root out along the introducer behind the start: the
// introducer reaches back past the furthest retraction (it ended two vessel radii behind the
// root, and a rod pulled further was dragged through its closed end until the run blew up).
// Nothing touches a wall in a straight vessel, so the tip follows the root back.
TEST(Advance, ARodPulledBackFurtherThanItsRootHasRoomSlidesOutAlongTheIntroducer) {
  std::string text = kStraightVessel;
  const std::string feed = R"("advance": {"points": [[0, 0], [0.5, 0.0125], [3, 0.1375]]})";
  text.replace(text.find(feed), feed.size(), R"("advance": {"points": [[0, 0], [1, -0.3]]})");
  const std::string run_section = R"("run": {"duration": 3, "output_interval": 0.1})";
  text.replace(text.find(run_section), run_section.size(), R"("run": {"duration": 1.5, "output_interval": 0.1})");
  const Scene scene = read_scene_text(text, "advance.json");
  vascsim::Run run(compile(scene));
  Frames frames;
  ASSERT_TRUE(run.run(frames)) << run.statistics().failure;
  const int tip_x = 2 * (scene.rod.nodes - 1);
  EXPECT_NEAR(frames.values.back()[tip_x] - frames.values.front()[tip_x], -0.3, 1e-3);
  EXPECT_NEAR(frames.values.back()[tip_x + 1], frames.values.front()[tip_x + 1], 1e-9);
}

// The drive's grip (nodes 0 and 1) moves with the feed and nothing stops it at a wall: a feed
// longer than the way to a dead end takes the rod's root into the cap, where a held node has no
// finite wall force (such a run stopped with a NaN drive force, its summary with none). The
// scene is refused where the grip would arrive. Reference: the vessel is a round-capped tube of
// radius 6 mm ending at x = 0.16 m, so the cap's far point is at x = 0.166 m; the rod (0.3 m,
// 40 nodes, radius 1 mm) lies straight behind the start at x = 0.1, node 1 at 0.1 - 0.3 + 0.3/39;
// it touches the cap when x1 + s + 0.001 = 0.166.
TEST(Advance, AFeedThatWouldTakeTheDrivesGripIntoAWallIsRefusedWhereItWouldArrive) {
  const std::string blocked = R"({
    "name": "blocked",
    "vessels": {"nodes": {"in": [0.1, 0.5], "end": [0.16, 0.5]}, "segments": [{"from": "in", "to": "end", "radius": 0.006}],
                "start": "in", "goal": "end"},
    "rod": {"nodes": 40, "length": 0.3, "outer_radius": 0.001, "inner_radius": 0.0005},
    "loads": {"drag": {"enabled": true, "area": "nodes"}, "damping": {"enabled": true, "coefficient": 0.05}},
    "control": {"mode": "none", "disturbance": {"amplitude": 0}, "advance": {"speed": 0.5, "start": 0, "stop": 1}},
    "run": {"duration": DURATION, "output_interval": 0.03333333333333333}
  })";
  auto with_duration = [&](const char* duration) {
    std::string text = blocked;
    return text.replace(text.find("DURATION"), 8, duration);
  };
  const double node1 = 0.1 - 0.3 + 0.3 / 39, arrival = 0.166 - 0.001 - node1;  // m of feed
  try {
    compile(read_scene_text(with_duration("1"), "blocked.json"));
    ADD_FAILURE() << "a feed of 0.5 m into a 0.06 m dead end was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("blocked.json: /control/advance: "), std::string::npos) << what;
    const std::size_t at = what.find("at a fed length of ");
    ASSERT_NE(at, std::string::npos) << what;
    // Within the lumen's polygon's chord error and the walk's last probe.
    EXPECT_NEAR(std::stod(what.substr(at + 19)), arrival, 1e-3) << what;
  }
  // The feed is checked as far as the run goes: stopped before the grip arrives, it is fine.
  char before[32];
  std::snprintf(before, sizeof before, "%.6f", (arrival - 0.005) / 0.5);
  EXPECT_NO_THROW(compile(read_scene_text(with_duration(before), "blocked.json")));
}

// A feed the rod cannot take (tests/scenes/crammed_feed.json: 5 m/s into a 6 cm dead end, a 1 mm
// rod of 40 nodes; the grip stays clear of the cap) squashes the rod past its linear stretching model, and then a step
// fails. The failure said only that the step did not resolve; it now says how far the rod was
// squashed, as the strain warning does (RunWarnings.LargeAxialStrainIsCountedAndItsSizeReported
// checks that measure against Hooke's law).
TEST(Advance, AFeedTheRodCannotTakeFailsSayingHowFarItSquashedTheRod) {
  vascsim::Run run(compile(read_scene_file(std::string(VASCSIM_SOURCE_DIR) + "/tests/scenes/crammed_feed.json")));
  Frames frames;
  ASSERT_FALSE(run.run(frames)) << "0.35 m of feed went into 0.026 m of lumen";
  const std::string& failure = run.statistics().failure;
  const std::size_t at = failure.find(" of the rod was squashed to ");
  ASSERT_NE(at, std::string::npos) << failure;
  const double percent = std::stod(failure.substr(at + 28));
  EXPECT_GE(percent, 0.0) << failure;
  EXPECT_LT(percent, 100 * (1 - kLargeAxialStrain)) << failure;
  EXPECT_NE(failure.find("a drive or load stronger than the rod"), std::string::npos) << failure;
  EXPECT_GE(frames.times.size(), 5u) << "the frames before the failure are kept";
}

// Any held node a scene drives into a wall stops the run there, naming the node: its wall force
// is outside the residual Newton solves, so the step converged with it non-finite, unseen. The
// tip is pushed sideways at 0.1 m/s from the centre of a vessel of radius 6 mm: its 1 mm radius
// reaches the wall after 0.05 s.
TEST(HeldNode, DrivenIntoAWallStopsTheRunNamingIt) {
  const char* pushed = R"({
    "name": "pushed",
    "vessels": {"nodes": {"in": [0.1, 0.5], "end": [0.3, 0.5]}, "segments": [{"from": "in", "to": "end", "radius": 0.006}],
                "start": "in", "goal": "end"},
    "rod": {"nodes": 20, "length": 0.1, "outer_radius": 0.001, "inner_radius": 0.0005},
    "boundary": {"prescribed": [{"node": -1, "velocity": [0, 0.1]}]},
    "control": {"mode": "none", "disturbance": {"amplitude": 0}},
    "run": {"duration": 0.2, "output_interval": 0.01}
  })";
  vascsim::Run run(compile(read_scene_text(pushed, "pushed.json")));
  Frames frames;
  ASSERT_FALSE(run.run(frames)) << "the tip was driven through the wall";
  const RunStatistics& s = run.statistics();
  EXPECT_NE(s.failure.find("the force holding node 19 is not finite"), std::string::npos) << s.failure;
  EXPECT_NE(s.failure.find("inside a wall"), std::string::npos) << s.failure;
  EXPECT_NEAR(s.simulated_time, 0.05, 0.002) << s.failure;
  // Every frame before the failure is kept.
  ASSERT_FALSE(frames.times.empty());
  EXPECT_GT(frames.times.back(), s.simulated_time - 0.0101);
}

TEST(Advance, ProfilesAndErrors) {
  AdvanceSpec a;
  a.points = {{1.0, 0.0}, {3.0, 0.1}};
  EXPECT_EQ(a.fed_length(0.5), 0.0);
  EXPECT_NEAR(a.fed_length(2.0), 0.05, 1e-15);
  EXPECT_EQ(a.fed_length(9.0), 0.1);
  EXPECT_NEAR(a.speed(2.0), 0.05, 1e-15);
  EXPECT_EQ(a.speed(3.5), 0.0);
  const Scene s = read_scene_text(R"({"control": {"advance": {"speed": 0.01, "start": 1, "stop": 4}}})", "a.json");
  ASSERT_EQ(s.control.advance.points.size(), 2u);
  EXPECT_NEAR(s.control.advance.fed_length(4.0), 0.03, 1e-15);
  EXPECT_EQ(read_scene_text(scene_to_json(s), "a.json").control.advance.points, s.control.advance.points);
  for (const char* bad : {R"({"control": {"advance": {"points": [[0, 0], [0, 1]]}}})",
                          R"({"control": {"advance": {"points": [[0, 0]]}}})",
                          R"({"control": {"advance": {"speed": 1, "start": 2, "stop": 1}}})",
                          R"({"control": {"advance": {"speed": 1, "points": [[0, 0], [1, 1]]}}})",
                          // A first fed length other than 0 was subtracted: this fed 0.05 m, not 0.1.
                          R"({"control": {"advance": {"points": [[0.1, 0.05], [0.3, 0.1]]}}})"}) {
    try {
      read_scene_text(bad, "a.json");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("a.json: /control/advance/"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace vascsim
