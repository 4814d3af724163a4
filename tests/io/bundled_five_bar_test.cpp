// models/five_bar.yaml (the demo's default model) is the same structure as the C++ builder of
// mechanisms/five_bar: two independent routes to one answer, and the paper's Table 1 row 14.
#include <gtest/gtest.h>

#include "kinestat/core/units.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat {
namespace {

TEST(BundledFiveBar, FileEqualsBuilderAndTable1Row14) {
  auto file = io::read_structure_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/five_bar.yaml");
  ASSERT_TRUE(file.ok()) << file.status().message();
  constexpr double deg = units::kDeg;
  const mechanisms::FiveBarParams paper;  // the paper's section-5 values
  auto built = mechanisms::make_five_bar_structure(paper, 64 * deg, 75 * deg, mechanisms::Assembly::kUp);
  ASSERT_TRUE(built.ok());
  const msa::Solution a = msa::solve(*file), b = msa::solve(*built);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  ASSERT_TRUE(a.cartesian && b.cartesian);
  // Node coordinates in the file carry 12 digits: the 6x6 compliances agree to ~1e-9.
  EXPECT_LT((a.cartesian->compliance - b.cartesian->compliance).norm(), 1e-8 * b.cartesian->compliance.norm());
  // Table 1, row 14 (theta1 = 64, theta2 = 75 deg): node 5 under Fx = 1 N and Fy = 1 N.
  const int p = *file->find_node("5");
  EXPECT_NEAR(a.cases[0].displacement[p](0), 2.3946e-5, 1e-4 * 2.3946e-5);
  EXPECT_NEAR(a.cases[0].displacement[p](1), -2.5246e-5, 1e-4 * 2.5246e-5);
  EXPECT_NEAR(a.cases[1].displacement[p](0), -2.5246e-5, 1e-4 * 2.5246e-5);
  EXPECT_NEAR(a.cases[1].displacement[p](1), 1.0635e-4, 1e-4 * 1.0635e-4);
}

}  // namespace
}  // namespace kinestat
