#include "sim/io/run_warnings.h"

#include <cstdio>

#include "sim/run/run.h"

namespace vascsim {

std::string RunWarning::line() const {
  char text[96];
  std::snprintf(text, sizeof text, " %d times, first at t = %g s", count, first_time);
  return what + text;
}

std::vector<RunWarning> listed_warnings(const nlohmann::json& summary) {
  char large_strain[300];
  const auto strain = summary.is_object() ? summary.find("axial_strain_max") : summary.end();
  std::snprintf(large_strain, sizeof large_strain,
                "an edge of the rod was stretched or squashed by more than %g %% of its rest length (up to %.3g %%: a "
                "drive or load stronger than the rod, past its linear stretching model) in a frame",
                100 * kLargeAxialStrain,
                strain != summary.end() && strain->is_number() ? 100 * strain->get<double>() : 100 * kLargeAxialStrain);
  const std::pair<const char*, std::string> kinds[] = {
      {"step_retried", "a step was retried with a smaller dt"},
      {"unresolved_step",
       "a step was kept that is not the motion (solver.adaptive \"off\": it ended at a saddle of its incremental "
       "potential, or an edge turned by more than 0.5 rad in it; a shorter dt or adaptive stepping resolves it)"},
      {"paper_contact_iteration_cap", "paper contact hit contact.paper_iterations unsettled"},
      {"unstable_equilibrium", "the static equilibrium is unstable (the Newton matrix has negative pivots)"},
      {"left_unstable_equilibrium",
       "the load path reached an unstable equilibrium; the solve left it for a stable one (solver.stable_branch)"},
      {"load_path_jumped",
       "the load path jumped off the stable branch where it turns more sharply than the smallest increment follows; the "
       "equilibrium may be on another branch than slower loading reaches (raise solver.load_steps or "
       "solver.max_halvings)"},
      {"stability_undecided",
       "the static equilibrium's stability is not decided: the Newton matrix's eigenvalue nearest zero is within its "
       "round-off at this many nodes (docs/solver.md, \"Limit: static solves of very fine meshes\")"},
      {"large_axial_strain", large_strain},
  };
  std::vector<RunWarning> listed;
  const auto warnings = summary.is_object() ? summary.find("warnings") : summary.end();
  if (warnings == summary.end() || !warnings->is_object()) return listed;
  for (const auto& [key, what] : kinds) {
    const auto w = warnings->find(key);
    if (w == warnings->end() || !w->is_object()) continue;
    const auto count = w->find("count"), first = w->find("first_time");
    if (count == w->end() || !count->is_number_integer() || count->get<long long>() <= 0 ||
        count->get<long long>() > 2147483647 || first == w->end() || !first->is_number())
      continue;
    listed.push_back({key, what, count->get<int>(), first->get<double>()});
  }
  return listed;
}

}  // namespace vascsim
