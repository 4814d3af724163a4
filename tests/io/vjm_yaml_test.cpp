// VJM model files: the file-built chains against the C++ builder, units, and every bad-input message.
#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/mechanisms/orthoglide_identification.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::io {
namespace {

using mechanisms::OrthoglideArchitecture;

const std::string kSource = KINESTAT_SOURCE_DIR;

Mat6 platform_stiffness(const std::vector<vjm::Chain>& chains) {
  StatusOr<CartesianStiffness> K = vjm::platform_unloaded_stiffness(chains);
  EXPECT_TRUE(K.ok()) << K.status().message();
  EXPECT_TRUE(K->status.ok()) << K->status.message();
  return K->stiffness;
}

double relative_difference(const Mat6& A, const Mat6& B) {
  return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
}

Mat6 builder_stiffness(OrthoglideArchitecture a, const Vec3& p, const mechanisms::OrthoglideStiffnessModel& m = {}) {
  StatusOr<std::vector<vjm::Chain>> c = mechanisms::orthoglide_chains(m, a, p);
  EXPECT_TRUE(c.ok()) << c.status().message();
  return platform_stiffness(*c);
}

// The declared calibration (mechanisms/orthoglide_identification.hpp) from the nominal defaults.
const mechanisms::OrthoglideStiffnessModel& identified_model() {
  static const mechanisms::OrthoglideStiffnessModel m = [] {
    const mechanisms::OrthoglideStiffnessModel start = mechanisms::paper_calibration_start();
    StatusOr<mechanisms::OrthoglideIdentification> id = mechanisms::identify_orthoglide_inputs(
        start, mechanisms::paper_calibration_inputs(), mechanisms::paper_calibration_targets());
    EXPECT_TRUE(id.ok()) << id.status().message();
    return id.ok() ? id->model : start;
  }();
  return m;
}

// The explicit chains at Q0 (fixtures: the nominal C++ defaults in mm-N-s) against
// mechanisms::orthoglide_chains with the defaults; the bundled model file against the builder with the
// identified inputs, which the file holds to 5 digits.
void compare_with_builder(const std::string& fixture, const std::string& model_file, OrthoglideArchitecture a) {
  StatusOr<VjmModel> explicit_chains = read_vjm_model_yaml(kSource + "/tests/io/data/" + fixture);
  ASSERT_TRUE(explicit_chains.ok()) << explicit_chains.status().message();
  ASSERT_EQ(explicit_chains->chains.size(), 3u);
  StatusOr<std::vector<vjm::Chain>> c = vjm_model_chains(*explicit_chains, std::nullopt);
  ASSERT_TRUE(c.ok());
  const Mat6 K_file = platform_stiffness(*c);
  const Mat6 K_cpp = builder_stiffness(a, Vec3::Zero());
  EXPECT_LT(relative_difference(K_file, K_cpp), 1e-9);
  EXPECT_LT((K_file - K_file.transpose()).norm() / K_file.norm(), 1e-12);

  StatusOr<VjmModel> model = read_vjm_model_yaml(kSource + "/models/" + model_file);
  ASSERT_TRUE(model.ok()) << model.status().message();
  ASSERT_TRUE(model->orthoglide.has_value());
  EXPECT_EQ(model->architecture, a);
  // Off Q0 too (the paper's Q1), so that every parameter matters and the inverse kinematics is used.
  const Vec3 q1 = mechanisms::paper_table_point(-73.65);
  StatusOr<std::vector<vjm::Chain>> at_q1 = vjm_model_chains(*model, q1);
  ASSERT_TRUE(at_q1.ok()) << at_q1.status().message();
  EXPECT_LT(relative_difference(platform_stiffness(*at_q1), builder_stiffness(a, q1, identified_model())), 2e-4);
  // And the file reproduces the calibration entries of its architecture (Tables 1-2) to its 5 digits.
  for (const mechanisms::ComplianceTarget& t : mechanisms::paper_calibration_targets()) {
    if (t.architecture != a) continue;
    StatusOr<std::vector<vjm::Chain>> chains = vjm_model_chains(*model, t.point);
    ASSERT_TRUE(chains.ok()) << chains.status().message();
    const Mat6 C = platform_stiffness(*chains).inverse();
    EXPECT_NEAR(C(t.row, t.col), t.value, 2e-4 * t.value) << t.label;
  }
}

TEST(VjmYaml, PuuFileChainsEqualTheBuilder) {
  compare_with_builder("vjm_puu_q0.yaml", "orthoglide_puu.yaml", OrthoglideArchitecture::kPUU);
}

TEST(VjmYaml, PrparFileChainsEqualTheBuilder) {
  compare_with_builder("vjm_prpar_q0.yaml", "orthoglide_prpar.yaml", OrthoglideArchitecture::kPRPaR);
}

TEST(VjmYaml, MatrixSpringIsConvertedFromMmToSi) {
  // A lone spring at the base: the chain's stiffness is that matrix. In mm-N-s, N/mm -> 1e3 N/m,
  // N (N/rad, N mm/mm) -> 1 N, N mm/rad -> 1e-3 N m/rad.
  const char* text = R"(units: mm-N-s
chains:
  - elements:
      - spring: {matrix: [[1, 0, 0, 0, 0, 0.5], [0, 2, 0, 0, 0, 0], [0, 0, 3, 0, 0, 0],
                          [0, 0, 0, 4, 0, 0], [0, 0, 0, 0, 5, 0], [0.5, 0, 0, 0, 0, 6]]}
)";
  StatusOr<VjmModel> m = read_vjm_model_yaml_string(text, "spring.yaml");
  ASSERT_TRUE(m.ok()) << m.status().message();
  Mat6 expected = Vec6(1e3, 2e3, 3e3, 4e-3, 5e-3, 6e-3).asDiagonal();
  expected(0, 5) = expected(5, 0) = 0.5;
  // Entry by entry: the engine's orthogonal elimination works through the compliance, so entries
  // spanning 1e-3 .. 1e3 carry round-off ~1e-16 times that 1e6 spread.
  const Mat6 K = platform_stiffness(m->chains);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_NEAR(K(i, j), expected(i, j), 1e-9 * std::sqrt(expected(i, i) * expected(j, j))) << i << "," << j;
}

