// The YAML structure reader: every bad-input path gives one message naming the file, the line
// and the item; good input arrives in SI with the documented conversions.
#include "kinestat/io/structure_yaml.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "kinestat/core/units.hpp"

namespace kinestat::io {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

std::string fixture(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/tests/io/data/" + name; }

struct BadInput {
  const char* file;
  int line;               // 1-based line of the offending entry in the fixture; 0: no line
  const char* item;       // the item the message must name
  const char* complaint;  // what it must say is wrong
};

class BadFixture : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadFixture, NamesFileLineAndItem) {
  const BadInput& b = GetParam();
  const std::string path = fixture(b.file);
  const auto r = read_structure_yaml(path);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  const std::string& m = r.status().message();
  const std::string prefix = b.line > 0 ? path + ":" + std::to_string(b.line) + ": " : path + ": ";
  EXPECT_EQ(m.rfind(prefix, 0), 0u) << m;
  expect_contains(m, b.item);
  expect_contains(m, b.complaint);
  EXPECT_EQ(m.find('\n'), std::string::npos) << "one message on one line: " << m;
}

// Lines counted in the fixture files (each starts with a comment line). A missing file has no
// line; joint_gap.yaml parses but fails Structure::validate(), whose message gets the joint's line.
INSTANTIATE_TEST_SUITE_P(
    Fixtures, BadFixture,
    ::testing::Values(BadInput{"malformed.yaml", 4, "malformed YAML", "check indentation"},
                      BadInput{"unknown_key.yaml", 13, "beam 'b1'",
                               "unknown key 'sektion'; allowed keys are: id, nodes, material, section"},
                      BadInput{"missing_key.yaml", 5, "material 'steel'", "missing required key 'E'"},
                      BadInput{"wrong_type.yaml", 5, "material 'steel'", "'E' must be a finite number, got 'stiff'"},
                      BadInput{"unknown_node.yaml", 11, "beam 'b2'", "unknown node 'Z'"},
                      BadInput{"duplicate_id.yaml", 5, "node 'B'", "already used"},
                      BadInput{"zero_length.yaml", 12, "beam 'b2'", "zero length"},
                      BadInput{"negative_modulus.yaml", 6, "material 'rubber'", "'E' = -5e+06 Pa must be positive"},
                      BadInput{"zero_inertia.yaml", 8, "section 'strip'", "'Iz' = 0 m^4 must be positive"},
                      BadInput{"load_missing_node.yaml", 11, "load case 'push'", "unknown node 'tip'"},
                      BadInput{"support_missing_node.yaml", 6, "support #2", "unknown node 'ground'"},
                      BadInput{"unknown_dof.yaml", 6, "support at node 'A'", "unknown dof 'uw'"},
                      BadInput{"no_such_file.yaml", 0, "no_such_file.yaml", "cannot open the structure file"},
                      BadInput{"joint_gap.yaml", 6, "joint 'j1'", "must coincide"}),
    [](const auto& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

// Messages for inline text: "<display>:LINE: ..." must contain all `parts`.
void expect_error(const std::string& yaml, int line, std::initializer_list<const char*> parts) {
  const auto r = read_structure_yaml_string(yaml, "model.yaml");
  ASSERT_FALSE(r.ok()) << yaml;
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  const std::string& m = r.status().message();
  EXPECT_EQ(m.rfind("model.yaml:" + std::to_string(line) + ": ", 0), 0u) << m;
  for (const char* p : parts) expect_contains(m, p);
}

constexpr const char* kTwoNodes =
    "nodes:\n"                        // 1
    "  - {id: A, xyz: [0, 0, 0]}\n"   // 2
    "  - {id: B, xyz: [1, 0, 0]}\n";  // 3

TEST(StructureYaml, EmptyFileAndMissingNodes) {
  auto r = read_structure_yaml_string("", "model.yaml");
  ASSERT_FALSE(r.ok());
  expect_contains(r.status().message(), "the file is empty");
  expect_error("title: nothing\n", 1, {"missing required key 'nodes'"});
  expect_error("- a\n- b\n", 1, {"top level is not a map"});
}

TEST(StructureYaml, TopLevelTypos) {
  expect_error(std::string(kTwoNodes) + "beam:\n  - {id: b}\n", 4, {"unknown key 'beam'", "beams"});
  expect_error(std::string(kTwoNodes) + "units: inch\n", 4, {"units", "unknown units 'inch'", "mm-N-s"});
  expect_error(std::string(kTwoNodes) + "nodes: []\n", 4, {"key 'nodes' is given twice"});
}

TEST(StructureYaml, EntryShapeErrors) {
  expect_error("nodes:\n  - {id: A, xyz: [0, 0]}\n", 2, {"node 'A'", "three numbers"});
  expect_error("nodes:\n  - {xyz: [0, 0, 0]}\n", 2, {"node #1", "missing required key 'id'"});
  expect_error("nodes:\n  - A\n", 2, {"node #1", "expected a map"});
  expect_error("nodes: {A: [0, 0, 0]}\n", 1, {"nodes", "expected a list"});
  expect_error(std::string(kTwoNodes) + "materials:\n  - {id: m, E: 1e9}\n", 5, {"material 'm'", "exactly one of G"});
  expect_error(std::string(kTwoNodes) + "materials:\n  - {id: m, E: 1e9, nu: 0.7}\n", 5, {"material 'm'", "nu = 0.7"});
  expect_error(std::string(kTwoNodes) + "sections:\n  - {id: s, type: hexagon, d: 1}\n", 5,
               {"section 's'", "unknown section type 'hexagon'"});
  expect_error(std::string(kTwoNodes) + "sections:\n  - {id: s, type: tube, d: 0.02, t: 0.01}\n", 5,
               {"section 's'", "less than half"});
  expect_error(std::string(kTwoNodes) + "sections:\n  - {id: s, type: circle, d: 0.02, t: 1}\n", 5,
               {"unknown key 't'", "id, type, d"});
}

constexpr const char* kBeamModel =
    "nodes:\n"                                // 1
    "  - {id: A, xyz: [0, 0, 0]}\n"           // 2
    "  - {id: B, xyz: [1, 0, 0]}\n"           // 3
    "  - {id: C, xyz: [1, 0, 0]}\n"           // 4
    "materials:\n"                            // 5
    "  - {id: steel, E: 210e9, nu: 0.3}\n"    // 6
    "sections:\n"                             // 7
    "  - {id: rod, type: circle, d: 0.02}\n"  // 8
    "supports:\n"                             // 9
    "  - {node: A, fixed: [ux, uy, uz]}\n";   // 10

TEST(StructureYaml, BeamJointLinkErrors) {
  const std::string m = kBeamModel;
  expect_error(m + "beams:\n  - {id: b, nodes: [A, B], material: iron, section: rod}\n", 12,
               {"beam 'b'", "unknown material 'iron'"});
  expect_error(m + "beams:\n  - {id: b, nodes: [A, B], material: steel, section: rod, orientation: [2, 0, 0]}\n", 12,
               {"beam 'b'", "orientation"});
  expect_error(m + "beams:\n  - {id: b, nodes: [A, B], material: steel, section: rod, theory: bernoulli}\n", 12,
               {"beam 'b'", "unknown theory 'bernoulli'"});
  expect_error(
      m + "beams:\n  - {id: b, nodes: [A, B], material: steel, section: rod, releases: {end1: [rx], end2: [rx]}}\n", 12,
      {"beam 'b'", "keep each dof fixed at one end"});
  expect_error(m + "joints:\n  - {id: j, nodes: [B, C], stiffness: [1, 1, 1, 1, 1]}\n", 12,
               {"joint 'j'", "six values"});
  expect_error(m + "joints:\n  - {id: j, nodes: [B, C], stiffness: [1, 1, 1, 1, 1, -1]}\n", 12,
               {"joint 'j'", "'stiffness rz' = -1 N m/rad must not be negative"});
  expect_error(m + "joints:\n  - {id: j, nodes: [B, C], stiffness: [1, 1, 1, 1, 1, stiff]}\n", 12,
               {"joint 'j'", "got 'stiff'"});
  expect_error(m + "joints:\n  - {id: j, nodes: [B, C], stiffness: {ux: 1, uy: 1, uz: 1, rx: 1, ry: 1}}\n", 12,
               {"joint 'j' stiffness", "missing required key 'rz'"});
  expect_error(
      m + "joints:\n  - {id: j, nodes: [B, C], stiffness: [0, 0, 0, 0, 0, 0], frame: {x: [1, 0, 0], z: [1, 0, 1]}}\n",
      12, {"joint 'j'", "not perpendicular"});
  expect_error(m + "rigid_links:\n  - {id: r, master: B, slave: B}\n", 12, {"rigid link 'r'", "same node"});
  expect_error(m + "rigid_links:\n  - {id: r, master: B, slave: C, dofs: [ux, ru]}\n", 12,
               {"rigid link 'r'", "unknown dof 'ru'"});
}

// Shear areas written by hand are used or refused, never dropped (issue 21): an Euler-Bernoulli beam
// on such a section is an error at the beam's line; `beam_theory:` sets every beam's default.
TEST(StructureYaml, HandWrittenShearAreasNeedTimoshenkoBeams) {
  const std::string m =
      "nodes:\n"                                                        // 1
      "  - {id: A, xyz: [0, 0, 0]}\n"                                   // 2
      "  - {id: B, xyz: [1, 0, 0]}\n"                                   // 3
      "  - {id: C, xyz: [0, 1, 0]}\n"                                   // 4
      "materials:\n"                                                    // 5
      "  - {id: steel, E: 210e9, nu: 0.3}\n"                            // 6
      "sections:\n"                                                     // 7
      "  - {id: rod, type: circle, d: 0.02}\n"                          // 8
      "  - {id: s, A: 1e-4, Iy: 1e-8, Iz: 1e-8, J: 2e-8, Asz: 8e-5}\n"  // 9
      "supports:\n"                                                     // 10
      "  - {node: A, fixed: all}\n";                                    // 11
  expect_error(m + "beams:\n  - {id: b, nodes: [A, B], material: steel, section: s}\n", 13,
               {"beam 'b'", "section 's' gives shear areas", "theory: timoshenko"});
  expect_error("beam_theory: bernoulli\n" + m, 1, {"unknown beam_theory 'bernoulli'"});
  // A standard shape carries its shear areas and is fine with either theory.
  auto ok = io::read_structure_yaml_string(m + "beams:\n  - {id: b, nodes: [A, B], material: steel, section: rod}\n",
                                           "t.yaml");
  ASSERT_TRUE(ok.ok()) << ok.status().message();
  auto d = io::read_structure_yaml_string("beam_theory: timoshenko\n" + m +
                                              "beams:\n  - {id: b, nodes: [A, B], material: steel, section: s}\n"
                                              "  - {id: c, nodes: [A, C], material: steel, section: rod, theory: "
                                              "euler-bernoulli}\n",
                                          "t.yaml");
  ASSERT_TRUE(d.ok()) << d.status().message();
  EXPECT_EQ(d->beams()[0].theory, BeamTheory::kTimoshenko);
  EXPECT_EQ(d->beams()[1].theory, BeamTheory::kEulerBernoulli);
}

// `roll:` gives Frame3DD's local axes (its coord_trans with z vertical), written out here component
// by component: y = (-Cx Cz sin p - Cy cos p, -Cy Cz sin p + Cx cos p, den^2 sin p) / den,
// z = (-Cx Cz cos p + Cy sin p, -Cy Cz cos p - Cx sin p, den^2 cos p) / den, den = sqrt(1 - Cz^2);
// for an exactly vertical member y = (-Cz sin p, cos p, 0).
TEST(StructureYaml, RollAngleGivesFrame3ddLocalAxes) {
  const std::string m =
      "nodes:\n"                                // 1
      "  - {id: A, xyz: [0, 0, 0]}\n"           // 2
      "  - {id: D, xyz: [1, 2, 2]}\n"           // 3
      "  - {id: E, xyz: [0, 0, -3]}\n"          // 4
      "materials:\n"                            // 5
      "  - {id: steel, E: 210e9, nu: 0.3}\n"    // 6
      "sections:\n"                             // 7
      "  - {id: rod, type: circle, d: 0.02}\n"  // 8
      "supports:\n"                             // 9
      "  - {node: A, fixed: all}\n";            // 10
  auto s =
      read_structure_yaml_string(m + "beams:\n  - {id: b, nodes: [A, D], material: steel, section: rod, roll: 30}\n"
                                     "  - {id: v, nodes: [A, E], material: steel, section: rod, roll: 90}\n",
                                 "t.yaml");
  ASSERT_TRUE(s.ok()) << s.status().message();
  const double p = std::numbers::pi / 6, cx = 1.0 / 3, cy = 2.0 / 3, cz = 2.0 / 3, den = std::sqrt(1 - cz * cz);
  const Vec3 y((-cx * cz * std::sin(p) - cy * std::cos(p)) / den, (-cy * cz * std::sin(p) + cx * std::cos(p)) / den,
               den * std::sin(p));
  const Vec3 z((-cx * cz * std::cos(p) + cy * std::sin(p)) / den, (-cy * cz * std::cos(p) - cx * std::sin(p)) / den,
               den * std::cos(p));
  const Mat3 axes = s->beam_axes(s->beams()[0]);
  EXPECT_LT((axes.col(1) - y).norm(), 1e-14) << axes;
  EXPECT_LT((axes.col(2) - z).norm(), 1e-14) << axes;
  // Straight down (Cz = -1), rolled 90 deg: y = (-Cz sin p, cos p, 0) = (1, 0, 0).
  EXPECT_LT((s->beam_axes(s->beams()[1]).col(1) - Vec3(1, 0, 0)).norm(), 1e-14);
  expect_error(m + "beams:\n  - {id: b, nodes: [A, D], material: steel, section: rod, roll: 30, orientation: [0, 0, "
                   "1]}\n",
               12, {"beam 'b'", "either 'orientation' or 'roll'"});
}

// Any length and force unit (issue 20): {length: in, force: kip}, converted once on reading with
// the exact definitions of core/units.hpp (1 in = 0.0254 m, 1 kip = 4448.2216152605 N). Frame3DD's example A gives its
// steel 7.33e-7 kip s^2/in^4, which must arrive as a steel density (7833 kg/m^3).
TEST(StructureYaml, KipAndInchArriveInSI) {
  const char* yaml = R"(
units: {length: in, force: kip}
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [120, 0, 0]}
materials:
  - {id: steel, E: 29000, G: 11500, density: 7.33e-7}
sections:
  - {id: s, A: 10, Iy: 1, Iz: 0.01, J: 1}
beams:
  - {id: b, nodes: [A, B], material: steel, section: s}
supports:
  - {node: A, fixed: all}
load_cases:
  - name: tip
    loads:
      - {node: B, force: [0, -10, 0], moment: [0, 0, 5]}
)";
  auto s = read_structure_yaml_string(yaml, "kip.yaml");
  ASSERT_TRUE(s.ok()) << s.status().message();
  const double in = units::kInch, kip = units::kKip;
  EXPECT_DOUBLE_EQ(s->nodes()[1].position.x(), 120 * in);
  EXPECT_DOUBLE_EQ(s->materials()[0].E, 29000 * kip / (in * in));
  EXPECT_DOUBLE_EQ(s->sections()[0].Iz, 0.01 * in * in * in * in);
  EXPECT_NEAR(s->materials()[0].density, 7833.4, 0.1);
  EXPECT_DOUBLE_EQ(s->load_cases()[0].loads[0].wrench(1), -10 * kip);
  EXPECT_DOUBLE_EQ(s->load_cases()[0].loads[0].wrench(5), 5 * kip * in);
  // Messages speak the file's units.
  expect_error("units: {length: in, force: kip}\nnodes:\n  - {id: A, xyz: [0, 0, 1e300]}\n", 3, {"1e+300 in"});
  expect_error("units: {length: furlong, force: kip}\nnodes:\n  - {id: A, xyz: [0, 0, 0]}\n", 1,
               {"unknown length unit 'furlong'", "m, mm, cm, in or ft"});
  expect_error("units: {length: in, force: lb}\nnodes:\n  - {id: A, xyz: [0, 0, 0]}\n", 1,
               {"unknown force unit 'lb'", "lbf"});
}

TEST(StructureYaml, LoadCaseErrors) {
  const std::string m = kBeamModel;
  expect_error(m + "load_cases:\n  - name: a\n    loads:\n      - {node: B}\n", 14, {"load case 'a'", "force"});
  expect_error(m + "load_cases:\n  - name: a\n    loads:\n      - {node: B, force: [1, 0, x]}\n", 14,
               {"load case 'a'", "got 'x'"});
  expect_error(m + "load_cases:\n  - name: a\n  - name: a\n", 13, {"load case 'a'", "already used"});
  // A prescribed displacement needs a support fixing that dof: A fixes ux uy uz, not rz.
  expect_error(m + "load_cases:\n  - name: a\n    prescribed:\n      - {node: A, dof: rz, value: 0.1}\n", 14,
               {"load case 'a'", "dof rz of node 'A' is not fixed by a support"});
  expect_error(m + "report: {node: Q}\n", 11, {"report", "unknown node 'Q'"});
}

// Everything the format offers, in mm-N-s: the Structure must hold the same model in SI.
TEST(StructureYaml, FullModelInMillimetresArrivesInSI) {
  const char* yaml = R"(
units: mm-N-s
title: all features
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [1000, 0, 0]}
  - {id: B2, xyz: [1000, 0, 0]}
  - {id: C, xyz: [1000, 500, 0]}
materials:
  - {id: steel, E: 210000, nu: 0.3}
  - {id: alu, E: 70000, G: 26000}
sections:
  - {id: rod, type: circle, d: 20}
  - {id: custom, A: 100, Iy: 2000, Iz: 3000, J: 4000, Asy: 80}
beams:
  - {id: b1, nodes: [A, B], material: steel, section: rod, orientation: [0, 0, 1], theory: timoshenko,
     releases: {end2: [ry, rz]}}
  - {id: b2, nodes: [B2, C], material: alu, section: custom, theory: timoshenko}
joints:
  - id: j
    nodes: [B, B2]
    stiffness: [1000, rigid, rigid, 0, 2000, rigid]
    frame: {x: [0, 1, 0], z: [0, 0, 2]}
rigid_links:
  - {id: r, master: A, slave: C, dofs: [uz, rx]}
supports:
  - {node: A, fixed: all, frame: {x: [0, 1, 0], z: [0, 0, 1]}}
load_cases:
  - name: mixed
    loads:
      - {node: C, force: [1, 2, 3], moment: [1000, 2000, 3000]}
    prescribed:
      - {node: A, dof: ux, value: 2}
      - {node: A, dof: rz, value: 0.01}
report: {node: C}
)";
  // The rigid link's slave C would clash with nothing: A is the supported master.
  const auto r = read_structure_yaml_string(yaml, "all.yaml");
  ASSERT_TRUE(r.ok()) << r.status().message();
  const msa::Structure& s = *r;
  EXPECT_EQ(s.title(), "all features");
  ASSERT_EQ(s.nodes().size(), 4u);
  EXPECT_TRUE(s.nodes()[3].position.isApprox(Vec3(1.0, 0.5, 0.0)));

  ASSERT_EQ(s.materials().size(), 2u);
  EXPECT_DOUBLE_EQ(s.materials()[0].E, 210e9);
  EXPECT_DOUBLE_EQ(s.materials()[0].G, 210e9 / 2.6);
  EXPECT_DOUBLE_EQ(s.materials()[1].G, 26e9);

  ASSERT_EQ(s.sections().size(), 2u);
  const double d = 0.02;
  EXPECT_NEAR(s.sections()[0].A, std::numbers::pi * d * d / 4, 1e-18);
  EXPECT_NEAR(s.sections()[0].Iy, std::numbers::pi * std::pow(d, 4) / 64, 1e-22);
  EXPECT_NEAR(s.sections()[1].A, 100e-6, 1e-18);
  EXPECT_NEAR(s.sections()[1].Iy, 2000e-12, 1e-24);
  EXPECT_NEAR(s.sections()[1].Iz, 3000e-12, 1e-24);
  EXPECT_NEAR(s.sections()[1].J, 4000e-12, 1e-24);
  EXPECT_NEAR(s.sections()[1].Asy, 80e-6, 1e-18);
  EXPECT_EQ(s.sections()[1].Asz, 0.0);

  ASSERT_EQ(s.beams().size(), 2u);
  const msa::Beam& b1 = s.beams()[0];
  EXPECT_EQ(b1.node1, 0);
  EXPECT_EQ(b1.node2, 1);
  EXPECT_EQ(b1.theory, BeamTheory::kTimoshenko);
  EXPECT_TRUE(b1.orientation.isApprox(Vec3(0, 0, 1)));  // a direction: not scaled by units
  for (int i = 0; i < 12; ++i) EXPECT_EQ(b1.releases[i], i == 10 || i == 11) << i;
  EXPECT_EQ(s.beams()[1].theory, BeamTheory::kTimoshenko);
  EXPECT_EQ(s.beams()[1].material, 1);

  ASSERT_EQ(s.joints().size(), 1u);
  const msa::Joint& j = s.joints()[0];
  EXPECT_DOUBLE_EQ(j.stiffness(0), 1000.0 * 1e3);  // N/mm -> N/m
  EXPECT_EQ(j.stiffness(1), msa::kRigid);
  EXPECT_EQ(j.stiffness(3), 0.0);
  EXPECT_DOUBLE_EQ(j.stiffness(4), 2000.0 * 1e-3);  // N mm/rad -> N m/rad
  // Frame columns are its x, y = z cross x, z axes: here x = global y, z = global z, y = -global x.
  Mat3 expected;
  expected << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_TRUE(j.frame.isApprox(expected)) << j.frame;

  ASSERT_EQ(s.rigid_links().size(), 1u);
  const msa::DofMask mask = s.rigid_links()[0].mask;
  EXPECT_TRUE(!mask[0] && !mask[1] && mask[2] && mask[3] && !mask[4] && !mask[5]);

  ASSERT_EQ(s.supports().size(), 1u);
  EXPECT_EQ(s.supports()[0].fixed, msa::kAllDofs);
  EXPECT_TRUE(s.supports()[0].frame.isApprox(expected));

  ASSERT_EQ(s.load_cases().size(), 1u);
  const msa::LoadCase& lc = s.load_cases()[0];
  ASSERT_EQ(lc.loads.size(), 1u);
  Vec6 w;
  w << 1, 2, 3, 1, 2, 3;  // moments N mm -> N m
  EXPECT_TRUE(lc.loads[0].wrench.isApprox(w)) << lc.loads[0].wrench.transpose();
  ASSERT_EQ(lc.prescribed.size(), 2u);
  EXPECT_DOUBLE_EQ(lc.prescribed[0].value, 2e-3);  // mm -> m
  EXPECT_DOUBLE_EQ(lc.prescribed[1].value, 0.01);  // rad stays rad
  ASSERT_TRUE(s.report_node().has_value());
  EXPECT_EQ(*s.report_node(), 3);
}

}  // namespace
}  // namespace kinestat::io
