// Two-node 3D beam element (Przemieniecki 1968; Gonçalves et al. 2010, eq. (2)-(4)).
// Local dofs per node: ux, uy, uz, rx, ry, rz; node 1 then node 2.
//
// Note on eq. (2)-(3) of the 5R paper: written literally, [kb -kb; -kb kb] with the 6x6 kb of
// eq. (3) is not an element matrix (its off-diagonal bending blocks would have the wrong signs and
// the 2EI/L carry-over terms would be missing, and it is not invariant under rigid motion). Here
// the full 12x12 matrix is derived from beam theory and tested for rigid-body invariance,
// symmetry and the cantilever formulas.
#pragma once

#include <array>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {

enum class BeamTheory { kEulerBernoulli, kTimoshenko };

// End releases: released[i] = true frees local dof i (0..11) from the element, e.g. a pin at
// node 2 about local z is released[11]. Forces at released dofs are zero.
using BeamReleases = std::array<bool, 12>;

// The shear-deformation parameters Phi = 12 E I / (G As L^2) of a beam (Przemieniecki, ch. 5):
// phi_y of bending in the local x-y plane (uy, rz: Iz, Asy), phi_z in the x-z plane (uz, ry: Iy,
// Asz). Zero for Euler-Bernoulli beams and for a plane whose shear area is 0 (no shear deformation).
struct BeamShearParameters {
  double phi_y = 0.0, phi_z = 0.0;
};
BeamShearParameters beam_shear_parameters(const Material& m, const Section& s, double length, BeamTheory theory);

// 12x12 local stiffness. Timoshenko uses the section's shear areas (a zero shear area means that
// plane has no shear deformation).
Mat12 beam_local_stiffness(const Material& m, const Section& s, double length, BeamTheory theory);

// Static condensation of released dofs: K* = K_aa - K_ar K_rr^-1 K_ra, zero rows/cols at r.
// Fails when the released dofs leave the element itself free (e.g. torsion released at both ends).
StatusOr<Mat12> condense_releases(const Mat12& K, const BeamReleases& released);

// The element's geometric stiffness or mass X condensed with the same static shapes: T' X T, T = [I;
// -K_rr^-1 K_ra] (the released dofs follow the retained ones as the unloaded beam K makes them: the
// condensed element's own shape functions), zero rows and columns at r. X = K gives condense_releases.
// A Rayleigh-Ritz reduction: the released dofs carry no inertia or K_G of their own, which is what a
// released end's zero force means for the static shapes; converges as the member is divided.
StatusOr<Mat12> condense_with_releases(const Mat12& K, const BeamReleases& released, const Mat12& X);

// The same condensation of a fixed-end force vector f (member_loads.hpp) of the unreleased element
// K: f*_a = f_a - K_ar K_rr^-1 f_r, zero at r (the released dofs carry no force).
StatusOr<Vec12> condense_fixed_end_forces(const Mat12& K, const BeamReleases& released, const Vec12& f);

// 12x12 local geometric (initial-stress) stiffness of a beam carrying the axial force N (N, positive
// in tension): the consistent matrix of the cubic Euler-Bernoulli shape functions, McGuire,
// Gallagher & Ziemian, "Matrix Structural Analysis", 2nd ed. (2000), eq. (9.18) with the end
// moments set to zero (Przemieniecki 1968, on stability, gives the same terms). Bending in each plane:
// (N/L) [6/5, L/10, -6/5, L/10; ., 2L^2/15, -L/10, -L^2/30; ...]; axial: (N/L) [1 -1; -1 1]; with
// `polar_radius2` = Ip/A > 0 (Ip: polar_moment(section)), the torsion term N Ip/(A L) [1 -1; -1 1]
// (Wagner), 0: none.
// Symmetric; zero for rigid translations. Used as K_G in K phi = -lambda K_G phi (msa/buckling.hpp).
Mat12 beam_local_geometric_stiffness(double N, double length, double polar_radius2 = 0.0);

// The terms of the geometric stiffness. Defaults: the matrix above.
struct GeometricStiffnessTerms {
  double polar_radius2 = 0.0;  // Ip / A of the torsion term (Wagner); 0: none
  bool axial = true;           // (N/L) [1 -1; -1 1] on the axial dofs (Frame3DD since 2010: none)
  // Shear-deformation parameters of a Timoshenko beam (beam_shear_parameters): the bending terms are
  // then the consistent K_G of its shear-deformable cubic shape functions (Friedman & Kosmatka 1993;
  // Frame3DD's geometric_K has the same), per plane with D = (1 + Phi)^2: N/L (6/5 + 2 Phi + Phi^2)/D,
  // N/10/D, N L (2/15 + Phi/6 + Phi^2/12)/D and -N L (1/30 + Phi/6 + Phi^2/12)/D in place of
  // N/L 6/5, N/10, 2 N L/15 and -N L/30 (Phi = 0: the matrix above). With the Timoshenko elastic
  // matrix they converge to Engesser's critical load P_E / (1 + P_E / (G As)); the Euler-Bernoulli
  // K_G would not (docs/stability-and-modes.md).
  BeamShearParameters shear{};
};
Mat12 beam_local_geometric_stiffness(double N, double length, const GeometricStiffnessTerms& terms);

// 12x12 local mass matrix (kg, kg m, kg m^2) of a prismatic beam of `m.density`. Consistent
// (Przemieniecki, "Theory of Matrix Structural Analysis" (1968), ch. 11, the beam element's mass matrix):
// axial rho A L/6 [2 1; 1 2], torsion rho Ip L/6 [2 1; 1 2] (Ip = polar_moment(s): Iy + Iz unless
// the section says otherwise, elements/section.hpp),
// bending rho A L/420 [156 22L 54 -13L; ...] plus, with `rotary_inertia`, the cross-section's rotary
// inertia rho I/(30 L) [36 3L -36 3L; ...]. Lumped: rho A L / 2 on each node's translations and
// rho Ip L / 2 on its twist, nothing on the bending rotations (Cook et al., "Concepts and
// Applications of FEA", lumped mass of a beam). Symmetric; positive definite when consistent.
Mat12 beam_local_mass(const Material& m, const Section& s, double length, bool lumped, bool rotary_inertia = true);

// T such that u_local = T u_global, from the local axes (columns x, y, z in global coordinates).
Mat12 beam_transformation(const Mat3& axes);

}  // namespace kinestat
