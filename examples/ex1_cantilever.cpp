// kinestat example 1: a cantilever built in code.
//
// Compile: built with kinestat (target ex1_cantilever), or against an installed kinestat with
//          find_package(kinestat) and target_link_libraries(... kinestat::kinestat).
// Run:     build/examples/ex1_cantilever
//
// A steel bar, 1 m long, 20 mm wide (y) and 40 mm high (z), clamped at its root and loaded at its
// tip by 1 kN downwards. Beam theory gives the tip deflection P L^3 / (3 E I) with I = b h^3 / 12;
// the example builds the model with the library's C++ API (no file), solves it, compares, and
// prints the 6x6 Cartesian stiffness of the tip with the report every kinestat method uses.
// It exits with status 1 when the deflection differs from beam theory by more than 1e-9.
//
// Expected output (entries of order 1e-11 and the symmetry error are round-off and vary):
//   tip deflection uz = -1.488095e-02 m, beam theory P L^3 / (3 E I) = -1.488095e-02 m (relative difference 1.2e-16)
//   clamp reaction Fz = 1000.000 N, My = -1000.000 N m (the load and its moment about the root)
//
//   Cartesian stiffness of the tip: point (1, 0, 0) m, global axes; dofs ux uy uz rx ry rz
//     stiffness K [N/m, N/rad (rows ux uy uz); N, N m/rad (rows rx ry rz)]
//                       ux          uy          uz          rx          ry          rz
//         ux    1.6800e+08  0.0000e+00  0.0000e+00  0.0000e+00  0.0000e+00  0.0000e+00
//         uy    0.0000e+00  6.7200e+04  0.0000e+00  0.0000e+00  0.0000e+00 -3.3600e+04
//         uz    0.0000e+00  0.0000e+00  2.6880e+05  3.1498e-11  1.3440e+05  0.0000e+00
//         rx    0.0000e+00  0.0000e+00  3.1498e-11  5.9105e+03  1.5749e-11  0.0000e+00
//         ry    0.0000e+00  0.0000e+00  1.3440e+05  1.5749e-11  8.9600e+04  0.0000e+00
//         rz    0.0000e+00 -3.3600e+04  0.0000e+00  0.0000e+00  0.0000e+00  2.2400e+04
//     compliance C = K^-1 [m/N, m/(N m) (rows ux uy uz); rad/N, rad/(N m) (rows rx ry rz)]
//                       ux          uy          uz          rx          ry          rz
//         ux    5.9524e-09  0.0000e+00  0.0000e+00  0.0000e+00  0.0000e+00  0.0000e+00
//         uy    0.0000e+00  5.9524e-05  0.0000e+00  0.0000e+00  0.0000e+00  8.9286e-05
//         uz    0.0000e+00  0.0000e+00  1.4881e-05  0.0000e+00 -2.2321e-05  0.0000e+00
//         rx    0.0000e+00  0.0000e+00  0.0000e+00  1.6919e-04  0.0000e+00  0.0000e+00
//         ry    0.0000e+00  0.0000e+00 -2.2321e-05  0.0000e+00  4.4643e-05  0.0000e+00
//         rz    0.0000e+00  8.9286e-05  0.0000e+00  0.0000e+00  0.0000e+00  1.7857e-04
//     indices of K:
//       size 6x6, symmetry error 6.1e-20
//       determinant       2.2499e+30 (sign 1, log10|det| = 30.3522)
//       trace             1.6845e+08
//       1-norm            1.6800e+08
//       2-norm            1.6800e+08
//       Frobenius norm    1.6800e+08
//       inf-norm (rows)   1.6800e+08
//       max |k_ij|        1.6800e+08
//       condition number  3.8028e+04
//     eigenvalues of K (SI, mixed units): 4.4178e+03 5.9105e+03 1.7671e+04 8.5182e+04 3.4073e+05 1.6800e+08
#include <cmath>
#include <cstdio>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/msa/static_analysis.hpp"

int main() {
  using namespace kinestat;

  // 1. The model (Pinocchio's Model): nodes, a material, a section, a beam, a support, a load
  //    case. SI units throughout: m, N, Pa, rad. add_* return the index of what they added.
  const double L = 1.0, P = 1000.0, E = 210e9;
  msa::Structure s;
  s.set_title("ex1: steel cantilever, 20 x 40 mm, 1 m");
  const int root = s.add_node("root", Vec3(0, 0, 0));
  const int tip = s.add_node("tip", Vec3(L, 0, 0));
  const int steel = s.add_material(Material::from_E_nu("steel", E, 0.3));
  // rectangle_section(b, h): b along the beam's local y, h along local z. For a beam along global x
  // the default orientation makes local y = global y and local z = global z, so h = 40 mm is the
  // height that resists the vertical load: I = Iy = b h^3 / 12.
  const int bar = s.add_section(rectangle_section(0.02, 0.04));
  s.add_beam({.id = "arm", .node1 = root, .node2 = tip, .material = steel, .section = bar});
  s.add_support({.node = root});  // default: all six dofs of the node fixed (a clamp)
  s.add_load_case({.name = "tip down", .loads = {{.node = tip, .wrench = Vec6(0, 0, -P, 0, 0, 0)}}});
  s.set_report_node(tip);  // the node whose 6x6 Cartesian stiffness the solve reports

  // 2. Solve (msa::Solution is Pinocchio's Data: what one solve produced). The structure is
  //    validated first; a singular structure would give status kSingular and a diagnosis in words.
  const msa::Solution sol = msa::solve(s);
  if (!sol.status.ok()) {
    std::fprintf(stderr, "ex1: %s\n", sol.status.message().c_str());
    return 1;
  }

  // 3. Compare with beam theory. Displacements are per node: ux uy uz (m), rx ry rz (rad).
  const msa::LoadCaseResult& down = sol.cases[0];
  const double uz = down.displacement[tip](2);
  const double I = s.sections()[bar].Iy;
  const double theory = -P * L * L * L / (3 * E * I);
  const double difference = std::abs(uz - theory) / std::abs(theory);
  std::printf("tip deflection uz = %.6e m, beam theory P L^3 / (3 E I) = %.6e m (relative difference %.1e)\n", uz,
              theory, difference);
  // Reactions: the force and moment the support applies to the structure (N, N m, global axes).
  const Vec6& R = down.reaction[root];
  std::printf("clamp reaction Fz = %.3f N, My = %.3f N m (the load and its moment about the root)\n\n", R(2), R(4));

  // 4. The 6x6 Cartesian stiffness of the report node (static condensation onto its dofs), as
  //    kinestat::CartesianStiffness: stiffness, compliance, indices, lost directions, with units.
  if (sol.cartesian)
    std::printf("%s", cartesian_stiffness_report(*sol.cartesian, "Cartesian stiffness of the tip").c_str());
  return difference <= 1e-9 ? 0 : 1;
}
