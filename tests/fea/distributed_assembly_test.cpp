// The distributed assembly (docs/fea.md, "Large meshes") on one process: element ranges that cover
// the mesh once, and a link stiffness assembled as two element halves whose sum the backend forms
// (LinearSolver::FactorizeSum) giving the 6x6 of the whole stiffness factorized at once.
// tests/mpi/ runs the same path on two MPI ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "fea/elasticity_assembly.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"

namespace kinestat::fea {
namespace {

TEST(ElementRange, CoversEveryElementOnceInBalancedRanges) {
  for (int ranks : {1, 2, 3, 7}) {
    int next = 0;
    for (int r = 0; r < ranks; ++r) {
      const auto [first, last] = element_range(100, r, ranks);
      EXPECT_EQ(first, next);
      EXPECT_LE(std::abs((last - first) - 100 / ranks), 1) << ranks << " ranks, rank " << r;
      next = last;
    }
    EXPECT_EQ(next, 100);
  }
}

// x of the centre of element e's vertices.
double element_centre_x(const TetMesh& mesh, int e) {
  double x = 0.0;
  for (int a = 0; a < 4; ++a) x += mesh.nodes[mesh.element(e)[a]].x();
  return x / 4.0;
}

// The 6x6 compliance of the reference dofs of `map` from the summands of its reduced stiffness.
Mat6 compliance(solver::Backend backend, const std::vector<solver::SparseMatrix>& summands, const DofMap& map,
                solver::FactorizationReport* report) {
  auto solver = solver::make_linear_solver({.backend = backend});
  const Status s = solver->FactorizeSum(summands, report);
  EXPECT_TRUE(s.ok()) << s.message();
  MatX F = MatX::Zero(map.num_dofs, 6), X;
  F.middleRows<6>(map.reference_dof).setIdentity();
  EXPECT_TRUE(solver->Solve(F, &X).ok());
  return X.middleRows<6>(map.reference_dof);
}

TEST(DistributedAssembly, TwoElementHalvesAddedByTheBackendGiveTheWholeStiffnesssCompliance) {
  // Steel bar 200 x 20 x 30 mm, 10-node tetrahedra, clamped at x = 0, rigid coupling at x = 200 mm.
  const TetMesh mesh = to_quadratic(make_box_mesh(Vec3(0, -0.01, -0.015), Vec3(0.2, 0.01, 0.015), 10, 2, 3));
  const std::vector<int> clamped = select_nodes(mesh, Region::plane(Vec3::Zero(), Vec3::UnitX()));
  const std::vector<int> coupled = select_nodes(mesh, Region::plane(Vec3(0.2, 0, 0), Vec3::UnitX()));
  const DofMap map = make_dof_map(mesh, clamped, coupled, Vec3(0.2, 0, 0));
  const std::vector<Mat6> D = {elasticity_matrix(Material::from_E_nu("steel", 210e9, 0.3))};
  const int elements = mesh.num_elements();
  solver::SparseMatrix whole, first, second;
  ASSERT_TRUE(assemble_stiffness(mesh, D, {}, map, &whole).ok());
  // The two slabs of elements along the bar's axis (x), as two ranks assemble them.
  const std::vector<int> order = elements_along_longest_axis(mesh);
  const int half = element_range(elements, 0, 2).second;
  for (int k = 1; k < elements; ++k) ASSERT_LE(element_centre_x(mesh, order[k - 1]), element_centre_x(mesh, order[k]));
  ASSERT_TRUE(assemble_stiffness(mesh, D, {}, map, &first, std::span(order).first(half)).ok());
  ASSERT_TRUE(assemble_stiffness(mesh, D, {}, map, &second, std::span(order).subspan(half)).ok());
  // Each half holds part of the matrix only; the halves share the entries of their common nodes.
  EXPECT_LT(first.nonZeros(), whole.nonZeros());
  EXPECT_LT(second.nonZeros(), whole.nonZeros());
  EXPECT_GT(first.nonZeros() + second.nonZeros(), whole.nonZeros());
  // Slabs overlap on their common face only: a few % of the entries at 10 cells along x.
  EXPECT_LT(first.nonZeros() + second.nonZeros(), 1.2 * whole.nonZeros());

  solver::FactorizationReport report;
  const Mat6 C = compliance(solver::Backend::kCholmod, {whole}, map, &report);
  for (solver::Backend b : solver::available_backends()) {
    if (b == solver::Backend::kPetscCg) continue;  // iterative: its tolerance, not 1e-9 (tests/mpi)
    SCOPED_TRACE(solver::backend_name(b));
    const Mat6 C_sum = compliance(b, {first, second}, map, &report);
    // The sum has the whole matrix's pattern: its stored lower-triangle entries are the same.
    EXPECT_EQ(report.nnz_matrix, whole.nonZeros());
    double worst = 0.0;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        worst = std::max(worst, std::abs(C_sum(i, j) - C(i, j)) / std::sqrt(C(i, i) * C(j, j)));
    EXPECT_LT(worst, 1e-9);
  }
}

}  // namespace
}  // namespace kinestat::fea
