#include "sim/step/sparse_solve.h"

#include <Eigen/SparseCholesky>
#include <algorithm>

namespace vascsim {

bool sparse_ldlt_solve(const BandedMatrix& band, const OffBandEntries& extra, const std::vector<char>& fixed,
                       Eigen::VectorXd& rhs, int* negative_pivots) {
  const int n = band.size();
  OffBandEntries entries;
  entries.reserve(static_cast<std::size_t>(n) * BandedMatrix::kWidth + extra.size());
  for (int i = 0; i < n; ++i)
    for (int j = std::max(0, i - BandedMatrix::kHalfBandwidth); j <= i; ++j)
      if (const double v = band.lower(i, j); v != 0.0 || i == j) entries.emplace_back(i, j, v);
  for (const auto& e : extra)
    if (!fixed[static_cast<std::size_t>(e.row())] && !fixed[static_cast<std::size_t>(e.col())]) entries.push_back(e);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());  // duplicates are summed
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(a);
  if (ldlt.info() != Eigen::Success) return false;
  // P A P^T = L D L^T: by Sylvester's law of inertia D's signs are A's, whatever the ordering.
  if (negative_pivots) *negative_pivots = static_cast<int>((ldlt.vectorD().array() < 0.0).count());
  rhs = ldlt.solve(rhs);
  return ldlt.info() == Eigen::Success && rhs.allFinite();
}

}  // namespace vascsim
