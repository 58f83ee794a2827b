// compile(): one step from a scene to a const Model that leaves its input alone, and that many
// runs can share at once: four threads running one compiled Model write exactly the frames of a
// run on its own (the contact neighbour lists and friction's lagged pairs live in each run's
// Workspace, not in the shared modules).
#include <gtest/gtest.h>

#include <cstring>
#include <thread>
#include <type_traits>

#include "sim/io/scene_reader.h"
#include "sim/run/compile.h"
#include "sim/run/navigation.h"
#include "sim/run/run.h"
#include "sim/scene/input_error.h"
#include "tests/run_test_support.h"

namespace vascsim {
namespace {

static_assert(std::is_copy_constructible_v<Model>, "a Model can be copied (its modules are shared)");

// Every frame's time and values, as bytes.
class ByteSink : public FrameSink {
 public:
  void write(double time, const std::vector<double>& values) override {
    append(&time, 1);
    append(values.data(), values.size());
  }
  std::string bytes;

 private:
  void append(const double* v, std::size_t n) { bytes.append(reinterpret_cast<const char*>(v), n * sizeof(double)); }
};

using test::default_maze;

TEST(Compile, LeavesItsSceneAloneAndResolvesACopy) {
  // A maze scene without a duration: it runs until its reference reaches the goal, plus settling.
  const Scene input = read_scene_text(R"({"maze": {"seed": 4}})", "implicit.json");
  const std::string before = scene_to_json(input);
  const auto model = compile(input);
  EXPECT_EQ(scene_to_json(input), before) << "compile() changed the scene it was given";
  ASSERT_NE(model->navigation, nullptr);
  EXPECT_NEAR(model->scene.run.duration, model->navigation->trajectory->duration() + RunSpec::kSettleTime, 1e-12);
  EXPECT_NE(scene_to_json(model->scene), before) << "the compiled scene resolves the duration and the rod's place";
  // Contact, friction and the gap statistics share one geometry.
  const auto with_friction = compile(default_maze(1.0));
  ASSERT_GT(with_friction->scene.contact.friction, 0.0);
  EXPECT_EQ(with_friction->navigation->contact_geometry.use_count(), 3) << "navigation, contact and friction";
}

TEST(Compile, FourThreadsShareOneModelAndWriteTheSequentialBytes) {
  const std::shared_ptr<const Model> model = compile(default_maze(19.0));
  ByteSink alone;
  vascsim::Run sequential(model);
  ASSERT_TRUE(sequential.run(alone));
  ASSERT_GT(sequential.statistics().contact_force_max, 0.0) << "the run must touch the walls (contact caches)";
  std::vector<ByteSink> sinks(4);
  std::vector<std::thread> threads;
  std::vector<char> ok(4, 0);
  for (int k = 0; k < 4; ++k)
    threads.emplace_back([&, k] {
      vascsim::Run run(model);
      ok[static_cast<std::size_t>(k)] = run.run(sinks[static_cast<std::size_t>(k)]);
    });
  for (auto& t : threads) t.join();
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(ok[static_cast<std::size_t>(k)]) << "thread " << k;
    EXPECT_EQ(sinks[static_cast<std::size_t>(k)].bytes.size(), alone.bytes.size()) << "thread " << k;
    EXPECT_TRUE(sinks[static_cast<std::size_t>(k)].bytes == alone.bytes) << "thread " << k << " wrote other frames";
  }
}

}  // namespace
}  // namespace vascsim

namespace vascsim {
namespace {

// A legal maze the rod cannot start in is refused at compile with what does not fit; it once
// ran and stopped at t = 0 with "the rod blew up" (issue 14 item 8).
TEST(Compile, RefusesARodThatDoesNotFitItsMaze) {
  const std::pair<const char*, const char*> cases[] = {
      // 2 m cells with 0.1 m lumens: 1.9 m thick walls, the rod would start inside the outer one.
      {R"({"maze": {"rows": 5, "cols": 5, "width": 10, "height": 10, "lumen_width": 0.1}})", "/maze: the rod starts"},
      // A 3 mm lumen for a 4 mm rod.
      {R"({"maze": {"lumen_width": 0.003}})", "/maze/lumen_width: the lumen (3 mm) must be wider than the rod (4 mm"},
  };
  for (const auto& [text, expected] : cases) {
    try {
      compile(read_scene_text(text, "misfit.json"));
      ADD_FAILURE() << "compiled " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("misfit.json: ") + expected), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(compile(read_scene_text(R"({"maze": {"lumen_width": 0.01}})", "fits.json")));
}

}  // namespace
}  // namespace vascsim
