// summary.json's Newton iteration counts: `total` counts the committed steps' accepted solves;
// `all_attempts` counts every iteration the run did, also those of attempts retried shorter and
// of the paper contact's re-solves. Before all_attempts existed, a paper-contact run reported a
// third more iterations than the implicit contact while doing several times the work.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/run_test_support.h"

namespace vascsim {
namespace {

using test::default_maze;
using test::summary_of;

long long total(const nlohmann::json& s) { return s["newton_iterations"]["total"].get<long long>(); }
long long all_attempts(const nlohmann::json& s) { return s["newton_iterations"]["all_attempts"].get<long long>(); }

TEST(NewtonWork, FixedStepsWithoutRetriesCountEachIterationOnce) {
  Scene fixed = default_maze(1.0);
  fixed.solver.adaptive = StepControl::kRetry;
  fixed.solver.dt = 1e-3;
  const auto s = summary_of(fixed);
  ASSERT_EQ(s["rejected_steps"], 0) << "the premise: no step is retried";
  EXPECT_GT(total(s), 0);
  EXPECT_EQ(all_attempts(s), total(s));
}

// With one Newton iteration allowed, every failed attempt did exactly one iteration.
TEST(NewtonWork, AttemptsRetriedShorterAreCounted) {
  Scene coarse = default_maze(1.0);
  coarse.solver.adaptive = StepControl::kRetry;
  coarse.solver.dt = 0.05;
  coarse.solver.max_iterations = 1;
  coarse.solver.rel_tol = 1e-6;
  coarse.solver.newton_stop_share = 0.0;
  const auto s = summary_of(coarse);
  const long long rejected = s["rejected_steps"].get<long long>();
  ASSERT_GT(rejected, 0) << "the premise: steps are retried";
  EXPECT_EQ(all_attempts(s), total(s) + rejected);
}

TEST(NewtonWork, StepsRejectedByErrorControlAreCounted) {
  const auto s = summary_of(default_maze(19.0));  // its balanced preset: error control; walls from 17 s
  ASSERT_GT(s["error_control"]["rejected_steps"].get<int>(), 0) << "the premise: error control rejects steps";
  EXPECT_GT(all_attempts(s), total(s));
}

// Each re-solve of a step is a whole Newton solve of at least one iteration.
TEST(NewtonWork, PaperContactReSolvesAreCounted) {
  Scene paper = default_maze(19.0);  // the first wall contacts come at about 17 s
  paper.contact.mode = ContactMode::kPaper;
  const auto s = summary_of(paper);
  const int re_solves_max = s["navigation"]["paper_contact_iterations_max"].get<int>() - 1;
  ASSERT_GT(re_solves_max, 0) << "the premise: some step is solved again";
  EXPECT_GE(all_attempts(s), total(s) + re_solves_max);
}

}  // namespace
}  // namespace vascsim
