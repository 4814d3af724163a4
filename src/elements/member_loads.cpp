#include "kinestat/elements/member_loads.hpp"

#include <array>
#include <cmath>

namespace kinestat {
namespace {

// Shear parameters of the two bending planes, as beam_local_stiffness computes them.
struct ShearParameters {
  double y = 0.0;  // bending in the x-y plane (uy, rz), I = Iz, shear area Asy
  double z = 0.0;  // bending in the x-z plane (uz, ry), I = Iy, shear area Asz
};

ShearParameters shear_parameters(const BeamSpan& b) {
  ShearParameters p;
  if (b.theory != BeamTheory::kTimoshenko) return p;
  const double E = b.material.E, G = b.material.G, L = b.length;
  if (b.section.Asy > 0) p.y = 12.0 * E * b.section.Iz / (G * b.section.Asy * L * L);
  if (b.section.Asz > 0) p.z = 12.0 * E * b.section.Iy / (G * b.section.Asz * L * L);
  return p;
}

// Exact deflection N and cross-section rotation R of a prismatic Timoshenko beam at xi = x / L for
// a unit value of each end dof (v1, theta1, v2, theta2) of one bending plane, the other three held
// at zero, theta being the rotation that turns +x towards +v (Friedman and Kosmatka 1993).
struct PlaneShapes {
  std::array<double, 4> N, R;
};

PlaneShapes plane_shapes(double xi, double L, double phi) {
  const double mu = 1.0 / (1.0 + phi), x2 = xi * xi, x3 = x2 * xi;
  PlaneShapes s;
  s.N = {mu * (1.0 - 3.0 * x2 + 2.0 * x3 + phi * (1.0 - xi)), L * mu * (xi - 2.0 * x2 + x3 + 0.5 * phi * (xi - x2)),
         mu * (3.0 * x2 - 2.0 * x3 + phi * xi), L * mu * (-x2 + x3 + 0.5 * phi * (x2 - xi))};
  s.R = {6.0 * mu / L * (x2 - xi), mu * (1.0 - 4.0 * xi + 3.0 * x2 + phi * (1.0 - xi)), 6.0 * mu / L * (xi - x2),
         mu * (-2.0 * xi + 3.0 * x2 + phi * xi)};
  return s;
}

// Adds the clamp forces of a force f and a moment c (local axes) at distance x: minus the work of
// (f, c) on the unit-dof fields. In the x-z plane the dofs are uz and ry = -theta (a positive ry
// turns +x towards -z), hence the sign flips on the rotation dofs.
void add_concentrated(const BeamSpan& b, const ShearParameters& phi, double x, const Vec3& f, const Vec3& c,
                      Vec12& fef) {
  const double L = b.length, xi = x / L;
  fef(0) -= f.x() * (1.0 - xi);
  fef(6) -= f.x() * xi;
  fef(3) -= c.x() * (1.0 - xi);
  fef(9) -= c.x() * xi;
  const PlaneShapes y = plane_shapes(xi, L, phi.y), z = plane_shapes(xi, L, phi.z);
  const int dy[4] = {1, 5, 7, 11}, dz[4] = {2, 4, 8, 10};
  const double sign[4] = {1.0, -1.0, 1.0, -1.0};  // uz = w, ry = -theta
  for (int k = 0; k < 4; ++k) {
    fef(dy[k]) -= f.y() * y.N[k] + c.z() * y.R[k];
    // The ry field of dof k is -sign[k] R[k]; the w field is sign[k] N[k].
    fef(dz[k]) -= f.z() * sign[k] * z.N[k] - c.y() * sign[k] * z.R[k];
  }
}

}  // namespace

Vec12 trapezoidal_load_fixed_end_forces(const BeamSpan& beam, double a, double b, const Vec3& w1, const Vec3& w2) {
  // The integrand (a cubic field times a linear load) has degree 4: three Gauss points are exact.
  static constexpr double kPoint[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
  static constexpr double kWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  const ShearParameters phi = shear_parameters(beam);
  Vec12 fef = Vec12::Zero();
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  for (int g = 0; g < 3; ++g) {
    const double t = 0.5 * (1.0 + kPoint[g]);  // 0 at a, 1 at b
    add_concentrated(beam, phi, mid + half * kPoint[g], (kWeight[g] * half) * ((1.0 - t) * w1 + t * w2), Vec3::Zero(),
                     fef);
  }
  return fef;
}

Vec12 uniform_load_fixed_end_forces(const BeamSpan& beam, const Vec3& w) {
  return trapezoidal_load_fixed_end_forces(beam, 0.0, beam.length, w, w);
}

Vec12 point_load_fixed_end_forces(const BeamSpan& beam, double a, const Vec3& force, const Vec3& moment) {
  Vec12 fef = Vec12::Zero();
  add_concentrated(beam, shear_parameters(beam), a, force, moment, fef);
  return fef;
}

Vec12 temperature_fixed_end_forces(const BeamSpan& beam, const ThermalLoad& t) {
  const double E = beam.material.E;
  const Section& s = beam.section;
  // Clamped: the mechanical strain cancels the thermal one, -alpha (dT + dTy y / hy + dTz z / hz).
  const double N = E * s.A * t.alpha * t.dT;                                  // compression in the beam
  const double Mz = t.dTy != 0.0 ? E * s.Iz * t.alpha * t.dTy / t.hy : 0.0;   // internal moment about z
  const double My = t.dTz != 0.0 ? -E * s.Iy * t.alpha * t.dTz / t.hz : 0.0;  // internal moment about y
  Vec12 fef = Vec12::Zero();
  // At the second end the force on the beam is the internal force, at the first end its negative.
  fef(0) = N;
  fef(6) = -N;
  fef(4) = -My;
  fef(10) = My;
  fef(5) = -Mz;
  fef(11) = Mz;
  return fef;
}

}  // namespace kinestat
