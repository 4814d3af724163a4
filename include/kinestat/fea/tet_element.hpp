// Isotropic linear-elastic tetrahedra: 4-node (constant strain) and 10-node (quadratic
// displacement, linear strain). Dofs per node: ux, uy, uz; element dofs node by node.
// Strains and stresses in Voigt order xx, yy, zz, yz, xz, xy with engineering shear strains.
#pragma once

#include "kinestat/core/types.hpp"
#include "kinestat/elements/material.hpp"

namespace kinestat::fea {

// 6x6 isotropic elasticity matrix D (Pa) from E and G of the material (sigma = D epsilon).
Mat6 elasticity_matrix(const Material& m);

// Element stiffness (N/m), 3n x 3n for n = 4 or 10 nodes at `x` (n coordinates). The 10-node
// element is integrated with the 4-point degree-2 rule, exact for straight-sided elements where
// B^T D B is quadratic. Returns an empty matrix when the Jacobian is not positive at a point.
MatX tet_stiffness(const Vec3* x, int n, const Mat6& D);

// The same, fixed-size (no heap allocation: the assembly's inner loop), N = 4 or 10; false when the
// Jacobian is not positive at a point.
template <int N>
using TetMatrix = Eigen::Matrix<double, 3 * N, 3 * N>;
template <int N>
bool tet_stiffness(const Vec3* x, const Mat6& D, TetMatrix<N>* K);
extern template bool tet_stiffness<4>(const Vec3*, const Mat6&, TetMatrix<4>*);
extern template bool tet_stiffness<10>(const Vec3*, const Mat6&, TetMatrix<10>*);

// Strain-displacement matrix B (6 x 3n) at the natural point (xi, eta, zeta) and det J there.
MatX tet_strain_matrix(const Vec3* x, int n, const Vec3& natural, double* det_jacobian);

// Von Mises equivalent stress of a Voigt stress vector (Pa).
double von_mises(const Vec6& stress);

}  // namespace kinestat::fea
