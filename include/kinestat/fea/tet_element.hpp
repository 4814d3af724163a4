// Isotropic linear-elastic tetrahedra: 4-node (constant strain) and 10-node (quadratic
// displacement, linear strain). Dofs per node: ux, uy, uz; element dofs node by node.
// Strains and stresses in Voigt order xx, yy, zz, yz, xz, xy with engineering shear strains.
#pragma once

#include <utility>
#include <vector>

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

// Consistent mass matrix rho * integral of N^T N dV (kg), 3n x 3n, the same dof order as the
// stiffness; `density` in kg/m^3. N^T N is of degree 2 (4 nodes) or 4 (10 nodes): the 4-node element
// is integrated with the 4-point degree-2 rule, the 10-node one with the 14-point degree-5 rule
// (positive weights), both exact for straight-sided elements. False (and an empty matrix from the
// MatX form) when the Jacobian is not positive at a point.
template <int N>
bool tet_mass(const Vec3* x, double density, TetMatrix<N>* M);
extern template bool tet_mass<4>(const Vec3*, double, TetMatrix<4>*);
extern template bool tet_mass<10>(const Vec3*, double, TetMatrix<10>*);
MatX tet_mass(const Vec3* x, int n, double density);

// The rule tet_mass integrates with (degree 2: 4 points; above: the 14-point rule of degree 5), as
// (xi, eta, zeta) and weight pairs on the unit tetrahedron (weights sum to 1/6).
std::vector<std::pair<Vec3, double>> tet_quadrature_rule(int degree);

// Strain-displacement matrix B (6 x 3n) at the natural point (xi, eta, zeta) and det J there.
MatX tet_strain_matrix(const Vec3* x, int n, const Vec3& natural, double* det_jacobian);

// Von Mises equivalent stress of a Voigt stress vector (Pa).
double von_mises(const Vec6& stress);

}  // namespace kinestat::fea
