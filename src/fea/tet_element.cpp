#include "kinestat/fea/tet_element.hpp"

#include <array>
#include <cmath>

namespace kinestat::fea {

namespace {

// Derivatives of the n shape functions with respect to (xi, eta, zeta): an n x 3 matrix.
// Volume coordinates L0 = 1 - xi - eta - zeta, L1 = xi, L2 = eta, L3 = zeta.
Eigen::MatrixXd natural_gradients(int n, const Vec3& p) {
  const std::array<double, 4> L = {1.0 - p.x() - p.y() - p.z(), p.x(), p.y(), p.z()};
  // dL_i / d(xi, eta, zeta)
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Eigen::MatrixXd g(n, 3);
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) g(i, k) = n == 4 ? dL[i][k] : (4.0 * L[i] - 1.0) * dL[i][k];  // N = L(2L-1)
  if (n == 10) {
    static const int kEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};  // = kTet10Edges
    for (int e = 0; e < 6; ++e) {
      const int a = kEdges[e][0], b = kEdges[e][1];
      for (int k = 0; k < 3; ++k) g(4 + e, k) = 4.0 * (dL[a][k] * L[b] + L[a] * dL[b][k]);  // N = 4 La Lb
    }
  }
  return g;
}

}  // namespace

Mat6 elasticity_matrix(const Material& m) {
  const double mu = m.G, nu = m.nu();
  const double lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
  Mat6 D = Mat6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    D(i, i) = lambda + 2.0 * mu;
    D(3 + i, 3 + i) = mu;
  }
  return D;
}

MatX tet_strain_matrix(const Vec3* x, int n, const Vec3& natural, double* det_jacobian) {
  const Eigen::MatrixXd g = natural_gradients(n, natural);
  Mat3 J = Mat3::Zero();  // J(i, k) = d x_i / d xi_k
  for (int a = 0; a < n; ++a) J += x[a] * g.row(a);
  *det_jacobian = J.determinant();
  const Eigen::MatrixXd dN = g * J.inverse();  // n x 3: d N_a / d x_j
  MatX B = MatX::Zero(6, 3 * n);
  for (int a = 0; a < n; ++a) {
    const double dx = dN(a, 0), dy = dN(a, 1), dz = dN(a, 2);
    const int c = 3 * a;
    B(0, c) = dx;
    B(1, c + 1) = dy;
    B(2, c + 2) = dz;
    B(3, c + 1) = dz;
    B(3, c + 2) = dy;
    B(4, c) = dz;
    B(4, c + 2) = dx;
    B(5, c) = dy;
    B(5, c + 1) = dx;
  }
  return B;
}

MatX tet_stiffness(const Vec3* x, int n, const Mat6& D) {
  // 4-point rule of degree 2 on the unit tetrahedron (weights sum to its volume 1/6).
  static const double a = 0.5854101966249685, b = 0.1381966011250105;
  static const Vec3 kPoints[4] = {{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}};
  const int npoints = n == 4 ? 1 : 4;  // constant strain: one point is exact
  MatX K = MatX::Zero(3 * n, 3 * n);
  for (int q = 0; q < npoints; ++q) {
    double det = 0.0;
    const Vec3 p = n == 4 ? Vec3(0.25, 0.25, 0.25) : kPoints[q];
    const MatX B = tet_strain_matrix(x, n, p, &det);
    if (!(det > 0.0)) return MatX();
    const double w = (n == 4 ? 1.0 / 6.0 : 1.0 / 24.0) * det;
    K.noalias() += w * B.transpose() * D * B;
  }
  return K;
}

double von_mises(const Vec6& s) {
  const double d1 = s(0) - s(1), d2 = s(1) - s(2), d3 = s(2) - s(0);
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

}  // namespace kinestat::fea
