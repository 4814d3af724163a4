// A link whose Cholesky factor would not fit is refused after the analysis with what would fit; the
// estimate against the factor CHOLMOD then computes on a small mesh.
#include <gtest/gtest.h>

#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {
namespace {

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);

LinkStiffnessOptions bar_options() {
  LinkStiffnessOptions o;
  o.clamp = Region::plane(Vec3::Zero(), Vec3::UnitX());
  o.reference = Region::plane(Vec3(0.2, 0, 0), Vec3::UnitX());
  return o;
}

// 200 x 20 x 30 mm, 10-node tetrahedra of ~10 mm: 4101 dofs.
TetMesh bar() { return to_quadratic(make_box_mesh(Vec3(0, -0.01, -0.015), Vec3(0.2, 0.01, 0.015), 20, 2, 3)); }

TEST(LinkStiffnessMemory, EstimateCoversTheFactorOfASmallMesh) {
  LinkStiffnessOptions o = bar_options();
  std::vector<std::string> stages;
  o.progress = [&stages](const std::string& s) { stages.push_back(s); };
  auto r = link_stiffness(bar(), kSteel, o);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const double values = 8.0 * static_cast<double>(r->factorization.nnz_factor);  // measured nnz(L)
  EXPECT_GT(r->factorization.factor_bytes, values);
  EXPECT_LT(r->factorization.factor_bytes, 2.5 * values);
  // Progress: assembly, analysis, the factorization with its flops (from the solver), the solves.
  bool announced = false;
  for (const auto& s : stages) announced = announced || s.find("Gflop") != std::string::npos;
  EXPECT_TRUE(announced);
}

TEST(LinkStiffnessMemory, RefusedWithTheEstimateTheMemoryAMeshSizeAndTheDistributedBackend) {
  LinkStiffnessOptions o = bar_options();
  o.solver.memory_limit_bytes = 1e6;  // injected: 1 MB available
  auto r = link_stiffness(bar(), kSteel, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  const std::string& m = r.status().message();
  EXPECT_NE(m.find("above the limit of 0.001"), std::string::npos) << m;  // the memory available, GB
  EXPECT_NE(m.find("--size"), std::string::npos) << m;
  EXPECT_NE(m.find("--solver petsc"), std::string::npos) << m;
}

}  // namespace
}  // namespace kinestat::fea
