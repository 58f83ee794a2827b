// Leaving an unstable static equilibrium for a stable one (issue 16 item 5c). Load stepping
// solves r(x) = 0 with Newton, which converges to any equilibrium, stable or not: a perfect
// column loaded past its buckling load stays straight, and an imperfect one can come back bent a
// hair against its imperfection (the middle, unstable root of an imperfect pitchfork). Both are
// saddles of the potential energy; the negative pivots of the Newton matrix count their unstable
// modes. From such a saddle, descend_to_stable nudges the rod along a direction of negative
// curvature and descends the energy with Newton steps whose negative pivots are flipped
// (L |D| L^T, sim/step/banded_ldlt.h) until the matrix is positive definite, then converges
// with plain Newton steps: it follows the energy down the branch the negative mode opens.
//
// Which way: of the two signs of the negative mode it takes the one pointing away from the side
// the unstable equilibrium leans to, measured from `reference` (the unloaded shape): the unstable
// root of an imperfect symmetric bifurcation lies opposite the imperfection (Koiter's theory;
// Thompson & Hunt, A General Theory of Elastic Stability, 1973), so this goes the imperfection's
// way. A perfect system gives no preference; the sign of the LDL^T direction then decides,
// deterministically.
//
// The line search needs an energy, which the force modules do not provide; it uses the change
// the residual (the energy's gradient) implies along the step, by the trapezoidal rule,
// dE ~ alpha/2 (r(x) + r(x + alpha dx)) . dx, exact to third order. So the loads must be
// conservative, as static loads are (gravity, dead forces and moments, contact barriers).
#pragma once

#include <Eigen/Core>
#include <string>

#include "sim/step/model.h"
#include "sim/step/newton.h"

namespace vascsim {

struct BranchOutcome {
  bool ok = false;       // ws.x is an equilibrium whose Newton matrix has no negative pivot
  int iterations = 0;    // linear solves
  std::string failure;   // when !ok; ws.x then holds the unstable equilibrium again
};

// ws.x holds an equilibrium of `problem` whose Newton matrix has negative pivots (ws.fixed and
// ws.target set, as newton_solve needs them); `reference` (2N, m) the unloaded shape.
BranchOutcome descend_to_stable(const Model& model, const NewtonProblem& problem, Workspace& ws,
                                const Eigen::VectorXd& reference);

}  // namespace vascsim
