// Bad input by class (docs/reliability.md), through the file readers: values that overflow once
// converted to SI, values out of their physical range, contradictions a reader used to accept
// silently, and the checks that run after reading (the solve's dof reduction), whose messages must
// still name the file and the line of the item.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kinestat/io/identification_yaml.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::io {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

// Reading `yaml` fails with kInvalidInput, a message starting "model.yaml:LINE: " and holding `parts`.
void expect_structure_error(const std::string& yaml, int line, std::initializer_list<const char*> parts) {
  const auto r = read_structure_yaml_string(yaml, "model.yaml");
  ASSERT_FALSE(r.ok()) << yaml;
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(r.status().message().rfind("model.yaml:" + std::to_string(line) + ": ", 0), 0u) << r.status().message();
  for (const char* p : parts) expect_contains(r.status().message(), p);
}

// A cantilever in mm-N-s; `extra` is appended (its first line is line 12).
std::string cantilever_mm(const std::string& node_b = "[1000, 0, 0]",
                          const std::string& section = "{id: rod, type: circle, d: 20}") {
  return "units: mm-N-s\n"                // 1
         "nodes:\n"                       // 2
         "  - {id: A, xyz: [0, 0, 0]}\n"  // 3
         "  - {id: B, xyz: " +
         node_b +
         "}\n"                                    // 4
         "materials:\n"                           // 5
         "  - {id: steel, E: 210000, nu: 0.3}\n"  // 6
         "sections:\n"                            // 7
         "  - " +
         section +
         "\n"                                                           // 8
         "beams:\n"                                                     // 9
         "  - {id: b, nodes: [A, B], material: steel, section: rod}\n"  // 10
         "supports:\n"                                                  // 11
         "  - {node: A, fixed: all}\n";                                 // 12
}

TEST(InputValidation, ValuesThatOverflowOnceInSiAreRefusedNamingItemAndUnit) {
  expect_structure_error(cantilever_mm("[1e300, 0, 0]"), 4,
                         {"node 'B'", "'xyz' = 1e+300 mm is too large for a length (|value| <= 1e+09 mm)"});
  expect_structure_error(cantilever_mm("[1000, 0, 0]", "{id: rod, A: 100, Iy: 1e308, Iz: 1, J: 1}"), 8,
                         {"section 'rod'", "'Iy' = 1e+308 mm^4 is too large for a second moment of area"});
  const std::string joint = cantilever_mm() +
                            "joints:\n"                                                         // 13
                            "  - {id: j, nodes: [B, B], stiffness: [1e308, 1, 1, 1, 1, 1]}\n";  // 14
  expect_structure_error(joint, 14, {"joint 'j'", "'stiffness ux' = 1e+308 N/mm is too large"});
  const std::string load = cantilever_mm() +
                           "load_cases:\n"                                // 13
                           "  - name: push\n"                             // 14
                           "    loads:\n"                                 // 15
                           "      - {node: B, moment: [0, 0, 1e300]}\n";  // 16
  expect_structure_error(load, 16, {"load case 'push'", "'moment' = 1e+300 N mm is too large for a moment"});
}

TEST(InputValidation, AHollowSectionWhoseWallLeavesNoHoleIsRefused) {
  // d - 2t < 0 still gives a positive area and inertia: it used to be accepted in model files.
  const char* vjm =
      "units: mm-N-s\n"                                                                    // 1
      "chains:\n"                                                                          // 2
      "  - name: leg\n"                                                                    // 3
      "    elements:\n"                                                                    // 4
      "      - actuator: {type: prismatic, axis: [1, 0, 0], value: 0, stiffness: 1000}\n"  // 5
      "      - spring: {cantilever: {E: 210000, nu: 0.3, length: 100,\n"                   // 6
      "                 section: {type: tube, d: 10, t: 6}}}\n";                           // 7
  const auto m = read_vjm_model_yaml_string(vjm, "leg.yaml");
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), StatusCode::kInvalidInput);
  expect_contains(m.status().message(), "leg.yaml:7: chain 'leg' element 2 (spring) cantilever section");
  expect_contains(m.status().message(), "the wall t must be less than half of d (t = 6 mm, d = 10 mm)");
  expect_structure_error(cantilever_mm("[1000, 0, 0]", "{id: rod, type: hollow_rectangle, b: 20, h: 10, t: 5}"), 8,
                         {"section 'rod'", "less than half of h"});
}

