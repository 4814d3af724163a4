// Density, gravity and member loads in structure files: every key read, converted from mm-N-s to the
// same SI model, and bad input named by file, line and item.
#include <gtest/gtest.h>

#include <string>

#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::io {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

// One frame with every new key, in SI and in mm-N-s (lengths x1000, forces per length / 1000,
// moments x1000, MPa, t/mm^3, mm/s^2).
constexpr const char* kSI = R"(units: SI
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [2, 0, 0]}
  - {id: C, xyz: [2, 1.5, 0]}
materials:
  - {id: steel, E: 210e9, nu: 0.3, density: 7850}
sections:
  - {id: bar, type: rectangle, b: 0.04, h: 0.08}
beams:
  - {id: b1, nodes: [A, B], material: steel, section: bar}
  - {id: b2, nodes: [B, C], material: steel, section: bar, theory: timoshenko}
supports:
  - {node: A, fixed: all}
  - {node: C, fixed: all}
load_cases:
  - name: all
    gravity: [0, 0, -9.81]
    member_loads:
      - {beam: b1, type: uniform, w: [0, 0, -500], axes: global}
      - {beam: b1, type: trapezoidal, a: 0.5, b: 1.5, w1: [0, 100, 0], w2: [0, 300, 0]}
      - {beam: b2, type: point, a: 0.75, force: [0, 0, -1000], moment: [0, 50, 0], axes: local}
      - {beam: b2, type: temperature, alpha: 1.2e-5, hy: 0.04, hz: 0.08, dT: 20, dTy: 5, dTz: -10}
)";

constexpr const char* kMm = R"(units: mm-N-s
nodes:
  - {id: A, xyz: [0, 0, 0]}
  - {id: B, xyz: [2000, 0, 0]}
  - {id: C, xyz: [2000, 1500, 0]}
materials:
  - {id: steel, E: 210000, nu: 0.3, density: 7.85e-9}
sections:
  - {id: bar, type: rectangle, b: 40, h: 80}
beams:
  - {id: b1, nodes: [A, B], material: steel, section: bar}
  - {id: b2, nodes: [B, C], material: steel, section: bar, theory: timoshenko}
supports:
  - {node: A, fixed: all}
  - {node: C, fixed: all}
load_cases:
  - name: all
    gravity: [0, 0, -9810]
    member_loads:
      - {beam: b1, type: uniform, w: [0, 0, -0.5], axes: global}
      - {beam: b1, type: trapezoidal, a: 500, b: 1500, w1: [0, 0.1, 0], w2: [0, 0.3, 0]}
      - {beam: b2, type: point, a: 750, force: [0, 0, -1000], moment: [0, 50000, 0], axes: local}
      - {beam: b2, type: temperature, alpha: 1.2e-5, hy: 40, hz: 80, dT: 20, dTy: 5, dTz: -10}
)";

TEST(MemberLoadsYaml, EveryKeyIsReadInSI) {
  const auto r = read_structure_yaml_string(kSI, "si.yaml");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->materials()[0].density, 7850.0);
  const msa::LoadCase& lc = r->load_cases()[0];
  EXPECT_EQ(lc.gravity, Vec3(0, 0, -9.81));
  ASSERT_EQ(lc.member_loads.size(), 4u);
  const msa::MemberLoad& u = lc.member_loads[0];
  EXPECT_EQ(u.type, msa::MemberLoadType::kUniform);
  EXPECT_TRUE(u.global_axes);
  EXPECT_EQ(u.beam, 0);
  EXPECT_EQ(u.w1, Vec3(0, 0, -500));
  EXPECT_EQ(u.source, "si.yaml:20");
  const msa::MemberLoad& t = lc.member_loads[1];
  EXPECT_EQ(t.type, msa::MemberLoadType::kTrapezoidal);
  EXPECT_FALSE(t.global_axes);  // local by default
  EXPECT_EQ(t.a, 0.5);
  EXPECT_EQ(t.b, 1.5);
  EXPECT_EQ(t.w1, Vec3(0, 100, 0));
  EXPECT_EQ(t.w2, Vec3(0, 300, 0));
  const msa::MemberLoad& p = lc.member_loads[2];
  EXPECT_EQ(p.type, msa::MemberLoadType::kPoint);
  EXPECT_EQ(p.beam, 1);
  EXPECT_EQ(p.a, 0.75);
  EXPECT_EQ(p.force, Vec3(0, 0, -1000));
  EXPECT_EQ(p.moment, Vec3(0, 50, 0));
  const msa::MemberLoad& h = lc.member_loads[3];
  EXPECT_EQ(h.type, msa::MemberLoadType::kTemperature);
  EXPECT_EQ(h.thermal.alpha, 1.2e-5);
  EXPECT_EQ(h.thermal.hy, 0.04);
  EXPECT_EQ(h.thermal.hz, 0.08);
  EXPECT_EQ(h.thermal.dT, 20.0);
  EXPECT_EQ(h.thermal.dTy, 5.0);
  EXPECT_EQ(h.thermal.dTz, -10.0);
}

