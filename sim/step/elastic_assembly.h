// The elastic part of the Newton system: grad E and Hess E of every stretching edge and bending
// hinge of the planar DER, from the element functions of sim/rod/elastic_energy.h (the ones the
// tests check against finite differences), added into the gradient and the band storage. Edge
// lengths and inverse squared lengths are computed once per edge in a first pass (each edge
// serves one stretch and two hinges); the stiffness constants EA/l0 and EI/dl come from the rod
// model. The element Hessians arrive factored and are scattered into the band's lower triangle
// directly: forming the dense 6x6 blocks first cost 7-10 % of a Newton iteration at N = 1000.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/rod/elastic_energy.h"
#include "sim/rod/rod_model.h"
#include "sim/step/banded_matrix.h"

namespace vascsim {

// Per-edge scratch, allocated once.
struct ElasticScratch {
  explicit ElasticScratch(const RodModel& rod) : edges(static_cast<std::size_t>(rod.nodes - 1)) {}
  std::vector<EdgeGeometry> edges;  // (N-1), at the current positions
};

// gradient = grad E(x); hess (if not null) += Hess E(x), lower band.
void assemble_elastic(const RodModel& rod, const Eigen::VectorXd& x, ElasticScratch& scratch,
                      Eigen::VectorXd& gradient, BandedMatrix* hess);

}  // namespace vascsim
