// The view as a value: layer names parse and print back, a layer changes the picture exactly when
// the log has something for it to draw, a still at time T is byte-identical to the video frame at T (the
// trail rebuilt from the first frame), and `vascsim render` rejects bad view options with exit 2
// naming the option.
#include <gtest/gtest.h>

#include "render/canvas.h"
#include "render/frame_painter.h"
#include "render/frame_source.h"
#include "render/view.h"
#include "render/view_frame.h"
#include "render_test_util.h"
#include "sim/io/log_metadata.h"
#include "sim/log/frame_log.h"
#include "sim/scene/input_error.h"

namespace vascsim::render {
namespace {

using testing::ScratchDir;

TEST(RenderView, LayerListsParseAndPrintBack) {
  EXPECT_EQ(format_layer_list(LayerSet::defaults()),
            "lumen,walls,path,start_goal,trail,rod,supports,magnetic,contact,hud,legend");
  EXPECT_EQ(parse_layer_list(format_layer_list(LayerSet::defaults())), LayerSet::defaults());
  EXPECT_EQ(parse_layer_list(""), LayerSet::none());
  const LayerSet some = parse_layer_list("rod,walls,nodes");
  EXPECT_TRUE(some.has(Layer::kRod) && some.has(Layer::kWalls) && some.has(Layer::kNodes));
  EXPECT_FALSE(some.has(Layer::kTrail));
  EXPECT_EQ(format_layer_list(hide_layers(LayerSet::defaults(), "trail,hud")),
            "lumen,walls,path,start_goal,rod,supports,magnetic,contact,legend");
  try {
    parse_layer_list("rod,bogus");
    FAIL() << "an unknown layer was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bogus"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("friction"), std::string::npos) << "the message lists the known layers";
  }
  for (const char* list : {"rod,rod", "rod,", ",rod", "rod,,walls"}) EXPECT_THROW(parse_layer_list(list), InputError) << list;
  EXPECT_THROW(parse_centre("1,"), InputError);
  EXPECT_THROW(parse_centre("1,2,"), InputError);
  EXPECT_THROW(parse_centre("1,2,3"), InputError);
  EXPECT_THROW(parse_centre("nan,1"), InputError);
  EXPECT_EQ(parse_centre("0.25,-1e-3"), Vec2(0.25, -1e-3));
  // Beyond the scenes' 1000 m the view shows nothing (at 1e308 its transform overflowed to NaN).
  EXPECT_EQ(parse_centre("-1000,1000"), Vec2(-1000, 1000));
  EXPECT_THROW(parse_centre("1e308,1e308"), InputError);
  EXPECT_THROW(parse_centre("0,-1000.5"), InputError);
}

// Each layer, turned off alone, changes the picture exactly when layers_with_content says the log
// has something for it (what the replay page greys out): `metadata` is the run's, `spec` gives its
// channels.
void expect_layers_change_the_picture_as_their_content_says(const ScratchDir& dir, const std::string& name,
                                                            SyntheticLogSpec spec, const LogMetadata& metadata) {
  spec.frames = 30;
  spec.duration = 3;
  spec.speed = 0.005;
  const std::string log = dir / (name + ".vlog");
  write_synthetic_log(log, spec, metadata);
  FrameSource source(log);
  const LayerSet content = layers_with_content(source.metadata(), source.header());
  ViewFrameInputs in;
  in.source = &source;
  in.peaks = measure_force_peaks(source);
  View all;
  all.width = 320;
  all.height = 240;
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i) all.layers.set(static_cast<Layer>(i), true);
  Canvas canvas(all.width, all.height);
  std::vector<std::uint8_t> reference, without;
  render_view_frame(canvas, in, all, 2.0, reference);
  for (int i = 0; i < static_cast<int>(Layer::kCount); ++i) {
    const Layer layer = static_cast<Layer>(i);
    View v = all;
    v.layers.set(layer, false);
    render_view_frame(canvas, in, v, 2.0, without);
    EXPECT_EQ(without != reference, content.has(layer))
        << name << ": turning off '" << layer_name(layer) << "' " << (without != reference ? "changed" : "left")
        << " the picture, and the log " << (content.has(layer) ? "has" : "has no") << " content for it";
  }
}

