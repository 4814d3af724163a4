// A Solution is read only with the structure it was solved for: check_solution_matches and
// full_report refuse another one (they used to index the solution's arrays by the other structure's
// nodes and read past their end).
#include <gtest/gtest.h>

#include <string>

#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {
namespace {

// "n3": appended, because GCC 12 warns falsely (-Wrestrict) about "n" + std::string&&.
std::string id(char prefix, int i) {
  std::string s(1, prefix);
  s += std::to_string(i);
  return s;
}

// A steel cantilever of `n` beams along x, fixed at node 0, loaded at its tip, reported there.
Structure cantilever(int n) {
  Structure s;
  s.add_node("n0", Vec3::Zero());
  const int m = s.add_material(Material::from_E_nu("steel", 210e9, 0.3));
  const int c = s.add_section(circle_section(0.02));
  for (int i = 1; i <= n; ++i) {
    s.add_node(id('n', i), Vec3(0.5 * i, 0, 0));
    Beam b;
    b.id = id('b', i);
    b.node1 = i - 1;
    b.node2 = i;
    b.material = m;
    b.section = c;
    s.add_beam(b);
  }
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case({"tip", {{n, (Vec6() << 0, 0, -1000, 0, 0, 0).finished()}}, {}});
  s.set_report_node(n);
  return s;
}

TEST(SolutionMatches, SolveRecordsItsStructure) {
  const Structure s = cantilever(2);
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  ASSERT_TRUE(sol.structure.has_value());
  EXPECT_EQ(sol.structure->nodes, 3);
  EXPECT_EQ(sol.structure->beams, 2);
  EXPECT_EQ(sol.structure->joints, 0);
  EXPECT_EQ(sol.structure->load_cases, 1);
  EXPECT_TRUE(check_solution_matches(s, sol).ok());
  EXPECT_TRUE(full_report(s, sol).ok());
}

TEST(SolutionMatches, AnotherStructureIsRefusedByTheReport) {
  const Solution small = solve(cantilever(2));
  ASSERT_TRUE(small.status.ok()) << small.status.message();
  // The larger structure's report node (3) is past the end of the small solution's 3 displacements.
  const StatusOr<std::string> report = full_report(cantilever(3), small);
  ASSERT_EQ(report.status().code(), StatusCode::kInvalidInput);
  const std::string& msg = report.status().message();
  EXPECT_NE(msg.find("solved for (3 nodes, 2 beams"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the structure's 4 nodes, 3 beams"), std::string::npos) << msg;
}

TEST(SolutionMatches, HandMadeSolutionIsCheckedByItsArrays) {
  const Structure s = cantilever(2);
  Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  sol.structure.reset();  // as a Solution built by hand: only the arrays tell
  EXPECT_TRUE(check_solution_matches(s, sol).ok());
  sol.cases[0].beam_end_forces.pop_back();
  const Status st = check_solution_matches(s, sol);
  ASSERT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_NE(st.message().find("load case 'tip': its 3 displacements, 3 reactions, 1 beam"), std::string::npos)
      << st.message();
}

}  // namespace
}  // namespace kinestat::msa
