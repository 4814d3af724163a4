// kinestat example 3: a VJM chain whose link spring comes from the FEA of the link's mesh.
//
// Run: build/examples/ex3_vjm_fea_link [MESH]      (default meshes/bar.off, run from the source folder)
//
// The virtual joint method (Pashkevich, Klimchik, Chablat, Wenger 2009) models a robot leg as rigid
// links with 6-dof virtual springs; the spring of a link is its 6x6 stiffness at the far end with
// the near end clamped. Here that 6x6 comes from a finite-element analysis of the link's solid:
//   1. fea::compute_link_stiffness meshes meshes/bar.off (a 200 x 20 x 30 mm steel bar, x along
//      the bar) with quadratic tetrahedra of 10 mm (coarse: it runs in seconds), clamps the face
//      x = 0, couples the face x = 200 mm rigidly to a reference point at its centre, and returns the
//      6x6 of that point (the same function behind `kinestat link-stiffness` and model files' `fea:`).
//   2. A one-leg chain: an actuated revolute joint about z at the base (actuator stiffness
//      k_a = 1e4 N m/rad), the rigid link (translate 200 mm along x), the FEA spring at its end.
//   3. The chain's Cartesian stiffness at the tool (the link's end), unloaded (eq. 9-10).
// Checks (exit status 1 when one fails): the FEA's axial stiffness is EA/L within 2 % (the clamped
// faces stiffen the solid slightly); the chain's compliance is the spring's plus the actuator's,
// C = C_fea + J_a J_a^T / k_a with J_a = (0, L, 0, 0, 0, 1) the tool twist of the actuator (springs
// in series add compliances), to 1e-9.
//
// Expected output (the mesh is CGAL's, with a fixed seed; the last digits, and the small off-diagonal
// entries that an unsymmetric mesh of a symmetric bar gives, may vary with the CGAL version):
//   link: meshes/bar.off, 1875 nodes, 883 elements, 5289 dofs (10-node tetrahedra, 10 mm)
//   axial stiffness 6.3548e+08 N/m, EA/L = 6.3000e+08 N/m (ratio 1.0087)
//   chain compliance = C_fea + J_a J_a^T / k_a to 3.0e-16 (relative)
//
//   Cartesian stiffness (one leg, unloaded): point (0.2, 0, 0) m, global axes; dofs ux uy uz rx ry rz
//     stiffness K [N/m, N/rad (rows ux uy uz); N, N m/rad (rows rx ry rz)]
//                       ux          uy          uz          rx          ry          rz
//         ux    6.3548e+08  3.4785e+02  4.0349e+03 -7.3660e+01  8.6330e+01 -6.3596e+01
//         uy    3.4785e+02  2.0825e+06 -1.1173e+02  3.4614e+01 -1.4799e+01 -3.4973e+05
//         uz    4.0349e+03 -1.1173e+02  1.3516e+07 -2.2762e+01  1.3518e+06  2.4041e+01
//         rx   -7.3660e+01  3.4614e+01 -2.2762e+01  1.9842e+04 -3.1916e+00 -5.7535e+00
//         ry    8.6330e+01 -1.4799e+01  1.3518e+06 -3.1916e+00  1.8275e+05  2.9367e+00
//         rz   -6.3596e+01 -3.4973e+05  2.4041e+01 -5.7535e+00  2.9367e+00  6.5523e+04
//     compliance C = K^-1 [m/N, m/(N m) (rows ux uy uz); rad/N, rad/(N m) (rows rx ry rz)]
//                       ux          uy          uz          rx          ry          rz
//         ux    1.5736e-09 -6.1385e-14 -1.5193e-12  5.8420e-12  1.0494e-11  1.2003e-12
//         uy   -6.1385e-14  4.6317e-06 -1.3305e-11 -9.1162e-10  7.6214e-11  2.4721e-05
//         uz   -1.5193e-12 -1.3305e-11  2.8427e-07 -1.2119e-11 -2.1027e-06 -8.1079e-11
//         rx    5.8420e-12 -9.1162e-10 -1.2119e-11  5.0397e-05  9.6973e-10 -4.4040e-10
//         ry    1.0494e-11  7.6214e-11 -2.1027e-06  9.6973e-10  2.1025e-05  2.3604e-10
//         rz    1.2003e-12  2.4721e-05 -8.1079e-11 -4.4040e-10  2.3604e-10  1.4721e-04
//     indices of K:
//       size 6x6, symmetry error 0.0e+00
//       determinant       1.1468e+35 (sign 1, log10|det| = 35.0595)
//       trace             6.5135e+08
//       1-norm            6.3549e+08
//       2-norm            6.3548e+08
//       Frobenius norm    6.3563e+08
//       inf-norm (rows)   6.3549e+08
//       max |k_ij|        6.3548e+08
//       condition number  9.6195e+04
//     eigenvalues of K (SI, mixed units): 6.6062e+03 1.9842e+04 4.7090e+04 2.1415e+06 1.3652e+07 6.3548e+08
#include <cmath>
#include <cstdio>
#include <string>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/vjm/chain.hpp"
#include "kinestat/vjm/stiffness.hpp"

