// Whether a static equilibrium's stability can be decided in double precision at all. The count
// of negative pivots (Sylvester's law of inertia) is only as good as the sign of the stiffness's
// eigenvalue nearest zero, and that eigenvalue (~EI/L^3 over N for a unit vector) shrinks while
// the round-off of the assembled matrix (~eps EI/dl^3) grows: for the paper's rod they meet at
// several thousand nodes, and at 10001 a column loaded past buckling counts as stable. Inverse
// iteration with the factor finds that eigenvalue; its residual |K y - lambda y| tells how far the
// matrix as assembled is from having it exactly, so a Rayleigh quotient no larger than that has
// no sign.
#pragma once

#include <vector>

#include "sim/step/banded_matrix.h"

namespace vascsim {

struct StabilityMargin {
  double eigenvalue = 0.0;  // N/m, Rayleigh quotient y^T K y of the unit vector inverse iteration ends at
  double round_off = 0.0;   // N/m, |K y - eigenvalue y|
  // The sign of the eigenvalue nearest zero stands clear of the matrix's round-off.
  bool decided() const { return std::abs(eigenvalue) > 2.0 * round_off; }
};

// `stiffness` as assembled, `factor` its banded_block_ldlt_factor; degrees of freedom with
// fixed[d] != 0 are held (their rows and columns are the identity's) and left out.
StabilityMargin stability_margin(const BandedMatrix& stiffness, const BandedMatrix& factor,
                                 const std::vector<char>& fixed);

}  // namespace vascsim
