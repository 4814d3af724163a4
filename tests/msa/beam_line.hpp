// Shared by the msa tests: steel with a density, and a straight line of n beams along x (or `dir`)
// from 0 to L (nodes "0".."n", beams "b0".., no supports), which the statics, load, station, buckling
// and mode tests build their cases on.
#pragma once

#include <string>

#include <fmt/format.h>

#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {

inline const Material kSteel{"steel", 2.1e11, 0.81e11, 7850.0};

inline Structure straight(double L, int n, const Section& sec, BeamTheory th = BeamTheory::kEulerBernoulli,
                          const Material& mat = kSteel, const Vec3& dir = Vec3::UnitX()) {
  Structure s;
  const int m = s.add_material(mat);
  const int c = s.add_section(sec);
  for (int i = 0; i <= n; ++i) s.add_node(std::to_string(i), dir.normalized() * (L * i / n));
  for (int i = 0; i < n; ++i) {
    Beam b;
    b.id = fmt::format("b{}", i);
    b.node1 = i;
    b.node2 = i + 1;
    b.material = m;
    b.section = c;
    b.theory = th;
    s.add_beam(b);
  }
  return s;
}

// One 1 m beam 'hinged' clamped at node 0, its second end released about local z, pushed by 1 kN
// along its axis: the end releases that buckling and the second-order solve refuse.
inline Structure hinged_beam(const Section& sec) {
  Structure s;
  Beam b;
  b.id = "hinged";
  b.material = s.add_material(kSteel);
  b.section = s.add_section(sec);
  b.node1 = s.add_node("a", Vec3(0, 0, 0));
  b.node2 = s.add_node("b", Vec3(1, 0, 0));
  b.releases[11] = true;
  s.add_beam(b);
  s.add_support({0, kAllDofs, Mat3::Identity()});
  LoadCase lc{.name = "axial"};
  lc.loads.push_back({1, Vec6::Unit(0) * -1000.0});
  s.add_load_case(lc);
  return s;
}

}  // namespace kinestat::msa
