// Nodal masses in structure files (`masses:`): read in SI and converted from mm-N-s (t, t mm^2), and
// bad input named by line and item.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/io/structure_yaml.hpp"

namespace kinestat::io {
namespace {

std::string model(const std::string& units, const std::string& masses) {
  return "units: " + units + R"(
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [1, 0, 0]}
materials:
  - {id: steel, E: 210000, nu: 0.3}   # read as MPa in the mm-N-s file, as 210 kPa in SI (both valid)
sections:
  - {id: bar, type: rectangle, b: 0.02, h: 0.03}
beams:
  - {id: arm, nodes: [A, B], material: steel, section: bar}
supports:
  - {node: A, fixed: all}
masses:
)" + masses;
}

TEST(NodalMassesYaml, ReadInSIAndMillimetres) {
  auto si = read_structure_yaml_string(model("SI", "  - {node: B, mass: 12.5, inertia: [0.1, 0.2, 0.3]}\n"), "si");
  ASSERT_TRUE(si.ok()) << si.status().message();
  ASSERT_EQ(si->masses().size(), 1u);
  EXPECT_EQ(si->masses()[0].node, 1);
  EXPECT_DOUBLE_EQ(si->masses()[0].mass, 12.5);
  EXPECT_DOUBLE_EQ(si->masses()[0].inertia(2), 0.3);
  // mm-N-s: mass in t (N s^2/mm = 1000 kg), inertia in t mm^2 (= 1e-3 kg m^2). Coordinates are in mm
  // there, but the masses do not depend on them.
  auto mm =
      read_structure_yaml_string(model("mm-N-s", "  - {node: B, mass: 0.0125, inertia: [100, 200, 300]}\n"), "mm");
  ASSERT_TRUE(mm.ok()) << mm.status().message();
  EXPECT_NEAR(mm->masses()[0].mass, 12.5, 1e-12);
  EXPECT_NEAR(mm->masses()[0].inertia(0), 0.1, 1e-15);
  EXPECT_NEAR(mm->masses()[0].inertia(2), 0.3, 1e-15);
}

TEST(NodalMassesYaml, BadInputIsNamed) {
  auto r = read_structure_yaml_string(model("SI", "  - {node: B, mass: -1}\n"), "f.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("mass at node 'B'"), std::string::npos) << r.status().message();
  r = read_structure_yaml_string(model("SI", "  - {node: B}\n"), "f.yaml");
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("needs 'mass: M'"), std::string::npos) << r.status().message();
  r = read_structure_yaml_string(model("SI", "  - {node: Z, mass: 1}\n"), "f.yaml");
  EXPECT_FALSE(r.ok());
  r = read_structure_yaml_string(model("SI", "  - {node: B, mass: 1, inertia: [0, -1, 0]}\n"), "f.yaml");
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace kinestat::io
