#include "kinestat/elements/beam_element.hpp"

#include <vector>

#include <fmt/format.h>

namespace kinestat {

BeamShearParameters beam_shear_parameters(const Material& m, const Section& s, double L, BeamTheory theory) {
  // Shear-deformation parameters Phi = 12 E I / (G As L^2) (Przemieniecki, ch. 5).
  BeamShearParameters p;  // phi_y: bending in x-y plane (uy, rz); phi_z: in x-z plane
  if (theory == BeamTheory::kTimoshenko) {
    if (s.Asy > 0) p.phi_y = 12.0 * m.E * s.Iz / (m.G * s.Asy * L * L);
    if (s.Asz > 0) p.phi_z = 12.0 * m.E * s.Iy / (m.G * s.Asz * L * L);
  }
  return p;
}

Mat12 beam_local_stiffness(const Material& m, const Section& s, double L, BeamTheory theory) {
  const double E = m.E, G = m.G;
  const auto [phi_y, phi_z] = beam_shear_parameters(m, s, L, theory);
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

namespace {

// The partition of K into released (r) and retained (a) dofs with K_rr factorized: shared by the
// condensation of the stiffness and of the fixed-end forces.
struct ReleasePartition {
  std::vector<int> r, a;
  MatX Kra;
  Eigen::LDLT<MatX> ldlt;
};

StatusOr<ReleasePartition> partition_releases(const Mat12& K, const BeamReleases& released) {
  ReleasePartition p;
  for (int i = 0; i < 12; ++i) (released[i] ? p.r : p.a).push_back(i);
  const int nr = static_cast<int>(p.r.size()), na = static_cast<int>(p.a.size());
  MatX Krr(nr, nr);
  p.Kra.resize(nr, na);
  for (int i = 0; i < nr; ++i) {
    for (int j = 0; j < nr; ++j) Krr(i, j) = K(p.r[i], p.r[j]);
    for (int j = 0; j < na; ++j) p.Kra(i, j) = K(p.r[i], p.a[j]);
  }
  p.ldlt.compute(Krr);
  // A released set that the element cannot resist on its own (both torsion ends, both axial
  // ends, ...) makes K_rr singular.
  const double scale = Krr.diagonal().cwiseAbs().maxCoeff();
  if (p.ldlt.info() != Eigen::Success || !(p.ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * scale))
    return Status::Invalid(
        "the end releases leave the beam free to move on its own (e.g. torsion or axial "
        "released at both ends); release at one end only");
  return p;
}

}  // namespace

StatusOr<Mat12> condense_releases(const Mat12& K, const BeamReleases& released) {
  return condense_with_releases(K, released, K);
}

StatusOr<Mat12> condense_with_releases(const Mat12& K, const BeamReleases& released, const Mat12& X) {
  bool any = false;
  for (bool r : released) any = any || r;
  if (!any) return X;
  auto p = partition_releases(K, released);
  if (!p.ok()) return p.status();
  const int na = static_cast<int>(p->a.size()), nr = static_cast<int>(p->r.size());
  // T: unit retained dofs and the released ones' static answer -K_rr^-1 K_ra.
  MatX T = MatX::Zero(12, na);
  const MatX Tr = -p->ldlt.solve(p->Kra);
  for (int j = 0; j < na; ++j) {
    T(p->a[j], j) = 1.0;
    for (int i = 0; i < nr; ++i) T(p->r[i], j) = Tr(i, j);
  }
  const MatX Xc = T.transpose() * X * T;
  Mat12 out = Mat12::Zero();
  for (int i = 0; i < na; ++i)
    for (int j = 0; j < na; ++j) out(p->a[i], p->a[j]) = 0.5 * (Xc(i, j) + Xc(j, i));
  return out;
}

StatusOr<Vec12> condense_fixed_end_forces(const Mat12& K, const BeamReleases& released, const Vec12& f) {
  bool any = false;
  for (bool r : released) any = any || r;
  if (!any) return f;
  auto p = partition_releases(K, released);
  if (!p.ok()) return p.status();
  VecX fr(p->r.size());
  for (size_t i = 0; i < p->r.size(); ++i) fr(static_cast<int>(i)) = f(p->r[i]);
  // The released dofs move until their clamp force is gone: f_a - K_ar K_rr^-1 f_r.
  const VecX fc = p->Kra.transpose() * p->ldlt.solve(fr);
  Vec12 out = Vec12::Zero();
  for (size_t i = 0; i < p->a.size(); ++i) out(p->a[i]) = f(p->a[i]) - fc(static_cast<int>(i));
  return out;
}

Mat12 beam_local_geometric_stiffness(double N, double L, double polar_radius2) {
  return beam_local_geometric_stiffness(N, L, GeometricStiffnessTerms{polar_radius2, true, {}});
}

Mat12 beam_local_geometric_stiffness(double N, double L, const GeometricStiffnessTerms& terms) {
  Mat12 K = Mat12::Zero();
  const double c = N / L;
  if (terms.axial) {
    K(0, 0) = K(6, 6) = c;
    K(0, 6) = K(6, 0) = -c;
  }
  const double t = c * terms.polar_radius2;
  K(3, 3) = K(9, 9) = t;
  K(3, 9) = K(9, 3) = -t;
  // McGuire-Gallagher-Ziemian eq. (9.18): x-y plane (uy1, rz1, uy2, rz2); the x-z plane has the
  // coupling signs flipped as in beam_local_stiffness (a positive ry bends towards -z). With shear
  // deformation (Phi > 0) the Timoshenko terms of GeometricStiffnessTerms::shear.
  auto plane = [L](double phi, double(&k)[4][4]) {
    const double d = (1 + phi) * (1 + phi);
    const double a = (6.0 / 5 + 2 * phi + phi * phi) / d, b = L / 10 / d;
    const double e = L * L * (2.0 / 15 + phi / 6 + phi * phi / 12) / d;
    const double f = -L * L * (1.0 / 30 + phi / 6 + phi * phi / 12) / d;
    const double m[4][4] = {{a, b, -a, b}, {b, e, -b, f}, {-a, -b, a, -b}, {b, f, -b, e}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) k[i][j] = m[i][j];
  };
  double ky[4][4], kz[4][4];
  plane(terms.shear.phi_y, ky);
  plane(terms.shear.phi_z, kz);
  const int dy[4] = {1, 5, 7, 11}, dz[4] = {2, 4, 8, 10};
  const double sz[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      K(dy[i], dy[j]) = c * ky[i][j];
      K(dz[i], dz[j]) = c * sz[i] * sz[j] * kz[i][j];
    }
  return K;
}

Mat12 beam_local_mass(const Material& mat, const Section& s, double L, bool lumped, bool rotary_inertia) {
  Mat12 M = Mat12::Zero();
  const double m = mat.density * s.A * L, mt = mat.density * polar_moment(s) * L;
  if (lumped) {
    for (int i : {0, 1, 2, 6, 7, 8}) M(i, i) = m / 2;
    M(3, 3) = M(9, 9) = mt / 2;
    return M;
  }
  M(0, 0) = M(6, 6) = m / 3;
  M(0, 6) = M(6, 0) = m / 6;
  M(3, 3) = M(9, 9) = mt / 3;
  M(3, 9) = M(9, 3) = mt / 6;
  // Przemieniecki ch. 11: translational (m/420) and rotary (rho I/(30 L)) parts, x-y plane
  // (uy1, rz1, uy2, rz2); the x-z plane flips the coupling signs as the stiffness does.
  const double t[4][4] = {{156, 22 * L, 54, -13 * L},
                          {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                          {54, 13 * L, 156, -22 * L},
                          {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
  const double r[4][4] = {{36, 3 * L, -36, 3 * L},
                          {3 * L, 4 * L * L, -3 * L, -L * L},
                          {-36, -3 * L, 36, -3 * L},
                          {3 * L, -L * L, -3 * L, 4 * L * L}};
  const double ry = rotary_inertia ? mat.density * s.Iz / (30 * L) : 0.0;  // bending about z: Iz
  const double rz = rotary_inertia ? mat.density * s.Iy / (30 * L) : 0.0;
  const int dy[4] = {1, 5, 7, 11}, dz[4] = {2, 4, 8, 10};
  const double sz[4] = {1, -1, 1, -1};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      M(dy[i], dy[j]) = m / 420 * t[i][j] + ry * r[i][j];
      M(dz[i], dz[j]) = sz[i] * sz[j] * (m / 420 * t[i][j] + rz * r[i][j]);
    }
  return M;
}

Mat12 beam_transformation(const Mat3& axes) {
  Mat12 T = Mat12::Zero();
  for (int b = 0; b < 4; ++b) T.block<3, 3>(3 * b, 3 * b) = axes.transpose();
  return T;
}

}  // namespace kinestat
