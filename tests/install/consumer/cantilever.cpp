// A steel cantilever built in code and solved by an installed kinestat: the tip deflection must be
// P L^3 / (3 E I). Exit status 0 when it is (to 1e-9), 1 otherwise. The README's "Use as a library".
#include <cmath>
#include <cstdio>

#include "kinestat/msa/static_analysis.hpp"

int main() {
  using namespace kinestat;
  const double L = 1.0, P = 1000.0, E = 210e9;  // m, N, Pa
  msa::Structure s;
  const int root = s.add_node("root", Vec3(0, 0, 0));
  const int tip = s.add_node("tip", Vec3(L, 0, 0));
  const int steel = s.add_material(Material::from_E_nu("steel", E, 0.3));
  const int bar = s.add_section(rectangle_section(0.02, 0.04));  // b along local y = global y, h along z
  s.add_beam({.id = "arm", .node1 = root, .node2 = tip, .material = steel, .section = bar});
  s.add_support({.node = root});  // every dof fixed
  s.add_load_case({.name = "tip down", .loads = {{.node = tip, .wrench = Vec6(0, 0, -P, 0, 0, 0)}}});

  const msa::Solution sol = msa::solve(s);
  if (!sol.status.ok()) {
    std::fprintf(stderr, "%s\n", sol.status.message().c_str());
    return 1;
  }
  const double w = sol.cases[0].displacement[tip](2);
  const double expected = -P * L * L * L / (3 * E * s.sections()[bar].Iy);
  std::printf("tip deflection %.6e m, P L^3 / (3 E I) = %.6e m\n", w, expected);
  return std::abs(w - expected) <= 1e-9 * std::abs(expected) ? 0 : 1;
}