TEST(MemberLoadsYaml, MillimetreFileGivesTheSameModelAndResults) {
  const auto si = read_structure_yaml_string(kSI, "si.yaml");
  const auto mm = read_structure_yaml_string(kMm, "mm.yaml");
  ASSERT_TRUE(si.ok()) << si.status().message();
  ASSERT_TRUE(mm.ok()) << mm.status().message();
  // Converted values agree to the round-off of one multiplication (7.85e-9 * 1e12 = 7850 + 1 ulp).
  EXPECT_NEAR(mm->materials()[0].density, 7850.0, 1e-12 * 7850.0);
  const msa::LoadCase &a = si->load_cases()[0], &b = mm->load_cases()[0];
  EXPECT_TRUE(b.gravity.isApprox(a.gravity, 1e-15));
  for (size_t i = 0; i < a.member_loads.size(); ++i) {
    const msa::MemberLoad &x = a.member_loads[i], &y = b.member_loads[i];
    EXPECT_NEAR(y.a, x.a, 1e-15 * x.a) << i;
    EXPECT_NEAR(y.b, x.b, 1e-15 * x.b) << i;
    EXPECT_TRUE(y.w1.isApprox(x.w1, 1e-15) || (x.w1.isZero(0) && y.w1.isZero(0))) << i;
    EXPECT_TRUE(y.w2.isApprox(x.w2, 1e-15) || (x.w2.isZero(0) && y.w2.isZero(0))) << i;
    EXPECT_TRUE(y.moment.isApprox(x.moment, 1e-15) || (x.moment.isZero(0) && y.moment.isZero(0))) << i;
    EXPECT_NEAR(y.thermal.hy, x.thermal.hy, 1e-15 * x.thermal.hy) << i;
    EXPECT_NEAR(y.thermal.hz, x.thermal.hz, 1e-15 * x.thermal.hz) << i;
  }
  // Solved, both give the same displacements and end forces (relative to the largest, round-off).
  const msa::Solution s1 = msa::solve(*si), s2 = msa::solve(*mm);
  ASSERT_TRUE(s1.status.ok()) << s1.status.message();
  ASSERT_TRUE(s2.status.ok()) << s2.status.message();
  const auto &c1 = s1.cases[0], &c2 = s2.cases[0];
  const Vec6 d1 = c1.displacement[1], d2 = c2.displacement[1];
  EXPECT_GT(d1.head<3>().norm(), 1e-6);  // the loads do move node B
  EXPECT_LT((d1 - d2).norm(), 1e-10 * d1.norm());
  for (int e = 0; e < 2; ++e)
    EXPECT_LT((c1.beam_end_forces[e] - c2.beam_end_forces[e]).norm(), 1e-10 * c1.beam_end_forces[e].norm()) << e;
  EXPECT_LT(c1.equilibrium_error, 1e-13);
}

void expect_error(const std::string& yaml, int line, std::initializer_list<const char*> parts) {
  const auto r = read_structure_yaml_string(yaml, "model.yaml");
  ASSERT_FALSE(r.ok()) << yaml;
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  const std::string& m = r.status().message();
  EXPECT_EQ(m.rfind("model.yaml:" + std::to_string(line) + ": ", 0), 0u) << m;
  for (const char* p : parts) expect_contains(m, p);
}

