#include "sim/step/elastic_assembly.h"

#include <cmath>

namespace vascsim {

ElasticScratch::ElasticScratch(const RodModel& rod) {
  const int edges = rod.nodes - 1;
  stretch_stiffness = rod.ea * rod.rest_length.cwiseInverse();
  bend_stiffness.setZero(rod.nodes);
  for (int i = 1; i + 1 < rod.nodes; ++i) bend_stiffness[i] = rod.ei / rod.voronoi[i];
  for (Eigen::VectorXd* v : {&edge_x, &edge_y, &length, &inverse_length2}) v->setZero(edges);
}

void assemble_elastic(const RodModel& rod, const Eigen::VectorXd& x, ElasticScratch& s, Eigen::VectorXd& gradient,
                      BandedMatrix* hess) {
  constexpr int W = BandedMatrix::kWidth;  // band row r holds A(r, r - m) at [m]
  const int n = rod.nodes;
  for (int e = 0; e + 1 < n; ++e) {
    const double ex = x[2 * e + 2] - x[2 * e], ey = x[2 * e + 3] - x[2 * e + 1];
    const double r = ex * ex + ey * ey;
    s.edge_x[e] = ex;
    s.edge_y[e] = ey;
    s.length[e] = std::sqrt(r);
    s.inverse_length2[e] = 1.0 / r;
  }
  gradient.setZero();
  double* band = hess ? hess->data() : nullptr;

  // Stretching, E = EA/(2 l0) (l - l0)^2: gradient k (l - l0) u on x1 (minus on x0), Hessian
  // [h -h; -h h] with h = k u u^T + t (I - u u^T), t = k (1 - l0/l), k = EA/l0.
  for (int e = 0; e + 1 < n; ++e) {
    const double l = s.length[e], inverse_l = l * s.inverse_length2[e];
    const double ux = s.edge_x[e] * inverse_l, uy = s.edge_y[e] * inverse_l;
    const double k = s.stretch_stiffness[e], l0 = rod.rest_length[e];
    const double f = k * (l - l0);
    double* g = gradient.data() + 2 * e;
    g[0] -= f * ux;
    g[1] -= f * uy;
    g[2] += f * ux;
    g[3] += f * uy;
    if (!band) continue;
    const double t = k * (1.0 - l0 * inverse_l), along = k - t;
    const double h00 = along * ux * ux + t, h10 = along * ux * uy, h11 = along * uy * uy + t;
    double* r0 = band + static_cast<std::size_t>(2 * e) * W;
    double* r1 = r0 + W;
    double* r2 = r1 + W;
    double* r3 = r2 + W;
    r0[0] += h00;
    r1[1] += h10, r1[0] += h11;
    r2[2] -= h00, r2[1] -= h10, r2[0] += h00;
    r3[3] -= h10, r3[2] -= h11, r3[1] += h10, r3[0] += h11;
  }

  // Bending at hinge i between e1 = edge i-1 and e2 = edge i (elastic_energy.h, bend_energy):
  // gradient dE grad phi, Hessian d2E grad phi grad phi^T + dE Hess phi, where Hess phi has the
  // 2x2 blocks a = d2phi/de1^2 and b = d2phi/de2^2 arranged as [a -a 0; -a a+b -b; 0 -b b].
  for (int i = 1; i + 1 < n; ++i) {
    const double x1 = s.edge_x[i - 1], y1 = s.edge_y[i - 1], x2 = s.edge_x[i], y2 = s.edge_y[i];
    const double ir1 = s.inverse_length2[i - 1], ir2 = s.inverse_length2[i];
    const double cross = x1 * y2 - y1 * x2, dot = x1 * x2 + y1 * y2;
    const double kappa = 2.0 * cross / (s.length[i - 1] * s.length[i] + dot);
    const double k1 = 1.0 + 0.25 * kappa * kappa;
    const double c = s.bend_stiffness[i], dk = kappa - rod.rest_kappa[i];
    const double dE = c * dk * k1;
    const double d2E = c * (k1 * k1 + dk * k1 * 0.5 * kappa);
    const double g1x = y1 * ir1, g1y = -x1 * ir1;   // dphi/de1
    const double g2x = -y2 * ir2, g2y = x2 * ir2;   // dphi/de2
    const double gphi[6] = {-g1x, -g1y, g1x - g2x, g1y - g2y, g2x, g2y};
    double* g = gradient.data() + 2 * i - 2;
    for (int r = 0; r < 6; ++r) g[r] += dE * gphi[r];
    if (!band) continue;
    double* row[6];
    row[0] = band + static_cast<std::size_t>(2 * i - 2) * W;
    for (int r = 1; r < 6; ++r) row[r] = row[r - 1] + W;
    for (int r = 0; r < 6; ++r) {
      const double scaled = d2E * gphi[r];
      for (int col = 0; col <= r; ++col) row[r][r - col] += scaled * gphi[col];
    }
    const double q1 = dE * ir1 * ir1, q2 = dE * ir2 * ir2;
    const double a00 = -2.0 * x1 * y1 * q1, a01 = (x1 * x1 - y1 * y1) * q1;  // dE a; a11 = -a00
    const double b00 = 2.0 * x2 * y2 * q2, b01 = (y2 * y2 - x2 * x2) * q2;   // dE b; b11 = -b00
    row[0][0] += a00;
    row[1][1] += a01, row[1][0] -= a00;
    row[2][2] -= a00, row[2][1] -= a01, row[2][0] += a00 + b00;
    row[3][3] -= a01, row[3][2] += a00, row[3][1] += a01 + b01, row[3][0] -= a00 + b00;
    row[4][2] -= b00, row[4][1] -= b01, row[4][0] += b00;
    row[5][3] -= b01, row[5][2] += b00, row[5][1] += b01, row[5][0] -= b00;
  }
}

}  // namespace vascsim
