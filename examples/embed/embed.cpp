// Embedding vascsim: read a scene, compile it once, run it in this process into a frame log,
// read the log back, and render the last frame as a still. A planner would run the compiled
// model many times (one Run each, in as many threads as it likes) and read the statistics.
//
//   embed SCENE OUT_DIR [DURATION_S]
// writes OUT_DIR/frames.vlog and OUT_DIR/summary.json (what `vascsim run SCENE --out OUT_DIR`
// writes), prints the tip's final position read back from the log, and renders
// OUT_DIR/still.png (what `vascsim render OUT_DIR --still T --png OUT_DIR/still.png` writes).
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/io/output_file.h"
#include "sim/io/run_log.h"
#include "sim/io/run_summary.h"
#include "sim/io/scene_reader.h"
#include "sim/log/frame_log.h"
#include "sim/run/compile.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#ifdef EMBED_WITH_RENDER
#include "render/render_run.h"
#endif

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: embed SCENE OUT_DIR [DURATION_S]\n");
    return 2;
  }
  const std::filesystem::path out = argv[2];
  try {
    vascsim::Scene scene = vascsim::read_scene_file(argv[1]);
    if (argc == 4) {
      scene.run.duration = std::stod(argv[3]);
      scene.run.duration_from_path = false;
    }
    const auto model = vascsim::compile(scene);  // const and shareable between runs
    vascsim::Run run(model);

    std::filesystem::create_directories(out);
    const std::string log_path = (out / "frames.vlog").string();
    vascsim::FrameLogWriter writer(log_path, vascsim::run_log_header(run));
    vascsim::FrameLogSink sink(writer);
    const bool ok = run.run(sink);
    writer.close();
    vascsim::write_file_atomically((out / "summary.json").string(), vascsim::run_summary_json(run.scene(), run));
    const vascsim::RunStatistics& stats = run.statistics();
    std::printf("%s: %d steps, %zu frames, %.3f s simulated\n", ok ? "done" : "FAILED", stats.steps, stats.frames,
                stats.simulated_time);
    if (!ok) std::fprintf(stderr, "embed: simulation failed: %s\n", stats.failure.c_str());

    // Read the log back: the tip is the last node of the position channel.
    const vascsim::FrameLogReader reader(log_path);
    const auto& header = reader.header();
    const int position = header.find_channel(vascsim::channel::kPosition);
    if (position < 0 || reader.frame_count() == 0) throw vascsim::InputError(log_path + ": no positions");
    const std::size_t last = reader.frame_count() - 1;
    double tip[2];
    reader.read_values(last, header.channel_offset(position) + 2 * (header.node_count - 1), 2, tip);
    std::printf("tip at t = %.4f s: (%.6f, %.6f) m\n", reader.time_of(last), tip[0], tip[1]);

#ifdef EMBED_WITH_RENDER
    vascsim::render::RenderOptions options;
    options.still = reader.time_of(last);
    options.png_path = (out / "still.png").string();
    options.force = true;
    vascsim::render::render_run(out.string(), options);
    std::printf("still: %s\n", options.png_path.c_str());
#endif
    return ok ? 0 : 1;
  } catch (const vascsim::InputError& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 2;
  }
}
