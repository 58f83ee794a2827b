// One Newton iteration (assembly of residual and banded Jacobian, LDL^T factorisation, solve) for
// the paper's rod at N = 1000, and one backward Euler step at N = 50 and 200. Issue 3's targets:
// <= 120 ns per node per iteration at N = 1000; >= 60000 steps/s at N = 50 (see docs/solver.md).
#include <benchmark/benchmark.h>

#include "sim/run/compile.h"
#include "sim/step/banded_ldlt.h"
#include "sim/step/model.h"
#include "sim/step/newton.h"
#include "sim/step/stepper.h"

namespace vascsim {
namespace {

Scene free_rod(int nodes) {
  Scene scene;
  scene.has_environment = false;
  scene.rod.nodes = nodes;
  scene.shape.initial_curvature = 2.0;  // a bent rod, so that every element does real work
  scene.solver.scheme = Scheme::kBackwardEuler;
  scene.solver.dt = 1e-3;
  PointLoadSpec tip;
  tip.force = Vec2(0.0, 1e-3);
  scene.loads.point_loads.push_back(tip);
  return scene;
}

void BM_NewtonIteration(benchmark::State& st) {
  const Model model = *compile(free_rod(static_cast<int>(st.range(0))));
  State state = initial_state(model);
  Workspace ws(model);
  ws.x_hat = state.x;
  ws.v_hat = state.v;
  ws.x = state.x;
  NewtonProblem p;
  p.c = 1.0 / model.solver.dt;
  for (auto _ : st) {
    assemble(model, p, ws.x, ws, true);
    ws.dx = -ws.residual;
    if (st.range(1)) {
      banded_block_ldlt_factor(ws.jacobian);
      banded_block_ldlt_solve(ws.jacobian, ws.dx);
    } else {
      banded_ldlt_factor(ws.jacobian);
      banded_ldlt_solve(ws.jacobian, ws.dx);
    }
    benchmark::DoNotOptimize(ws.dx.data());
  }
  // Seconds per node per iteration (printed with an SI prefix, e.g. 95n = 95 ns).
  st.counters["per_node"] = benchmark::Counter(static_cast<double>(st.range(0)),
                                               benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_NewtonIteration)->Args({1000, 0})->Args({1000, 1});  // scalar, block LDL^T

void BM_BackwardEulerStep(benchmark::State& st) {
  const Model model = *compile(free_rod(static_cast<int>(st.range(0))));
  State state = initial_state(model);
  Workspace ws(model);
  Controls controls;
  for (auto _ : st) {
    const StepReport r = step(model, state, ws, controls, model.solver.dt);
    benchmark::DoNotOptimize(r.ok);
  }
  st.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(st.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_BackwardEulerStep)->Arg(50)->Arg(200);

}  // namespace
}  // namespace vascsim
