// ForceModule: one kind of force on the rod (gravity, point loads, damping, drag, and later
// contact, friction, actuation), behind one small interface so that a new kind is a new file in
// sim/rod/, sim/contact/ or sim/control/ and the stepper never changes.
//
// At each Newton iterate the stepper calls add() with the iterate's positions and the velocities
// the time scheme implies, v = (x - x_hat) * dv_dx. The module adds its force F (N) into `force`
// and, when `stiffness` is not null, its contribution to the Newton matrix:
//     K += -(dF/dx + dv_dx * dF/dv)
// which must be symmetric. Entries within BandedMatrix's band (degrees of freedom at most 5
// apart) go into `stiffness`; a module coupling nodes far apart along the rod (self-contact)
// adds the lower-triangle entries beyond it to ForceContext::off_band, and Newton then solves
// that iteration with a sparse factorisation (sim/step/sparse_solve.h). A force whose
// exact Jacobian is not symmetric (friction) adds a symmetric approximation: Newton then
// converges linearly but still to the right answer, since convergence is judged on the residual.
// Modules are immutable (const), so one Model can be shared by many runs and threads: per-step
// inputs come in ForceContext (time, controls, the state at the start of the step for lagged
// quantities), and what a module keeps between calls (friction's lagged pairs) lives in a
// ModuleCache it declares (make_cache) and the run's Workspace stores, as Drake's systems declare
// cache entries that their Context holds; what several users of one object keep (the wall
// geometry's neighbour lists) lives in the Workspace's SharedCaches, keyed by that object.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sim/step/banded_matrix.h"
#include "sim/step/controls.h"
#include "sim/step/state.h"

namespace vascsim {

// One module's mutable data for one run: a derived type of the module's own, made by
// ForceModule::make_cache and handed back in ForceContext::cache.
struct ModuleCache {
  virtual ~ModuleCache() = default;
};

// Per-run data of an immutable object that several modules share, one entry per object, made on
// first use (the wall geometry's neighbour lists serve contact, friction and the run's gap
// statistics: one set of lists, rebuilt once, instead of one per user). The Workspace keeps it.
// An owner's entry always has one type: the code that owns the key decides it.
class SharedCaches {
 public:
  template <class C>
  C& of(const void* owner) {
    for (auto& [key, cache] : entries_)
      if (key == owner) return static_cast<C&>(*cache);
    entries_.emplace_back(owner, std::make_unique<C>());
    return static_cast<C&>(*entries_.back().second);
  }

 private:
  std::vector<std::pair<const void*, std::unique_ptr<ModuleCache>>> entries_;
};

// Newton matrix entries outside the band: (row, column, value) with row > column + 5.
using OffBandEntries = std::vector<Eigen::Triplet<double>>;

struct ForceContext {
  double t = 0.0;                         // s, time the forces act at (end of the step)
  const Eigen::VectorXd* x = nullptr;     // (2N), m, current Newton iterate
  const Eigen::VectorXd* v = nullptr;     // (2N), m/s, velocities implied by x
  double dv_dx = 0.0;                     // 1/s, dv/dx of the scheme (1/(beta h)); 0 in statics
  double load_scale = 1.0;                // 1 in dynamics; static load stepping ramps it 0 -> 1 and
                                          // applied loads (gravity, point loads) multiply by it
  const Controls* controls = nullptr;
  const State* start = nullptr;           // state at the start of the step
  OffBandEntries* off_band = nullptr;     // where entries beyond the band go (null: none wanted)
  ModuleCache* cache = nullptr;           // the called module's cache in this run, or null (then a
                                          // module that keeps one works from scratch: slower, same answer)
  SharedCaches* shared = nullptr;         // the run's caches of shared objects, or null (the same)

  // The context of a committed state, for the forces acting on it (a frame, a predictor): its
  // own time, positions and velocities, and itself as the start of the step.
  static ForceContext at(const State& state, const Controls& controls) {
    ForceContext ctx;
    ctx.t = state.t;
    ctx.x = &state.x;
    ctx.v = &state.v;
    ctx.controls = &controls;
    ctx.start = &state;
    return ctx;
  }
};

class ForceModule {
 public:
  virtual ~ForceModule() = default;
  // Frame log channel of this force (sim/log/channel_names.h), e.g.
  // "force/drag". Modules sharing a channel are summed in the log.
  virtual std::string channel() const = 0;
  virtual void add(const ForceContext& ctx, Eigen::Ref<Eigen::VectorXd> force, BandedMatrix* stiffness) const = 0;
  // The largest fraction of the Newton update x -> x + dx that keeps this force defined (a
  // barrier must never see a closed gap). The stepper caps every line search by the minimum over
  // all modules. x is the current iterate.
  virtual double max_step_fraction(const ForceContext& ctx, const Eigen::VectorXd& dx) const {
    (void)ctx;
    (void)dx;
    return 1.0;
  }
  // Whether the force is defined at the context's positions (a barrier: every gap open). The run
  // asks it of a frame interpolated inside a step (sim/step/dense_output.h), which, unlike a
  // Newton iterate, no step cap has kept out of the walls.
  virtual bool defined_at(const ForceContext& ctx) const {
    (void)ctx;
    return true;
  }
  // The cache this module keeps between calls within one run, or null if it keeps none.
  virtual std::unique_ptr<ModuleCache> make_cache() const { return nullptr; }
};

// The cache of type C in `ctx`, or `fallback` when the caller passed none.
template <class C>
C& cache_or(const ForceContext& ctx, C& fallback) {
  return ctx.cache ? static_cast<C&>(*ctx.cache) : fallback;
}

}  // namespace vascsim