// A 1 m beam; a member load written after it is on line 16.
std::string with_member_load(const std::string& entry, const std::string& units = "SI",
                             const std::string& material = "{id: steel, E: 210e9, nu: 0.3}") {
  return "units: " + units +
         "\n"                             // 1
         "nodes:\n"                       // 2
         "  - {id: A, xyz: [0, 0, 0]}\n"  // 3
         "  - {id: B, xyz: [1, 0, 0]}\n"  // 4
         "materials:\n"                   // 5
         "  - " +
         material +
         "\n"                                                           // 6
         "sections:\n"                                                  // 7
         "  - {id: rod, type: circle, d: 0.02}\n"                       // 8
         "beams:\n"                                                     // 9
         "  - {id: b, nodes: [A, B], material: steel, section: rod}\n"  // 10
         "supports:\n"                                                  // 11
         "  - {node: A, fixed: all}\n"                                  // 12
         "load_cases:\n"                                                // 13
         "  - name: c\n"                                                // 14
         "    member_loads:\n"                                          // 15
         "      - " +
         entry + "\n";  // 16
}

TEST(MemberLoadsYaml, BadInputNamesTheLineTheItemAndTheFix) {
  expect_error(
      with_member_load("{beam: b, type: uniform, w: [0, 0, -1], at: 3}"), 16,
      {"load case 'c': the member load on beam 'b'", "unknown key 'at'; allowed keys are: beam, type, axes, w"});
  expect_error(with_member_load("{beam: q, type: uniform, w: [0, 0, -1]}"), 16,
               {"load case 'c' member load", "unknown beam 'q'; define it under beams"});
  expect_error(with_member_load("{beam: b, type: point, a: 1.5, force: [0, 0, -1]}"), 16,
               {"the member load on beam 'b'", "a = 1.5 m lies beyond the end of the beam (length 1 m)"});
  expect_error(with_member_load("{beam: b, type: point, a: 1500, force: [0, 0, -1]}", "mm-N-s",
                                "{id: steel, E: 210000, nu: 0.3}"),
               16, {"a = 1500 mm lies beyond the end of the beam (length 1 mm)"});
  expect_error(with_member_load("{beam: b, type: trapezoidal, a: 0.8, b: 0.2, w1: [0, 0, 1], w2: [0, 0, 1]}"), 16,
               {"give a < b"});
  expect_error(with_member_load("{beam: b, type: linear, w: [0, 0, -1]}"), 16,
               {"unknown member load type 'linear'; use uniform, trapezoidal, point or temperature"});
  expect_error(with_member_load("{beam: b, type: uniform, w: [0, 0, -1], axes: beam}"), 16,
               {"unknown axes 'beam'; use local or global"});
  expect_error(with_member_load("{beam: b, type: temperature, alpha: 1e-5, dTy: 10}"), 16,
               {"missing required key 'hy'"});
  expect_error(with_member_load("{beam: b, type: temperature, alpha: 1e-5, hy: 0.02}"), 16, {"needs dT"});
  expect_error(with_member_load("{beam: b, type: point, a: 0.5}"), 16, {"needs 'force"});
  // Density: negative, and an SI value written in a mm-N-s file (t/mm^3).
  expect_error(with_member_load("{beam: b, type: uniform, w: [0, 0, -1]}", "SI",
                                "{id: steel, E: 210e9, nu: 0.3, density: -7850}"),
               6, {"material 'steel'", "'density' = -7850 kg/m^3 must not be negative"});
  expect_error(with_member_load("{beam: b, type: uniform, w: [0, 0, -1]}", "mm-N-s",
                                "{id: steel, E: 210000, nu: 0.3, density: 7850}"),
               6, {"'density' = 7850 t/mm^3 is too large for a density"});
  // Gravity: a list of three accelerations.
  expect_error("nodes:\n  - {id: A, xyz: [0, 0, 0]}\nload_cases:\n  - name: g\n    gravity: [0, -9.81]\n", 5,
               {"load case 'g'", "'gravity' must be a list of three numbers"});
}

}  // namespace
}  // namespace kinestat::io
