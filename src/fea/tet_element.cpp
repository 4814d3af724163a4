#include "kinestat/fea/tet_element.hpp"

#include <array>
#include <cmath>

#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {

namespace {

// Derivatives of the N shape functions with respect to (xi, eta, zeta): an N x 3 matrix.
// Volume coordinates L0 = 1 - xi - eta - zeta, L1 = xi, L2 = eta, L3 = zeta.
template <int N>
Eigen::Matrix<double, N, 3> natural_gradients(const Vec3& p) {
  const std::array<double, 4> L = {1.0 - p.x() - p.y() - p.z(), p.x(), p.y(), p.z()};
  // dL_i / d(xi, eta, zeta)
  static const double dL[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Eigen::Matrix<double, N, 3> g;
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) g(i, k) = N == 4 ? dL[i][k] : (4.0 * L[i] - 1.0) * dL[i][k];  // N = L(2L-1)
  if constexpr (N == 10) {
    for (int e = 0; e < 6; ++e) {
      const int a = kTet10Edges[e][0], b = kTet10Edges[e][1];
      for (int k = 0; k < 3; ++k) g(4 + e, k) = 4.0 * (dL[a][k] * L[b] + L[a] * dL[b][k]);  // N = 4 La Lb
    }
  }
  return g;
}

template <int N>
Eigen::Matrix<double, 6, 3 * N> strain_matrix(const Vec3* x, const Vec3& natural, double* det_jacobian) {
  const Eigen::Matrix<double, N, 3> g = natural_gradients<N>(natural);
  Mat3 J = Mat3::Zero();  // J(i, k) = d x_i / d xi_k
  for (int a = 0; a < N; ++a) J += x[a] * g.row(a);
  *det_jacobian = J.determinant();
  const Eigen::Matrix<double, N, 3> dN = g * J.inverse();  // d N_a / d x_j
  Eigen::Matrix<double, 6, 3 * N> B = Eigen::Matrix<double, 6, 3 * N>::Zero();
  for (int a = 0; a < N; ++a) {
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

// The N shape functions at the natural point p.
template <int N>
Eigen::Matrix<double, N, 1> shape_functions(const Vec3& p) {
  const std::array<double, 4> L = {1.0 - p.x() - p.y() - p.z(), p.x(), p.y(), p.z()};
  Eigen::Matrix<double, N, 1> s;
  for (int i = 0; i < 4; ++i) s(i) = N == 4 ? L[i] : L[i] * (2.0 * L[i] - 1.0);
  if constexpr (N == 10)
    for (int e = 0; e < 6; ++e) s(4 + e) = 4.0 * L[kTet10Edges[e][0]] * L[kTet10Edges[e][1]];
  return s;
}

// det J at the natural point p (J(i, k) = d x_i / d xi_k).
template <int N>
double jacobian_determinant(const Vec3* x, const Vec3& p) {
  const Eigen::Matrix<double, N, 3> g = natural_gradients<N>(p);
  Mat3 J = Mat3::Zero();
  for (int a = 0; a < N; ++a) J += x[a] * g.row(a);
  return J.determinant();
}

// A symmetric quadrature rule on the unit tetrahedron: points in volume coordinates (L1, L2, L3) =
// (xi, eta, zeta), weights summing to its volume 1/6.
struct QuadraturePoint {
  Vec3 p;
  double w;
};

// 4 points, degree 2.
std::array<QuadraturePoint, 4> degree2_rule() {
  const double a = 0.5854101966249685, b = 0.1381966011250105, w = 1.0 / 24.0;
  return {{{{b, b, b}, w}, {{a, b, b}, w}, {{b, a, b}, w}, {{b, b, a}, w}}};
}

// 14 points, degree 5, positive weights (Walkington 2000; the rule of Keast 1986 of the same
// degree): two orbits of 4 points (a, a, a, 1 - 3a) and one of 6 points (b, b, 1/2 - b, 1/2 - b).
// tests/fea/tet_element_test.cpp checks it integrates every monomial of degree <= 5 exactly.
std::array<QuadraturePoint, 14> degree5_rule() {
  std::array<QuadraturePoint, 14> r;
  int k = 0;
  const double a[2] = {0.0927352503108912, 0.3108859192633006};
  const double wa[2] = {0.01224884051939366, 0.01878132095300264};
  for (int o = 0; o < 2; ++o)
    for (int i = 0; i < 4; ++i) {
      std::array<double, 4> L;
      L.fill(a[o]);
      L[i] = 1.0 - 3.0 * a[o];
      r[k++] = {Vec3(L[1], L[2], L[3]), wa[o]};
    }
  const double b = 0.0455037041256496, c = 0.5 - b, wb = 0.007091003462846911;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      std::array<double, 4> L;
      L.fill(b);
      L[i] = c;
      L[j] = c;
      r[k++] = {Vec3(L[1], L[2], L[3]), wb};
    }
  return r;
}

}  // namespace

std::vector<std::pair<Vec3, double>> tet_quadrature_rule(int degree) {
  std::vector<std::pair<Vec3, double>> out;
  if (degree <= 2)
    for (const QuadraturePoint& q : degree2_rule()) out.emplace_back(q.p, q.w);
  else
    for (const QuadraturePoint& q : degree5_rule()) out.emplace_back(q.p, q.w);
  return out;
}

template <int N>
bool tet_mass(const Vec3* x, double density, TetMatrix<N>* M) {
  static const auto rule = [] {
    if constexpr (N == 4)
      return degree2_rule();
    else
      return degree5_rule();
  }();
  // The scalar mass rho N N^T, then one copy per direction: M(3a+d, 3b+d) = m(a, b).
  Eigen::Matrix<double, N, N> m = Eigen::Matrix<double, N, N>::Zero();
  for (const QuadraturePoint& q : rule) {
    const double det = jacobian_determinant<N>(x, q.p);
    if (!(det > 0.0)) return false;
    const Eigen::Matrix<double, N, 1> s = shape_functions<N>(q.p);
    m.noalias() += (density * q.w * det) * (s * s.transpose());
  }
  M->setZero();
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N; ++b)
      for (int d = 0; d < 3; ++d) (*M)(3 * a + d, 3 * b + d) = m(a, b);
  return true;
}
template bool tet_mass<4>(const Vec3*, double, TetMatrix<4>*);
template bool tet_mass<10>(const Vec3*, double, TetMatrix<10>*);

