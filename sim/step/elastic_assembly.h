// The elastic part of the Newton system: grad E and Hess E of every stretching edge and bending
// hinge of the planar DER, written straight into the gradient and the band storage. The
// element formulas are those of sim/rod/elastic_energy.h (tested there against finite
// differences; tests/rod_energy_test.cpp checks this assembly against their sum). It is written
// out by hand because it is the hot loop of every Newton iteration: edge lengths and inverse
// squared lengths are computed once per edge in a first, independent pass (each edge serves one
// stretch and two hinges), so the element loops hold no square root and one division per hinge,
// and only the lower triangle of each element block is formed.
#pragma once

#include <Eigen/Core>

#include "sim/rod/rod_model.h"
#include "sim/step/banded_matrix.h"

namespace vascsim {

// Per-model constants and per-edge scratch, allocated once.
struct ElasticScratch {
  explicit ElasticScratch(const RodModel& rod);
  Eigen::VectorXd stretch_stiffness;  // (N-1), N/m, EA / l0 per edge
  Eigen::VectorXd bend_stiffness;     // (N), N m, EI / dl_voronoi per node (0 at the ends)
  Eigen::VectorXd edge_x, edge_y;     // (N-1), m, edge vectors at the current positions
  Eigen::VectorXd length;             // (N-1), m
  Eigen::VectorXd inverse_length2;    // (N-1), 1/m^2
};

// gradient = grad E(x); hess (if not null) += Hess E(x), lower band.
void assemble_elastic(const RodModel& rod, const Eigen::VectorXd& x, ElasticScratch& scratch,
                      Eigen::VectorXd& gradient, BandedMatrix* hess);

}  // namespace vascsim