TEST(VjmYaml, PointIsOnlyForOrthoglideModels) {
  StatusOr<VjmModel> m = read_vjm_model_yaml(kSource + "/tests/io/data/vjm_puu_q0.yaml");
  ASSERT_TRUE(m.ok());
  StatusOr<std::vector<vjm::Chain>> c = vjm_model_chains(*m, Vec3(0.01, 0, 0));
  EXPECT_EQ(c.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(c.status().message().find("mechanism: orthoglide"), std::string::npos);
}

struct BadCase {
  const char* name;
  const char* text;
  const char* expected;  // "bad.yaml:LINE: ITEM: ..." prefix or a distinctive part
};

class BadVjmFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadVjmFile, MessageNamesLineAndItem) {
  StatusOr<VjmModel> m = read_vjm_model_yaml_string(GetParam().text, "bad.yaml");
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(m.status().message().find(GetParam().expected), std::string::npos) << m.status().message();
}

constexpr const char* kOrthoTail = R"(
  link_length: 310.6
  actuator_stiffness: 2.0e4
  bar: {E: 70000, nu: 0.33, section: {type: tube, d: 20, t: 2}}
  foot: {E: 210000, nu: 0.3, section: {type: hollow_rectangle, b: 60, h: 60, t: 5}, length: 100}
)";

const std::string kBadArch = std::string("mechanism: orthoglide\northoglide:\n  architecture: 3-RRR") + kOrthoTail;
const std::string kNegativeOffset =
    std::string("mechanism: orthoglide\northoglide:\n  architecture: 3-PUU\n  platform_offset: -3") + kOrthoTail;
const std::string kBadNu =
    "mechanism: orthoglide\northoglide:\n  architecture: 3-PUU\n  link_length: 310.6\n  actuator_stiffness: 2.0e4\n"
    "  bar: {E: 70000, nu: 0.7, section: {type: tube, d: 20, t: 2}}\n";