TEST(InputValidation, AnAxisWhoseNormOverflowsIsStillADirection) {
  const char* vjm =
      "chains:\n"
      "  - name: pendulum\n"
      "    elements:\n"
      "      - actuator: {type: revolute, axis: [1e300, 1e300, 0], value: 0, stiffness: 1000}\n"
      "      - translate: [0.1, 0, 0]\n";
  const auto m = read_vjm_model_yaml_string(vjm, "p.yaml");
  ASSERT_TRUE(m.ok()) << m.status().message();
  const vjm::Factor& f = m->chains[0].factors()[0];
  EXPECT_NEAR((f.axis - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 0.0, 1e-15);  // not (nan, nan, nan)
}

TEST(InputValidation, TwoValuesForOnePrescribedDofAreRefused) {
  const std::string m = cantilever_mm() +
                        "load_cases:\n"                            // 13
                        "  - name: settle\n"                       // 14
                        "    prescribed:\n"                        // 15
                        "      - {node: A, dof: uz, value: 1}\n"   // 16
                        "      - {node: A, dof: uz, value: 2}\n";  // 17
  expect_structure_error(m, 17, {"load case 'settle'", "dof uz of node 'A' is already prescribed (at model.yaml:16)"});
}

// The checks of the solve's dof reduction: the message starts with the offending item's line.
void expect_solve_error(const std::string& yaml, const std::string& start, const char* complaint) {
  const auto s = read_structure_yaml_string(yaml, "model.yaml");
  ASSERT_TRUE(s.ok()) << s.status().message();
  const msa::Solution sol = msa::solve(*s);
  ASSERT_EQ(sol.status.code(), StatusCode::kInvalidInput) << sol.status.message();
  EXPECT_EQ(sol.status.message().rfind(start, 0), 0u) << sol.status.message();
  expect_contains(sol.status.message(), complaint);
}

constexpr const char* kThreeNodes =
    "nodes:\n"                        // 1
    "  - {id: A, xyz: [0, 0, 0]}\n"   // 2
    "  - {id: B, xyz: [1, 0, 0]}\n"   // 3
    "  - {id: C, xyz: [1, 1, 0]}\n";  // 4

TEST(InputValidation, ChecksAfterReadingNameFileAndLine) {
  const std::string nodes = kThreeNodes;
  expect_solve_error(nodes +
                         "supports:\n"                                                         // 5
                         "  - {node: A, fixed: [ux]}\n"                                        // 6
                         "  - {node: A, fixed: [uy], frame: {x: [0, 1, 0], z: [0, 0, 1]}}\n",  // 7
                     "model.yaml:7: ", "two supports in different frames");
  expect_solve_error(nodes +
                         "supports:\n"                   // 5
                         "  - {node: A, fixed: all}\n"   // 6
                         "  - {node: B, fixed: all}\n"   // 7
                         "  - {node: C, fixed: all}\n",  // 8
                     "model.yaml: ", "every dof of the structure is supported");
}

TEST(InputValidation, OrthoglideModelChecksNameTheLine) {
  // E overflows once converted from MPa: refused at its line, not later without one.
  const char* model =
      "units: mm-N-s\n"                                                               // 1
      "mechanism: orthoglide\n"                                                       // 2
      "orthoglide:\n"                                                                 // 3
      "  architecture: 3-PUU\n"                                                       // 4
      "  link_length: 310.0\n"                                                        // 5
      "  actuator_stiffness: 1e4\n"                                                   // 6
      "  bar: {E: 1e305, nu: 0.3, section: {type: circle, d: 10}}\n"                  // 7
      "  foot: {E: 210000, nu: 0.3, length: 100, section: {type: circle, d: 30}}\n";  // 8
  const auto m = read_vjm_model_yaml_string(model, "og.yaml");
  ASSERT_FALSE(m.ok());
  expect_contains(m.status().message(), "og.yaml:7: orthoglide bar: 'E' = 1e+305 MPa is too large for a modulus");
}

TEST(InputValidation, IdentificationTargetsAreCheckedAndKeepTheirLine) {
  const auto negative = read_identification_targets_yaml_string(
      "units: mm-N-s\n"
      "inputs: [actuator_stiffness]\n"
      "targets:\n"
      "  - {architecture: 3-PUU, point: [0, 0, 0], row: 0, col: 0, value: -2.78e-4}\n",
      "t.yaml");
  ASSERT_FALSE(negative.ok());
  expect_contains(negative.status().message(), "t.yaml:4: target #1: 'value' = -0.000278 mm/N must be positive");
  const auto good = read_identification_targets_yaml_string(
      "inputs: [actuator_stiffness]\n"
      "targets:\n"
      "  - {label: q0, architecture: 3-PUU, point: [0, 0, 0], row: 0, col: 0, value: 2.78e-7}\n",
      "t.yaml");
  ASSERT_TRUE(good.ok()) << good.status().message();
  EXPECT_EQ(good->targets[0].source, "t.yaml:3");
}

}  // namespace
}  // namespace kinestat::io