TEST(RenderView, ALayerChangesThePictureExactlyWhenTheLogHasContentForIt) {
  ScratchDir dir("view_layers");
  SyntheticLogSpec every;  // a maze run that logs every force and the tip's reference, its rod held
  every.friction_and_drag = true;
  LogMetadata held = synthetic_metadata(every);
  held.boundary.clamp = ClampKind::kFirstEdge;
  held.boundary.pinned = {12};
  held.boundary.supports = {{25, SupportAxis::kX}};
  expect_layers_change_the_picture_as_their_content_says(dir, "every", every, held);
  EXPECT_EQ(layers_with_content(held, FrameSource(dir / "every.vlog").header()),
            parse_layer_list("lumen,walls,path,start_goal,trail,rod,nodes,supports,magnetic,contact,friction,drag,hud,legend"));

  // No vessel, path, start or goal, and no force channels; bounds that frame the rod (as a free
  // rod logs them: a box round the lumen-toned rod read as a channel it was in).
  SyntheticLogSpec free_rod;
  free_rod.forces = false;
  free_rod.reference = false;
  LogMetadata bare = synthetic_metadata(free_rod);
  bare.walls.clear();
  bare.lumen.clear();
  bare.path.clear();
  bare.start = bare.goal = Vec2::Zero();
  expect_layers_change_the_picture_as_their_content_says(dir, "free", free_rod, bare);
  EXPECT_EQ(layers_with_content(bare, FrameSource(dir / "free.vlog").header()),
            parse_layer_list("trail,rod,nodes,hud,legend"));

  SyntheticLogSpec walled;  // walls, a start and goal but no path; magnetic and contact forces only
  walled.reference = false;
  LogMetadata no_path = synthetic_metadata(walled);
  no_path.path.clear();
  expect_layers_change_the_picture_as_their_content_says(dir, "walled", walled, no_path);
  EXPECT_EQ(layers_with_content(no_path, FrameSource(dir / "walled.vlog").header()),
            parse_layer_list("lumen,walls,start_goal,trail,rod,nodes,magnetic,contact,hud,legend"));
}

// `--layers` naming a layer that draws nothing for the run (a force its log does not record) says
// so and still makes the picture; the default layers, which the user did not name, say nothing.
TEST(RenderView, ANamedLayerThatDrawsNothingForTheRunIsWarnedAbout) {
  ScratchDir dir("view_named_layers");
  SyntheticLogSpec pushed;  // no magnetic or contact force, no friction or drag
  pushed.forces = false;
  const std::string run = testing::make_run(dir, pushed);
  const auto named = testing::run_vascsim(
      "render " + run + " --still 0.5 --width 160 --height 120 --layers rod,walls,magnetic,drag --png " + (dir / "n.png"), dir);
  ASSERT_EQ(named.exit_code, 0) << named.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "n.png"));
  const std::string log = run + "/frames.vlog";
  EXPECT_NE(named.err.find("warning: layer 'magnetic' draws nothing: " + log + " does not record a magnetic force"),
            std::string::npos) << named.err;
  EXPECT_NE(named.err.find("warning: layer 'drag' draws nothing: " + log + " does not record drag forces"),
            std::string::npos) << named.err;
  EXPECT_EQ(named.err.find("layer 'rod'"), std::string::npos) << named.err;
  EXPECT_EQ(named.err.find("layer 'walls'"), std::string::npos) << named.err;
  const auto hidden = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --layers rod,magnetic "
                                           "--hide magnetic --png " + (dir / "h.png"), dir);
  EXPECT_EQ(hidden.err.find("layer 'magnetic'"), std::string::npos) << "a layer hidden again is not drawn: " << hidden.err;
  const auto defaults =
      testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + (dir / "d.png"), dir);
  ASSERT_EQ(defaults.exit_code, 0) << defaults.err;
  EXPECT_EQ(defaults.err.find("draws nothing"), std::string::npos) << defaults.err;
}

