// The Newton system when a module added entries beyond the band (self-contact couples nodes far
// apart along the rod): the band plus those entries as an Eigen sparse matrix, factorised by
// Eigen's SimplicialLDLT with its approximate minimum degree ordering. A band with a few extra
// entries keeps a near-linear fill, so the cost stays close to the banded solver's; it is used
// only for the iterations that have such entries, so a scene without self-contact (or a rod not
// touching itself) pays nothing for it.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/step/banded_matrix.h"
#include "sim/step/force_module.h"

namespace vascsim {

// Solves (band + extra) x = rhs in place (rhs becomes x). Rows and columns of `fixed` degrees of
// freedom are dropped from `extra` (the band has them fixed already). False if the matrix is
// singular or not positive definite enough to factorise. `negative_pivots`, if given, gets the
// number of negative eigenvalues of the matrix (its factorisation's negative pivots), as the
// banded factorisation reports them: a step's saddle check works with self-contact too.
bool sparse_ldlt_solve(const BandedMatrix& band, const OffBandEntries& extra, const std::vector<char>& fixed,
                       Eigen::VectorXd& rhs, int* negative_pivots = nullptr);

}  // namespace vascsim
