// In-place LDL^T factorisation and solve of a BandedMatrix (half-bandwidth 5), without pivoting.
//
// Why hand-written: the Newton matrix is refactorised every iteration and at N = 1000 the whole
// iteration must cost about 100 ns per node. Eigen has no banded solver; SimplicialLDLT fed from
// triplets costs 700-1300 ns per node per iteration and about 300 even with a fixed pattern
// (issue 3 measured it); LAPACK's dpbtrf needs a positive definite matrix, while the Newton
// matrix can be indefinite (compressed or buckling rods, static solves) and LDL^T without
// pivoting still works there whenever no pivot vanishes. A fixed compile-time band lets the
// compiler unroll the inner loops. Tested against Eigen's dense solve in banded_ldlt_test.cpp.
//
// The number of negative pivots is the matrix's count of negative eigenvalues (Sylvester's law
// of inertia), which the buckling test uses to find the critical load.
#pragma once

#include <Eigen/Core>

#include "sim/step/banded_matrix.h"

namespace vascsim {

struct LdltResult {
  bool ok = false;        // false: a pivot vanished or was not finite
  int failed_row = -1;    // the offending row when !ok
  int negative_pivots = 0;
};

// Overwrites `a` with L (strictly lower band, unit diagonal implied) and 1/D (on the diagonal).
// A pivot counts as vanished when |d_i| <= pivot_tol * |A(i,i)|.
LdltResult banded_ldlt_factor(BandedMatrix& a, double pivot_tol = 1e-13);
// Solves (L D L^T) x = b in place, given a factor from banded_ldlt_factor.
void banded_ldlt_solve(const BandedMatrix& factor, Eigen::VectorXd& b);

}  // namespace vascsim

namespace vascsim {

// The same factorisation by 2x2 blocks (one block per rod node), for matrices whose entries
// couple nodes at most two apart (every rod Newton matrix; ForceModule's contract), i.e. the
// band entries A(2i, 2i-5) are zero, and of even size. Per node: one 2x2 inverse and a few
// independent 2x2 products, a shorter dependency chain than the scalar rows (the scalar
// factorisation is latency-bound). The diagonal blocks store D_i^-1; negative_pivots counts
// negative eigenvalues of the D_i (still the inertia of A); failed_row is 2i+1 for block i.
// A block pivot counts as vanished when its smallest eigenvalue (in magnitude) is
// <= pivot_tol * (|A(2i,2i)| + |A(2i+1,2i+1)| + 2 |A(2i+1,2i)|), to within a factor sqrt 2: the
// scalar test per eigenvalue, whatever the other eigenvalue (a finely meshed bent cantilever's
// tip pivot has both eigenvalues ~ EI/L^3, 1e-9 of the diagonal's EA/dl, and is well-posed).
LdltResult banded_block_ldlt_factor(BandedMatrix& a, double pivot_tol = 1e-13);
void banded_block_ldlt_solve(const BandedMatrix& factor, Eigen::VectorXd& b);

// For leaving an unstable equilibrium (sim/step/stable_branch.h), given a block factor of A:
// - a direction of negative curvature, y^T A y < 0: y = L^-T z, z the eigenvector of the first
//   block pivot's negative eigenvalue (zero elsewhere), so y^T A y = z^T D z (the classic
//   construction of modified-Newton methods, Gill & Murray 1974; More & Sorensen 1979). Zero if
//   no pivot is negative.
Eigen::VectorXd banded_block_ldlt_negative_direction(const BandedMatrix& factor);
// - replaces every block pivot D_i by |D_i| (same eigenvectors, eigenvalue magnitudes), so that
//   the solve applies (L |D| L^T)^-1: positive definite, and its Newton step descends an energy
//   where A is indefinite, moving away from a saddle along its negative modes ("saddle-free
//   Newton", Dauphin et al., NeurIPS 2014, with the modulus taken on the LDL^T pivots).
void banded_block_ldlt_absolute_pivots(BandedMatrix& factor);

}  // namespace vascsim
