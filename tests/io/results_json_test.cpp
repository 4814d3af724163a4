// solution_to_json carries every number of a hand-made Solution to the documented place, encodes
// non-finite numbers as null with a note, and write_json round-trips through a file.
#include "kinestat/io/results_json.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "kinestat/io/structure_yaml.hpp"
#include "sample_results.hpp"

namespace kinestat::io {
namespace {

using io_test::sample_displacement;
using nlohmann::json;

TEST(ResultsJson, HeaderModelAndSolver) {
  const json j = *solution_to_json(io_test::sample_structure(), io_test::sample_solution());
  EXPECT_EQ(j["schema"], "kinestat-msa-results");
  EXPECT_EQ(j["schema_version"], kResultsSchemaVersion);
  EXPECT_EQ(j["units"]["length"], "m");
  EXPECT_EQ(j["model"]["title"], "sample");
  EXPECT_EQ(j["model"]["num_nodes"], 4);
  EXPECT_EQ(j["model"]["num_beams"], 1);
  EXPECT_EQ(j["model"]["num_joints"], 1);
  EXPECT_EQ(j["model"]["num_rigid_links"], 1);
  EXPECT_EQ(j["model"]["num_dofs"], 24);
  EXPECT_EQ(j["model"]["num_free_dofs"], 12);
  EXPECT_EQ(j["model"]["report_node"], "C");
  EXPECT_EQ(j["status"]["code"], "ok");
  EXPECT_EQ(j["solver"]["backend"], "test backend");
  EXPECT_EQ(j["solver"]["assembly_seconds"], 0.25);
  EXPECT_EQ(j["solver"]["factorization"]["ordering"], "AMD");
  EXPECT_EQ(j["solver"]["factorization"]["nnz_factor"], 55);
  EXPECT_EQ(j["solver"]["factorization"]["reused_symbolic"], true);
  EXPECT_TRUE(j["global_indices"].is_null());
}

TEST(ResultsJson, LoadCaseFields) {
  const json j = *solution_to_json(io_test::sample_structure(), io_test::sample_solution());
  ASSERT_EQ(j["load_cases"].size(), 2u);
  const json& c = j["load_cases"][1];
  EXPECT_EQ(c["name"], "second <&>");
  ASSERT_EQ(c["displacements"].size(), 4u);
  for (int n = 0; n < 4; ++n) {
    const json& d = c["displacements"][n];
    EXPECT_EQ(d["node"], std::string(n == 0 ? "A" : n == 1 ? "B" : n == 2 ? "B2" : "C"));
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(d["translation"][k], sample_displacement(1, n, k));
      EXPECT_EQ(d["rotation"][k], sample_displacement(1, n, k + 3));
    }
  }
  // Only the supported node A has a reaction entry.
  ASSERT_EQ(c["reactions"].size(), 1u);
  EXPECT_EQ(c["reactions"][0]["node"], "A");
  EXPECT_EQ(c["reactions"][0]["force"], json({-1.0, -2.0, -3.0}));
  EXPECT_EQ(c["reactions"][0]["moment"], json({-4.0, -5.0, -7.0}));
  // End forces: case 2 is twice the sample vector, named per end.
  const Vec12 f = io_test::sample_end_forces() * 2;
  const json& b = c["beam_end_forces"][0];
  EXPECT_EQ(b["beam"], "arm");
  EXPECT_EQ(b["end1"]["N"], f(0));
  EXPECT_EQ(b["end1"]["Mz"], f(5));
  EXPECT_EQ(b["end2"]["N"], f(6));
  EXPECT_EQ(b["end2"]["T"], f(9));
  EXPECT_EQ(b["end2"]["Mz"], f(11));
  EXPECT_EQ(c["joint_forces"][0]["joint"], "hinge");
  EXPECT_EQ(c["joint_forces"][0]["moment"], json({3.5, 4.5, 6.5}));
  EXPECT_EQ(c["equilibrium"]["resultant_moment"][2], 2e-12);
  EXPECT_EQ(c["equilibrium"]["error"], 3e-15);
  EXPECT_EQ(c["max_translation"]["node"], "C");
  EXPECT_EQ(c["max_translation"]["value"], 0.125);
}

TEST(ResultsJson, CartesianStiffnessWithUnitsAndIndices) {
  const msa::Solution sol = io_test::sample_solution();
  const json j = *solution_to_json(io_test::sample_structure(), sol);
  const json& cs = j["cartesian_stiffness"];
  EXPECT_EQ(cs["node"], "C");
  EXPECT_EQ(cs["stiffness_defined"], true);
  for (int r = 0; r < 6; ++r) {
    for (int c = 0; c < 6; ++c) {
      EXPECT_EQ(cs["compliance"][r][c], sol.cartesian->compliance(r, c));
      EXPECT_EQ(cs["stiffness"][r][c], sol.cartesian->stiffness(r, c));
    }
  }
  // Compliance maps a wrench (N, N m) to a motion (m, rad); stiffness the other way.
  EXPECT_EQ(cs["compliance_units"][0][0], "m/N");
  EXPECT_EQ(cs["compliance_units"][1][4], "m/(N m)");
  EXPECT_EQ(cs["compliance_units"][5][2], "rad/N");
  EXPECT_EQ(cs["compliance_units"][3][3], "rad/(N m)");
  EXPECT_EQ(cs["stiffness_units"][0][0], "N/m");
  EXPECT_EQ(cs["stiffness_units"][0][3], "N/rad");
  EXPECT_EQ(cs["stiffness_units"][4][1], "N m/m");
  EXPECT_EQ(cs["stiffness_units"][3][5], "N m/rad");

  const json& ind = cs["indices"];
  EXPECT_EQ(ind["trace"], 42.0);
  EXPECT_EQ(ind["eigenvalues"], json({1.0, 2.0, 3.0, 4.0, 5.0, 6.0}));
  // eigenvectors[i] is the column belonging to eigenvalues[i].
  EXPECT_EQ(ind["eigenvectors"][1][0], 0.25);
  EXPECT_EQ(ind["eigenvectors"][0][1], 0.0);
  for (const char* key : {"size", "det_sign", "log10_abs_det", "norm_1", "norm_2", "norm_frobenius", "norm_inf",
                          "max_abs_entry", "symmetry_error"}) {
    EXPECT_TRUE(ind.contains(key)) << key;
  }
}

TEST(ResultsJson, NonFiniteNumbersBecomeNullWithANote) {
  const json j = *solution_to_json(io_test::sample_structure(), io_test::sample_solution());
  const json& ind = j["cartesian_stiffness"]["indices"];
  EXPECT_TRUE(ind["condition_number"].is_null());
  EXPECT_TRUE(ind["determinant"].is_null());
  const json& notes = j["non_finite_values"];
  ASSERT_EQ(notes.size(), 2u);
  json expected = json::array({{{"path", "/cartesian_stiffness/indices/condition_number"}, {"value", "inf"}},
                               {{"path", "/cartesian_stiffness/indices/determinant"}, {"value", "nan"}}});
  // Object keys are sorted, so "condition_number" is visited before "determinant".
  EXPECT_EQ(notes, expected);
  // The text is strict JSON: it parses back to the same document.
  EXPECT_EQ(json::parse(j.dump()), j);
}

TEST(ResultsJson, SingularDiagnosis) {
  const json j = *solution_to_json(io_test::sample_structure(), io_test::sample_singular_solution());
  EXPECT_EQ(j["status"]["code"], "singular");
  EXPECT_EQ(j["load_cases"].size(), 0u);
  EXPECT_TRUE(j["cartesian_stiffness"].is_null());
  const json& d = j["singularity"];
  EXPECT_EQ(d["singular"], true);
  EXPECT_EQ(d["message"], "node 'C' moves freely");
  EXPECT_EQ(d["weak_dofs"], json::array({{{"node", "B2"}, {"dof", "rz"}}}));
  ASSERT_EQ(d["free_motions"].size(), 1u);
  const json& m = d["free_motions"][0];
  EXPECT_EQ(m["rayleigh_ratio"], 1e-17);
  EXPECT_EQ(m["nodes"][3]["node"], "C");
  EXPECT_EQ(m["nodes"][3]["translation"], json({-0.5, 0.0, 0.0}));
  EXPECT_EQ(m["nodes"][3]["rotation"], json({0.0, 0.0, 1.0}));
}

TEST(ResultsJson, WriteJsonRoundTripsAndReportsBadPaths) {
  const json j = *solution_to_json(io_test::sample_structure(), io_test::sample_solution());
  const std::string path = ::testing::TempDir() + "kinestat_results_json_test.json";
  ASSERT_TRUE(write_json(path, j).ok());
  std::ifstream in(path);
  EXPECT_EQ(json::parse(in), j);
  std::filesystem::remove(path);

  const std::string bad = ::testing::TempDir() + "no_such_dir_kinestat/x.json";
  const Status st = write_json(bad, j);
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(st.message().rfind(bad + ": ", 0), 0u) << st.message();
}

// End to end with the solver: the cantilever's JSON holds the tip deflection P L^3 / (3 E I)
// and balanced reactions.
TEST(ResultsJson, CantileverEndToEnd) {
  const auto s = read_structure_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/cantilever.yaml");
  ASSERT_TRUE(s.ok()) << s.status().message();
  const json j = *solution_to_json(*s, msa::solve(*s));
  ASSERT_EQ(j["status"]["code"], "ok");
  const json& c = j["load_cases"][0];
  ASSERT_EQ(c["name"], "tip_down");
  const double Iy = 0.02 * std::pow(0.04, 3) / 12;
  EXPECT_NEAR(c["displacements"][1]["translation"][2].get<double>(), -1000.0 / (3 * 210e9 * Iy), 1e-12);
  EXPECT_NEAR(c["reactions"][0]["force"][2].get<double>(), 1000.0, 1e-6);
  EXPECT_TRUE(j["cartesian_stiffness"]["stiffness_defined"].get<bool>());
}

// A solution of another structure is refused (it used to give a silent document with the other
// structure's ids): by the counts solve() records, and for a hand-made one by its arrays.
TEST(ResultsJson, SolutionOfAnotherStructureIsRefused) {
  const auto s = read_structure_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/cantilever.yaml");
  ASSERT_TRUE(s.ok()) << s.status().message();
  const msa::Solution sol = msa::solve(*s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const auto other = solution_to_json(io_test::sample_structure(), sol);
  ASSERT_EQ(other.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(other.status().message().find("the counts it was solved for"), std::string::npos)
      << other.status().message();

  msa::Solution hand = io_test::sample_solution();
  hand.cases[1].reaction.pop_back();
  const auto short_one = solution_to_json(io_test::sample_structure(), hand);
  ASSERT_EQ(short_one.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(short_one.status().message().find("load case"), std::string::npos) << short_one.status().message();
}

}  // namespace
}  // namespace kinestat::io
