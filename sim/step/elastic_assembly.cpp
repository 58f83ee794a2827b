#include "sim/step/elastic_assembly.h"

namespace vascsim {

void assemble_elastic(const RodModel& rod, const Eigen::VectorXd& x, ElasticScratch& s, Eigen::VectorXd& gradient,
                      BandedMatrix* hess) {
  constexpr int W = BandedMatrix::kWidth;  // band row r holds A(r, r - m) at [m]
  const int n = rod.nodes;
  for (int e = 0; e + 1 < n; ++e)
    s.edges[static_cast<std::size_t>(e)] = EdgeGeometry::of(x.segment<2>(2 * e + 2) - x.segment<2>(2 * e));
  gradient.setZero();
  double* band = hess ? hess->data() : nullptr;

  // Stretching: Hessian [h -h; -h h], lower triangle only, straight into rows 2e .. 2e+3.
  for (int e = 0; e + 1 < n; ++e) {
    const StretchElement el = stretch_element(s.edges[static_cast<std::size_t>(e)], rod.stretch_stiffness[e], rod.rest_length[e]);
    gradient.segment<4>(2 * e) += el.gradient;
    if (!band) continue;
    const double h00 = el.block(0, 0), h10 = el.block(1, 0), h11 = el.block(1, 1);
    double* r0 = band + static_cast<std::size_t>(2 * e) * W;
    double* r1 = r0 + W;
    double* r2 = r1 + W;
    double* r3 = r2 + W;
    r0[0] += h00;
    r1[1] += h10, r1[0] += h11;
    r2[2] -= h00, r2[1] -= h10, r2[0] += h00;
    r3[3] -= h10, r3[2] -= h11, r3[1] += h10, r3[0] += h11;
  }

  // Bending at hinge i: d2E gphi gphi^T + [a -a 0; -a a+b -b; 0 -b b] over rows 2i-2 .. 2i+3.
  for (int i = 1; i + 1 < n; ++i) {
    const BendElement el = bend_element(s.edges[static_cast<std::size_t>(i - 1)], s.edges[static_cast<std::size_t>(i)],
                                        rod.bend_stiffness[i], rod.rest_kappa[i]);
    gradient.segment<6>(2 * i - 2) += el.gradient;
    if (!band) continue;
    double* row[6];
    row[0] = band + static_cast<std::size_t>(2 * i - 2) * W;
    for (int r = 1; r < 6; ++r) row[r] = row[r - 1] + W;
    for (int r = 0; r < 6; ++r) {
      const double scaled = el.d2E * el.gphi[r];
      for (int col = 0; col <= r; ++col) row[r][r - col] += scaled * el.gphi[col];
    }
    const double a00 = el.a(0, 0), a01 = el.a(0, 1), b00 = el.b(0, 0), b01 = el.b(0, 1);  // a11 = -a00, b11 = -b00
    row[0][0] += a00;
    row[1][1] += a01, row[1][0] -= a00;
    row[2][2] -= a00, row[2][1] -= a01, row[2][0] += a00 + b00;
    row[3][3] -= a01, row[3][2] += a00, row[3][1] += a01 + b01, row[3][0] -= a00 + b00;
    row[4][2] -= b00, row[4][1] -= b01, row[4][0] += b00;
    row[5][3] -= b01, row[5][2] += b00, row[5][1] += b01, row[5][0] -= b00;
  }
}

}  // namespace vascsim