TEST(RenderView, StillAtTIsTheVideoFrameAtT) {
  ScratchDir dir("view_still");
  SyntheticLogSpec spec;
  spec.frames = 21;
  spec.duration = 2;
  spec.speed = 0.006;
  const std::string run = testing::make_run(dir, spec);
  // fps 10: frame k shows t = 0.5 + 0.1 k; frame 7 is t = 1.2, between logged frames.
  auto r = testing::run_vascsim("render " + run + " --png-dir " + (dir / "seq") +
                                    " --from 0.5 --to 1.5 --fps 10 --width 320 --height 240 --hide hud",
                                dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = testing::run_vascsim("render " + run + " --still 1.2 --png " + (dir / "still.png") +
                               " --width 320 --height 240 --hide hud",
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::read_bytes(dir / "still.png") == testing::read_bytes(dir / "seq/frame_000007.png"))
      << "the still at 1.2 s differs from the clip's frame at 1.2 s";
  // A still never overwrites without --force.
  r = testing::run_vascsim("render " + run + " --still 1.0 --png " + (dir / "still.png"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;

  // The same with a second run overlaid (compare mode's pixels, the replay's overlay export): a
  // shorter run B, held at its own end (1 s) while this run goes on.
  SyntheticLogSpec short_spec = spec;
  short_spec.frames = 11;
  short_spec.duration = 1;
  short_spec.speed = 0.012;
  const std::string run_b = testing::make_run(dir, short_spec, "b");
  r = testing::run_vascsim("render " + run + " --png-dir " + (dir / "seq_b") +
                               " --from 0.5 --to 1.5 --fps 10 --width 320 --height 240 --hide hud --overlay " + run_b,
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = testing::run_vascsim("render " + run + " --still 1.2 --png " + (dir / "still_b.png") +
                               " --width 320 --height 240 --hide hud --overlay " + run_b,
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::read_bytes(dir / "still_b.png") == testing::read_bytes(dir / "seq_b/frame_000007.png"));
  EXPECT_FALSE(testing::read_bytes(dir / "still_b.png") == testing::read_bytes(dir / "still.png")) << "no overlay drawn";
}

// Run B drawn over a run is an input like it: its files are never replaced by an output (a still
// with --force wrote a PNG over its frames.vlog), its log's times are checked (a frame out of
// order drew B's rod at another time), and an empty --overlay is refused (it drew no overlay).
TEST(RenderView, AnOverlaidRunIsAnInput) {
  ScratchDir dir("view_overlay_input");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::string run_b = testing::make_run(dir, SyntheticLogSpec{}, "b");
  const std::string log_b = run_b + "/frames.vlog";
  const std::string log_bytes = testing::read_bytes(log_b);
  auto r = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + log_b + " --force --overlay " + run_b, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("refusing to write over it"), std::string::npos) << r.err;
  EXPECT_TRUE(testing::read_bytes(log_b) == log_bytes) << "run B's log was replaced";

  const std::string unordered = dir / "unordered.vlog";
  {
    FrameLogHeader h;
    h.node_count = 3;
    h.channels = {{"position", "m", ChannelLayout::kNodeVectors, 6}};
    h.metadata = write_log_metadata(synthetic_metadata(SyntheticLogSpec{}));
    FrameLogWriter w(unordered, h);
    for (const double t : {0.0, 0.6, 0.2, 0.9}) w.append(t, {0.0, 0.0, 0.01, 0.0, 0.02, t});
  }
  r = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + (dir / "b.png") +
                               " --overlay " + unordered, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("unordered.vlog: frame 2 has time 0.2"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.png"));

  const std::string stopped = testing::make_run(dir, SyntheticLogSpec{}, "stopped");
  std::filesystem::remove(stopped + "/summary.json");
  r = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + (dir / "s.png") + " --overlay " + stopped, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + stopped + " has no summary.json"), std::string::npos) << r.err;

  EXPECT_EQ(r.err.find("another environment"), std::string::npos) << r.err;

  // A run of another maze over this one's map: drawn, with a warning (most likely the wrong run).
  SyntheticLogSpec other;
  other.grid = 4;
  const std::string elsewhere = testing::make_run(dir, other, "elsewhere");
  r = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + (dir / "e.png") + " --overlay " + elsewhere, dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: " + elsewhere + " ran in another environment"), std::string::npos) << r.err;

  r = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --png " + (dir / "c.png") + " --overlay ''", dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.err.find("option '--overlay' needs a value RUN_B, got an empty one"), std::string::npos) << r.err;
}

TEST(RenderView, BadViewOptionsExit2NamingTheOption) {
  ScratchDir dir("view_cli");
  const std::string run = testing::make_run(dir, SyntheticLogSpec{});
  const std::pair<std::string, std::string> cases[] = {
      {"--still 0.5 --png X --layers rod,bogus", "--layers: unknown layer 'bogus'"},
      {"--still 0.5 --png X --layers rod,rod", "--layers: layer 'rod' is listed twice"},
      {"--still 0.5 --png X --layers rod,", "--layers: an empty layer name in 'rod,'"},
      {"--still 0.5 --png X --hide nope", "--hide: unknown layer 'nope'"},
      {"--still 0.5 --png X --camera center", "--center"},
      {"--still 0.5 --png X --center 1", "--center: expected X,Y in metres"},
      {"--still 0.5 --png X --center 1,2,", "--center: expected X,Y in metres"},
      {"--still 0.5 --png X --camera follow --center 0.1,0.1", "--center goes with --camera center"},
      {"--still 0.5 --png X --camera orbit", "--camera: expected fit, follow or center, got 'orbit'"},
      {"--still 0.5", "--png"},
      {"--png X", "--still"},
      {"--plots P --overlay " + run, "--overlay"},
      {"--still 0.5 --png X --mp4 v.mp4", "--mp4"},
      {"--still 99 --png X", "--still 99: no frame at that time (the log spans 0 .. 1 s)"},
      {"--mp4 v.mp4 --from 5 --to 6", "--from/--to: no frame in the time range"},
      {"--still 0.5 --png ''", "option '--png' needs a value FILE, got an empty one"},
      {"--still 0.5 --png X --from 0.2 --to 0.4", "--from chooses a video's frames; --still T draws the one picture at T"},
      {"--still 0.5 --png X --speed 5", "--speed chooses a video's frames"},
  };
  for (const auto& [options, named] : cases) {
    const auto r = testing::run_vascsim("render " + run + " " + options, dir);
    EXPECT_EQ(r.exit_code, 2) << options;
    EXPECT_NE(r.err.find(named), std::string::npos) << options << ": " << r.err;
  }
  // An empty list is a list: no layers, a blank page.
  const auto blank = testing::run_vascsim("render " + run + " --still 0.5 --width 160 --height 120 --layers '' --png " + (dir / "blank.png"), dir);
  EXPECT_EQ(blank.exit_code, 0) << blank.err;
}

}  // namespace
}  // namespace vascsim::render