INSTANTIATE_TEST_SUITE_P(
    VjmYaml, BadVjmFile,
    ::testing::Values(
        BadCase{"Empty", "", "bad.yaml: file: the file is empty"},
        BadCase{"UnknownTopKey", "units: SI\nchain: []\n",
                "bad.yaml:2: file: unknown key 'chain'; allowed keys are: units"},
        BadCase{"UnknownUnits", "units: inch\nchains: []\n", "bad.yaml:1: units: unknown units 'inch'"},
        BadCase{"UnknownMechanism", "mechanism: hexapod\n", "bad.yaml:1: file: unknown mechanism 'hexapod'"},
        BadCase{"OrthoglideBlockMissing", "mechanism: orthoglide\n", "file: missing required key 'orthoglide'"},
        BadCase{"BadArchitecture", kBadArch.c_str(), "bad.yaml:3: orthoglide: unknown architecture '3-RRR'"},
        BadCase{"NegativePlatformOffset", kNegativeOffset.c_str(),
                "bad.yaml:4: orthoglide: 'platform_offset' = -3 m must not be negative"},
        BadCase{"PoissonOutOfRange", kBadNu.c_str(), "bad.yaml:6: orthoglide bar: 'nu' = 0.7 is not in (-1, 0.5)"},
        BadCase{"NoChains", "units: SI\n", "file: missing required key 'chains'"},
        BadCase{"EmptyChains", "chains: []\n", "bad.yaml:1: chains: the list is empty"},
        BadCase{"TwoKindsInOneElement",
                "chains:\n  - name: a\n    elements:\n      - {translate: [1, 0, 0], rotate: {axis: [0, 0, 1], angle: "
                "1}}\n",
                "bad.yaml:4: chain 'a' element 1: give exactly one of"},
        BadCase{"UnknownElement", "chains:\n  - name: a\n    elements:\n      - {twist: 1}\n",
                "bad.yaml:4: chain 'a' element 1: unknown key 'twist'"},
        BadCase{"ZeroAxis", "chains:\n  - name: a\n    elements:\n      - rotate: {axis: [0, 0, 0], angle: 1}\n",
                "bad.yaml:4: chain 'a' element 1 (rotate): 'axis': the direction must be finite and non-zero"},
        BadCase{"CoupledToUnknownJoint",
                "chains:\n  - name: a\n    elements:\n      - coupled: {to: q9, type: revolute, axis: [0, 1, 0], "
                "coefficient: -1}\n",
                "bad.yaml:4: chain 'a' element 1 (coupled): no passive joint with id 'q9'"},
        BadCase{"BadJointType",
                "chains:\n  - name: a\n    elements:\n      - passive: {type: ball, axis: [0, 1, 0], q: 0}\n",
                "bad.yaml:4: chain 'a' element 1 (passive): unknown joint type 'ball'"},
        BadCase{"NegativeActuatorStiffness",
                "chains:\n  - name: a\n    elements:\n      - actuator: {type: prismatic, axis: [1, 0, 0], value: 0,\n"
                "                   stiffness: -5}\n",
                "bad.yaml:5: chain 'a' element 1 (actuator): 'stiffness' = -5 N/m must be positive"},
        BadCase{"MatrixNotSixRows", "chains:\n  - name: a\n    elements:\n      - spring: {matrix: [[1, 2]]}\n",
                "bad.yaml:4: chain 'a' element 1 (spring): 'matrix' must be 6 rows of 6 numbers"},
        BadCase{
            "UnknownSection",
            "chains:\n  - name: a\n    elements:\n      - spring:\n          cantilever: {E: 1, nu: 0.3, length: 1,\n"
            "                       section: {type: star, d: 1}}\n",
            "bad.yaml:6: chain 'a' element 1 (spring) cantilever section: unknown section type 'star'"},
        BadCase{"SpringNotPositiveDefinite",
                "chains:\n  - name: a\n    elements:\n      - spring: {matrix: [[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, "
                "0], [0, 0, 1, 0, 0, 0],\n"
                "                          [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, -1]]}\n",
                "bad.yaml:2: chain 'a': "},
        BadCase{"ToolPointsDoNotMeet",
                "chains:\n  - name: a\n    elements: [{translate: [1, 0, 0]}]\n  - name: b\n    elements: [{translate: "
                "[0, 1, 0]}]\n",
                "bad.yaml:2: chains: "},
        BadCase{"MalformedYaml", "chains:\n  - name: [a\n", "bad.yaml:3: malformed YAML"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

TEST(VjmYaml, MissingFileIsBadInput) {
  StatusOr<VjmModel> m = read_vjm_model_yaml("/nonexistent/model.yaml");
  EXPECT_EQ(m.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(m.status().message().find("/nonexistent/model.yaml: cannot open the VJM model file"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::io
