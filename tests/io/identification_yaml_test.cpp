// Identification targets files: the bundled paper targets file is the library's declared calibration
// (mechanisms::paper_calibration_targets, typed in separately) after the unit conversion; bad files
// give FILE:LINE: ITEM messages.
#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/io/identification_yaml.hpp"

namespace kinestat::io {
namespace {

TEST(IdentificationYaml, PaperTargetsFileIsTheDeclaredCalibration) {
  StatusOr<IdentificationTargets> t =
      read_identification_targets_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/orthoglide_paper_targets.yaml");
  ASSERT_TRUE(t.ok()) << t.status().message();
  EXPECT_EQ(t->inputs, mechanisms::paper_calibration_inputs());
  const std::vector<mechanisms::ComplianceTarget> expected = mechanisms::paper_calibration_targets();
  ASSERT_EQ(t->targets.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const mechanisms::ComplianceTarget &a = t->targets[k], &b = expected[k];
    EXPECT_EQ(a.label, b.label);
    EXPECT_EQ(a.architecture, b.architecture);
    EXPECT_LT((a.point - b.point).norm(), 1e-12) << b.label;  // mm -> m
    EXPECT_EQ(a.row, b.row);
    EXPECT_EQ(a.col, b.col);
    EXPECT_NEAR(a.value, b.value, 1e-12 * b.value) << b.label;  // mm/N -> m/N, rad/(N mm) -> rad/(N m)
  }
}

TEST(IdentificationYaml, CouplingTermsAreOneOverNewtonInEveryUnitSystem) {
  const char* text = R"(units: mm-N-s
inputs: [actuator_stiffness]
targets:
  - {architecture: 3-PUU, point: [1, 2, 3], row: 0, col: 4, value: 2.5e-6}
)";
  StatusOr<IdentificationTargets> t = read_identification_targets_yaml_string(text, "t.yaml");
  ASSERT_TRUE(t.ok()) << t.status().message();
  EXPECT_DOUBLE_EQ(t->targets[0].value, 2.5e-6);  // mm/(N mm) = m/(N m) = 1/N
  EXPECT_LT((t->targets[0].point - Vec3(1e-3, 2e-3, 3e-3)).norm(), 1e-15);
  EXPECT_EQ(t->targets[0].label, "target #1");
}

struct BadCase {
  const char* name;
  const char* text;
  const char* expected;
};

class BadTargetsFile : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadTargetsFile, MessageNamesLineAndItem) {
  StatusOr<IdentificationTargets> t = read_identification_targets_yaml_string(GetParam().text, "bad.yaml");
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(t.status().message().find(GetParam().expected), std::string::npos) << t.status().message();
}

constexpr const char* kTarget = "targets:\n  - {architecture: 3-PUU, point: [0, 0, 0], row: 0, col: 0, value: 1e-4}\n";
const std::string kUnknownInput = std::string("inputs: [stiffness]\n") + kTarget;
const std::string kTwice = std::string("inputs: [foot_length, foot_length]\n") + kTarget;
const std::string kTooFew = std::string("inputs: [foot_length, bar_scale]\n") + kTarget;

INSTANTIATE_TEST_SUITE_P(
    IdentificationYaml, BadTargetsFile,
    ::testing::Values(
        BadCase{"Empty", "", "bad.yaml: file: the file is empty"},
        BadCase{"UnknownInput", kUnknownInput.c_str(), "bad.yaml:1: inputs: unknown input 'stiffness'"},
        BadCase{"InputTwice", kTwice.c_str(), "bad.yaml:1: inputs: 'foot_length' is listed twice"},
        BadCase{"TooFewTargets", kTooFew.c_str(), "bad.yaml:3: targets: 1 target(s) for 2 input(s)"},
        BadCase{"BadRow",
                "inputs: [foot_length]\ntargets:\n  - {architecture: 3-PUU, point: [0, 0, 0], row: 6, col: 0, "
                "value: 1}\n",
                "bad.yaml:3: target #1: 'row' = 6 is not a dof index"},
        BadCase{"BadArchitecture",
                "inputs: [foot_length]\ntargets:\n  - {architecture: delta, point: [0, 0, 0], row: 0, col: 0, "
                "value: 1}\n",
                "bad.yaml:3: target #1: unknown architecture 'delta'"},
        BadCase{"ZeroValue",
                "inputs: [foot_length]\ntargets:\n  - {architecture: 3-PUU, point: [0, 0, 0], row: 0, col: 0, "
                "value: 0}\n",
                "bad.yaml:3: target #1: 'value' = 0 m/N must be positive"}),
    [](const ::testing::TestParamInfo<BadCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace kinestat::io