MatX tet_mass(const Vec3* x, int n, double density) {
  if (n == 4) {
    TetMatrix<4> M;
    return tet_mass<4>(x, density, &M) ? MatX(M) : MatX();
  }
  TetMatrix<10> M;
  return tet_mass<10>(x, density, &M) ? MatX(M) : MatX();
}

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
  if (n == 4) return strain_matrix<4>(x, natural, det_jacobian);
  return strain_matrix<10>(x, natural, det_jacobian);
}

template <int N>
bool tet_stiffness(const Vec3* x, const Mat6& D, TetMatrix<N>* K) {
  // 4-point rule of degree 2 on the unit tetrahedron (weights sum to its volume 1/6).
  static const double a = 0.5854101966249685, b = 0.1381966011250105;
  static const Vec3 kPoints[4] = {{b, b, b}, {a, b, b}, {b, a, b}, {b, b, a}};
  constexpr int kPointCount = N == 4 ? 1 : 4;  // constant strain: one point is exact
  K->setZero();
  for (int q = 0; q < kPointCount; ++q) {
    double det = 0.0;
    const Vec3 p = N == 4 ? Vec3(0.25, 0.25, 0.25) : kPoints[q];
    const Eigen::Matrix<double, 6, 3 * N> B = strain_matrix<N>(x, p, &det);
    if (!(det > 0.0)) return false;
    const double w = (N == 4 ? 1.0 / 6.0 : 1.0 / 24.0) * det;
    const Eigen::Matrix<double, 6, 3 * N> DB = w * D * B;
    K->noalias() += B.transpose() * DB;
  }
  return true;
}
template bool tet_stiffness<4>(const Vec3*, const Mat6&, TetMatrix<4>*);
template bool tet_stiffness<10>(const Vec3*, const Mat6&, TetMatrix<10>*);

MatX tet_stiffness(const Vec3* x, int n, const Mat6& D) {
  if (n == 4) {
    TetMatrix<4> K;
    return tet_stiffness<4>(x, D, &K) ? MatX(K) : MatX();
  }
  TetMatrix<10> K;
  return tet_stiffness<10>(x, D, &K) ? MatX(K) : MatX();
}

double von_mises(const Vec6& s) {
  const double d1 = s(0) - s(1), d2 = s(1) - s(2), d3 = s(2) - s(0);
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) + 3.0 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

}  // namespace kinestat::fea
