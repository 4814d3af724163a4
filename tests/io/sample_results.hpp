// A small structure and a hand-made Solution with distinct, known numbers, so the JSON and VTK
// writers can be checked field by field independently of the solver.
#pragma once

#include <cmath>
#include <limits>
#include <string>

#include "kinestat/elements/section.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::io_test {

// Nodes A (0,0,0), B (1,0,0), B2 (1,0,0), C (1,0.5,0); beam A-B, joint B-B2 (coincident nodes),
// rigid link B2 -> C; A clamped; the two load cases of sample_solution (without loads: the writers
// read the loads' results from the solution, and check_solution_matches counts the cases).
inline msa::Structure sample_structure() {
  msa::Structure s;
  s.set_title("sample");
  s.add_node("A", Vec3(0, 0, 0));
  s.add_node("B", Vec3(1, 0, 0));
  s.add_node("B2", Vec3(1, 0, 0));
  s.add_node("C", Vec3(1, 0.5, 0));
  s.add_material(Material::from_E_nu("steel", 210e9, 0.3));
  Section sec = circle_section(0.02);
  sec.id = "rod";
  s.add_section(sec);
  msa::Beam b;
  b.id = "arm";
  b.node1 = 0;
  b.node2 = 1;
  b.material = 0;
  b.section = 0;
  s.add_beam(b);
  msa::Joint j;
  j.id = "hinge";
  j.node1 = 1;
  j.node2 = 2;
  j.stiffness << 1e8, 1e8, 1e8, 1e4, 1e4, 0.0;
  s.add_joint(j);
  msa::RigidLink r;
  r.id = "offset";
  r.master = 2;
  r.slave = 3;
  s.add_rigid_link(r);
  s.add_support({0, msa::kAllDofs, Mat3::Identity()});
  s.set_report_node(3);
  s.add_load_case({"first", {}, {}});
  s.add_load_case({"second <&>", {}, {}});
  return s;
}

// Displacement component k of node n in load case c.
inline double sample_displacement(int c, int n, int k) { return (c + 1) * 1e-3 * (n + 1) + 1e-4 * k; }

inline Vec12 sample_end_forces() {
  Vec12 f;
  f << -10, 1, 2, 3, -4, 5, 10, -1, -2, -3, 6, -7;
  return f;
}

// Two load cases, a Cartesian stiffness whose indices hold an infinite condition number and a
// NaN determinant (to exercise the non-finite encoding).
inline msa::Solution sample_solution() {
  msa::Solution sol;
  sol.num_dofs = 24;
  sol.num_free_dofs = 12;
  sol.backend = "test backend";
  sol.factorization.n = 12;
  sol.factorization.nnz_matrix = 40;
  sol.factorization.nnz_factor = 55;
  sol.factorization.ordering = "AMD";
  sol.factorization.reused_symbolic = true;
  sol.assembly_seconds = 0.25;
  for (int c = 0; c < 2; ++c) {
    msa::LoadCaseResult r;
    r.name = c == 0 ? "first" : "second <&>";
    for (int n = 0; n < 4; ++n) {
      Vec6 d;
      for (int k = 0; k < 6; ++k) d(k) = sample_displacement(c, n, k);
      r.displacement.push_back(d);
      r.reaction.push_back(n == 0 ? Vec6(-1, -2, -3, -4, -5, -6 - c) : Vec6(Vec6::Zero()));
    }
    r.beam_end_forces.push_back(sample_end_forces() * (c + 1));
    r.joint_forces.push_back(Vec6(0.5, 1.5, 2.5, 3.5, 4.5, 5.5 + c));
    r.resultant = Vec6(1e-12, 0, 0, 0, 0, 2e-12);
    r.equilibrium_error = 3e-15;
    r.max_translation = 0.125;
    r.max_translation_node = 3;
    sol.cases.push_back(r);
  }
  CartesianStiffness cs;  // of the report node (sample_structure: node 3)
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) cs.compliance(i, j) = 1.0 / (1 + i + j);  // Hilbert: symmetric
  }
  cs.stiffness = cs.compliance.inverse();
  cs.stiffness_defined = true;
  StiffnessIndices& ix = cs.indices.emplace();
  ix.size = 6;
  ix.trace = 42.0;
  ix.condition_number = std::numeric_limits<double>::infinity();
  ix.determinant = std::numeric_limits<double>::quiet_NaN();
  ix.eigenvalues = VecX::LinSpaced(6, 1.0, 6.0);
  ix.eigenvectors = MatX::Identity(6, 6);
  ix.eigenvectors(0, 1) = 0.25;
  sol.cartesian = cs;
  return sol;
}

// A singular solution: no cases, one free motion (node C swings along y, rotating about z).
inline msa::Solution sample_singular_solution() {
  msa::Solution sol;
  sol.status = Status::Singular("the structure is a mechanism");
  sol.singularity.singular = true;
  sol.singularity.message = "node 'C' moves freely";
  sol.singularity.weak_dofs.push_back({2, 5});
  msa::FreeMotion m;
  m.node_motion.assign(4, Vec6::Zero());
  m.node_motion[2](5) = 1.0;
  m.node_motion[3] << -0.5, 0, 0, 0, 0, 1.0;  // theta z x (0, 0.5, 0) for theta = 1
  m.rayleigh_ratio = 1e-17;
  m.description = "C rotates about z";
  sol.singularity.modes.push_back(m);
  return sol;
}

}  // namespace kinestat::io_test
