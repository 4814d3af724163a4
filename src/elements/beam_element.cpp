#include "kinestat/elements/beam_element.hpp"

#include <vector>

#include <fmt/format.h>

namespace kinestat {

Mat12 beam_local_stiffness(const Material& m, const Section& s, double L, BeamTheory theory) {
  const double E = m.E, G = m.G;
  // Shear-deformation parameters Phi = 12 E I / (G As L^2) (Przemieniecki, ch. 5).
  double phi_y = 0.0, phi_z = 0.0;  // phi_y: bending in x-y plane (uy, rz); phi_z: in x-z plane
  if (theory == BeamTheory::kTimoshenko) {
    if (s.Asy > 0) phi_y = 12.0 * E * s.Iz / (G * s.Asy * L * L);
    if (s.Asz > 0) phi_z = 12.0 * E * s.Iy / (G * s.Asz * L * L);
  }
  Mat12 K = Mat12::Zero();
  const double ea = E * s.A / L, gj = G * s.J / L;
  K(0, 0) = K(6, 6) = ea;
  K(0, 6) = K(6, 0) = -ea;
  K(3, 3) = K(9, 9) = gj;
  K(3, 9) = K(9, 3) = -gj;

  // Bending in the local x-y plane: dofs uy1 (1), rz1 (5), uy2 (7), rz2 (11); I = Iz.
  {
    const double c = E * s.Iz / ((1.0 + phi_y) * L * L * L);
    const int d[4] = {1, 5, 7, 11};
    const double k[4][4] = {{12, 6 * L, -12, 6 * L},
                            {6 * L, (4 + phi_y) * L * L, -6 * L, (2 - phi_y) * L * L},
                            {-12, -6 * L, 12, -6 * L},
                            {6 * L, (2 - phi_y) * L * L, -6 * L, (4 + phi_y) * L * L}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) K(d[i], d[j]) = c * k[i][j];
  }
  // Bending in the local x-z plane: dofs uz1 (2), ry1 (4), uz2 (8), ry2 (10); I = Iy.
  // A positive ry bends the beam towards -z, hence the opposite coupling signs.
  {
    const double c = E * s.Iy / ((1.0 + phi_z) * L * L * L);
    const int d[4] = {2, 4, 8, 10};
    const double k[4][4] = {{12, -6 * L, -12, -6 * L},
                            {-6 * L, (4 + phi_z) * L * L, 6 * L, (2 - phi_z) * L * L},
                            {-12, 6 * L, 12, 6 * L},
                            {-6 * L, (2 - phi_z) * L * L, 6 * L, (4 + phi_z) * L * L}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) K(d[i], d[j]) = c * k[i][j];
  }
  return K;
}

StatusOr<Mat12> condense_releases(const Mat12& K, const BeamReleases& released) {
  std::vector<int> r, a;
  for (int i = 0; i < 12; ++i) (released[i] ? r : a).push_back(i);
  if (r.empty()) return K;
  const int nr = static_cast<int>(r.size()), na = static_cast<int>(a.size());
  MatX Krr(nr, nr), Kra(nr, na), Kaa(na, na);
  for (int i = 0; i < nr; ++i) {
    for (int j = 0; j < nr; ++j) Krr(i, j) = K(r[i], r[j]);
    for (int j = 0; j < na; ++j) Kra(i, j) = K(r[i], a[j]);
  }
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < na; ++j) Kaa(i, j) = K(a[i], a[j]);
  Eigen::LDLT<MatX> ldlt(Krr);
  // A released set that the element cannot resist on its own (both torsion ends, both axial
  // ends, ...) makes K_rr singular.
  const double scale = Krr.diagonal().cwiseAbs().maxCoeff();
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * scale))
    return Status::Invalid("the end releases leave the beam free to move on its own (e.g. torsion or axial "
                           "released at both ends); release at one end only");
  const MatX Kc = Kaa - Kra.transpose() * ldlt.solve(Kra);
  Mat12 out = Mat12::Zero();
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < na; ++j) out(a[i], a[j]) = Kc(i, j);
  return out;
}

Mat12 beam_transformation(const Mat3& axes) {
  Mat12 T = Mat12::Zero();
  for (int b = 0; b < 4; ++b) T.block<3, 3>(3 * b, 3 * b) = axes.transpose();
  return T;
}

}  // namespace kinestat