int main(int argc, char** argv) {
  using namespace kinestat;
  const double L = 0.2, E = 210e9, A = 0.02 * 0.03;  // m, Pa, m^2: the bar of meshes/bar.off

  // 1. The link's 6x6 by FEA. Regions and sizes are in metres; the mesh file is in mm.
  fea::LinkStiffnessRequest request;
  request.mesh_file = argc > 1 ? argv[1] : "meshes/bar.off";
  request.unit_scale = 1e-3;
  request.mesh_size = 0.010;
  request.material = Material::from_E_nu("steel", E, 0.3);
  request.options.clamp = fea::Region::plane(Vec3(0, 0, 0), Vec3::UnitX());
  request.options.reference = fea::Region::plane(Vec3(L, 0, 0), Vec3::UnitX());
  request.options.reference_point = Vec3(L, 0, 0);
  StatusOr<fea::LinkStiffnessRun> run = fea::compute_link_stiffness(request);
  if (!run.ok()) {
    std::fprintf(stderr, "ex3: %s\n", run.status().message().c_str());
    return 1;
  }
  const fea::LinkStiffness& link = run->result;
  std::printf("link: %s, %d nodes, %d elements, %d dofs (%d-node tetrahedra, %g mm)\n", request.mesh_file.c_str(),
              link.num_nodes, link.num_elements, link.num_dofs, link.nodes_per_element, run->mesh_size * 1e3);
  const double axial = link.cartesian.stiffness(0, 0);
  std::printf("axial stiffness %.4e N/m, EA/L = %.4e N/m (ratio %.4f)\n", axial, E * A / L, axial / (E * A / L));

  // 2. The chain of eq. (1): base -> actuated joint (with its virtual spring) -> rigid link -> the
  //    link's 6-dof virtual spring. The FEA's axes are the mesh's, which here are the chain's
  //    current axes at the link's end, and its reference point is that frame's origin.
  const double k_a = 1e4;  // N m/rad
  vjm::Chain leg("one leg");
  leg.add_actuator(vjm::JointType::kRevolute, Vec3::UnitZ(), 0.0, k_a, "base motor");
  leg.add_translation(Vec3(L, 0, 0), "link");
  leg.add_spring(link.cartesian.stiffness, "link spring (FEA)");

  // 3. Its Cartesian stiffness at the tool: a kinestat::CartesianStiffness, as MSA and FEA give.
  StatusOr<CartesianStiffness> K = vjm::unloaded_stiffness(leg);
  if (!K.ok() || !K->compliance_defined) {
    std::fprintf(stderr, "ex3: %s\n", K.ok() ? K->status.message().c_str() : K.status().message().c_str());
    return 1;
  }
  Vec6 Ja;
  Ja << 0, L, 0, 0, 0, 1;  // tool twist per unit actuator rotation: v = e_z x (L, 0, 0), omega = e_z
  const Mat6 expected = link.cartesian.compliance + Ja * Ja.transpose() / k_a;
  const double series_error = (K->compliance - expected).norm() / expected.norm();
  std::printf("chain compliance = C_fea + J_a J_a^T / k_a to %.1e (relative)\n\n", series_error);
  std::printf("%s", cartesian_stiffness_report(*K, "Cartesian stiffness (one leg, unloaded)").c_str());

  const bool axial_ok = std::abs(axial / (E * A / L) - 1.0) <= 0.02;
  return axial_ok && series_error <= 1e-9 ? 0 : 1;
}
