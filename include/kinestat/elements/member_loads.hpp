// Fixed-end forces of loads on a beam's span, in the beam's local axes: the forces the two clamps
// exert on the beam when both ends are held fixed, in the order of the element's dofs (N1 Vy1 Vz1 T1
// My1 Mz1 N2 Vy2 Vz2 T2 My2 Mz2; the same convention as k u, "the force on the beam"). The
// equivalent nodal loads are their negatives, and the member's true end forces are k u + FEF.
//
// Exact for Euler-Bernoulli and Timoshenko beams: by Betti's theorem the clamp force at dof i is
// minus the work of the load on the displacement field of a unit displacement of dof i with the
// other dofs fixed, and for a prismatic beam without span load that field is known exactly (cubic
// deflection, quadratic rotation, with the shear parameter Phi = 12 E I / (G As L^2): Friedman and
// Kosmatka, "An improved two-node Timoshenko beam finite element", Computers & Structures 47(3),
// 1993; Phi = 0 gives the Hermite cubics). tests/elements/member_loads_test.cpp checks the point
// load against an independent force-method derivation.
// End releases are condensed afterwards with condense_fixed_end_forces (beam_element.hpp).
#pragma once

#include "kinestat/core/types.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {

// A temperature change of the beam: uniform dT at the centroid, and through-depth differences
// dTy = T(+y face) - T(-y face) over the depth hy (along local y) and dTz = T(+z face) - T(-z face)
// over hz. Frame3DD's face temperatures Ty+, Ty-, Tz+, Tz- give dT = (Ty+ + Ty- + Tz+ + Tz-)/4,
// dTy = Ty+ - Ty-, dTz = Tz+ - Tz-. Units: alpha 1/K, depths m, temperatures K (or degrees C).
struct ThermalLoad {
  double alpha = 0.0;
  double hy = 0.0, hz = 0.0;
  double dT = 0.0, dTy = 0.0, dTz = 0.0;
};

// The bending and shear data the fixed-end forces need (Phi from the section's shear areas when
// `theory` is Timoshenko, as beam_local_stiffness does).
struct BeamSpan {
  Material material;
  Section section;
  double length = 0.0;
  BeamTheory theory = BeamTheory::kEulerBernoulli;
};

// A uniform load w (force per length, local axes: axial w.x, transverse w.y, w.z) on the whole span.
Vec12 uniform_load_fixed_end_forces(const BeamSpan& beam, const Vec3& w);

// A load varying linearly from w1 at distance a to w2 at distance b from the first node
// (0 <= a < b <= L), zero elsewhere; local axes, force per length.
Vec12 trapezoidal_load_fixed_end_forces(const BeamSpan& beam, double a, double b, const Vec3& w1, const Vec3& w2);

// A force and a moment (local axes) applied at distance a (0 <= a <= L) from the first node.
Vec12 point_load_fixed_end_forces(const BeamSpan& beam, double a, const Vec3& force, const Vec3& moment);

// A temperature change: the clamps hold the free thermal elongation alpha dT L and curvatures
// alpha dTy / hy, alpha dTz / hz (a heated +y face bends the beam towards -y). Axial force in the
// clamped beam -E A alpha dT (compression for heating), end moments E Iz alpha dTy / hy about z and
// E Iy alpha dTz / hz about y; shear deformation plays no part (the moment is constant).
Vec12 temperature_fixed_end_forces(const BeamSpan& beam, const ThermalLoad& t);

}  // namespace kinestat
