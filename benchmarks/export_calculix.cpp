// Writes bench_fea's structured quadratic-tet bar as a CalculiX input deck (.inp), so that
// scripts/bench_calculix.sh can time `ccx` on exactly the mesh kinestat factorizes. With --solve it
// also prints kinestat's six tip displacements (compliance diagonal) for the check against ccx.
//
// The problem: steel bar 200 x 20 x 30 mm (E = 210 GPa, nu = 0.3), x = 0 face clamped, x = 0.2 m
// face tied to a reference node at (0.2, 0, 0) by *RIGID BODY (the linear rigid coupling of
// fea::make_dof_map), six unit loads (1 N along x, y, z; 1 N m about x, y, z) on that node, one
// *STEP each: ccx has no multi-right-hand-side static step, so it assembles and factors six times.
#include <cstdio>
#include <string>
#include <system_error>

#include <fmt/format.h>
#include <fmt/os.h>
#include <CLI/CLI.hpp>

#include "bar_mesh.hpp"
#include "fea/elasticity_assembly.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"

namespace {

using namespace kinestat;

constexpr double kLength = 0.2;          // m
constexpr double kE = 210e9, kNu = 0.3;  // Pa, -

// ccx reads at most 20 characters per number: 14 significant digits fit ("-1.2345678901234e-19").
constexpr const char* kNodeLine = "{}, {:.14g}, {:.14g}, {:.14g}\n";

// One *NSET line holds at most 16 entries in Abaqus/CalculiX syntax.
void write_node_set(fmt::ostream& out, const char* name, const std::vector<int>& nodes) {
  out.print("*NSET, NSET={}\n", name);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    out.print("{}{}", nodes[i] + 1, (i + 1) % 16 == 0 || i + 1 == nodes.size() ? ",\n" : ", ");
}

// kinestat's node order (VTK_QUADRATIC_TETRA: vertices, then edges 01 12 20 03 13 23) is the
// Abaqus/CalculiX C3D10 order (vertices, then edges 1-2 2-3 3-1 1-4 2-4 3-4), so nodes are written
// as they are, 1-based. Node N+1 is the rigid body's reference node (translations), N+2 its
// rotation node (its dofs 1-3 are the rotations). An element is one line: ccx 2.20
// rejected the two-line form ("element ... is already defined").
void write_deck(const fea::TetMesh& mesh, const std::vector<int>& clamped, const std::vector<int>& tip,
                const std::string& path) {
  auto out = fmt::output_file(path);
  const int ref = mesh.num_nodes() + 1, rot = mesh.num_nodes() + 2;
  out.print("** kinestat bench_fea bar: {} nodes, {} C3D10 elements. Units: m, N, Pa.\n", mesh.num_nodes(),
            mesh.num_elements());
  out.print("*NODE, NSET=NALL\n");
  for (int i = 0; i < mesh.num_nodes(); ++i)
    out.print(kNodeLine, i + 1, mesh.nodes[i].x(), mesh.nodes[i].y(), mesh.nodes[i].z());
  out.print("{}, {}, 0, 0\n{}, {}, 0, 0\n", ref, kLength, rot, kLength);
  out.print("*ELEMENT, TYPE=C3D10, ELSET=EALL\n");
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* v = mesh.element(e);
    out.print("{}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}\n", e + 1, v[0] + 1, v[1] + 1, v[2] + 1, v[3] + 1, v[4] + 1,
              v[5] + 1, v[6] + 1, v[7] + 1, v[8] + 1, v[9] + 1);
  }
  write_node_set(out, "FIX", clamped);
  write_node_set(out, "TIP", tip);
  out.print("*NSET, NSET=REFS\n{}, {}\n", ref, rot);
  out.print("*MATERIAL, NAME=STEEL\n*ELASTIC\n{}, {}\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n", kE, kNu);
  out.print("*BOUNDARY\nFIX, 1, 3\n*RIGID BODY, NSET=TIP, REF NODE={}, ROT NODE={}\n", ref, rot);
  const char* names[6] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  for (int c = 0; c < 6; ++c) {
    out.print("*STEP\n*STATIC\n** load case {}: unit {} on the reference node\n*CLOAD, OP=NEW\n{}, {}, 1.0\n", c + 1,
              names[c], c < 3 ? ref : rot, c % 3 + 1);
    out.print("*NODE PRINT, NSET=REFS\nU\n*END STEP\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Write bench_fea's quadratic-tet bar as a CalculiX .inp (six load-case steps)"};
  int n = 6;
  std::string path;
  bool solve = false;
  app.add_option("-n,--cells", n, "cells across the 20 mm side, as in bench_fea (6: 88k dofs, 9: 296k)")
      ->check(CLI::Range(1, 20));
  app.add_option("output", path, "the .inp file to write")->required();
  app.add_flag("--solve", solve, "also solve with kinestat and print the six tip displacements");
  CLI11_PARSE(app, argc, argv);

  const fea::TetMesh mesh = bench::bar(n);
  const auto clamped = fea::select_nodes(mesh, fea::Region::plane(Vec3::Zero(), Vec3::UnitX()));
  const auto tip = fea::select_nodes(mesh, fea::Region::plane(Vec3(kLength, 0, 0), Vec3::UnitX()));
  try {
    write_deck(mesh, clamped, tip, path);
  } catch (const std::system_error& e) {  // fmt::output_file reports an unwritable path this way
    std::fprintf(stderr, "cannot write %s: %s\n", path.c_str(), e.what());
    return 1;
  }
  const fea::DofMap map = fea::make_dof_map(mesh, clamped, tip, Vec3(kLength, 0, 0));
  fmt::print("{}: {} nodes, {} elements, {} dofs (kinestat, clamped face removed)\n", path, mesh.num_nodes(),
             mesh.num_elements(), map.num_dofs);
  if (!solve) return 0;

  const Material steel = Material::from_E_nu("steel", kE, kNu);
  solver::SparseMatrix K;
  const bool assembled = fea::assemble_stiffness(mesh, {fea::elasticity_matrix(steel)}, {}, map, &K).ok();
  auto chol = solver::make_sparse_cholesky();
  solver::FactorizationReport report;
  if (!assembled || !chol->Factorize(K, &report).ok()) {
    std::fprintf(stderr, "kinestat assembly or factorization failed\n");
    return 1;
  }
  MatX F = MatX::Zero(map.num_dofs, 6), X;
  F.middleRows<6>(map.reference_dof).setIdentity();
  if (!chol->Solve(F, &X).ok()) return 1;
  // Tip displacement along each unit load = the diagonal of the 6x6 compliance.
  fmt::print("kinestat compliance diagonal (m/N x3, rad/(N m) x3): {:.6e} {:.6e} {:.6e} {:.6e} {:.6e} {:.6e}\n",
             X(map.reference_dof, 0), X(map.reference_dof + 1, 1), X(map.reference_dof + 2, 2),
             X(map.reference_dof + 3, 3), X(map.reference_dof + 4, 4), X(map.reference_dof + 5, 5));
  return 0;
}
