// Shared by the msa tests: steel with a density, one beam between two nodes, and a straight line of n
// beams along x (or `dir`) from 0 to L (nodes "0".."n", beams "b0".., no supports), which the
// statics, load, station, buckling, mode, singularity and tie tests build their cases on.
#pragma once

#include <string>
#include <utility>

#include <fmt/format.h>

#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {

inline const Material kSteel{"steel", 2.1e11, 0.81e11, 7850.0};

// A beam `id` from node1 to node2 of the structure's material and section indices, the rest default.
inline Beam make_beam(std::string id, int node1, int node2, int material, int section) {
  Beam b;
  b.id = std::move(id);
  b.node1 = node1;
  b.node2 = node2;
  b.material = material;
  b.section = section;
  return b;
}

// released_ends: the first beam's bending rotations released at node 0 and the last one's at node n
// (local ry, rz), so that clamped end nodes make a pinned-pinned line (pinned_by_releases).
inline Structure straight(double L, int n, const Section& sec, BeamTheory th = BeamTheory::kEulerBernoulli,
                          const Material& mat = kSteel, bool released_ends = false, const Vec3& dir = Vec3::UnitX()) {
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
    if (released_ends && i == 0) b.releases[4] = b.releases[5] = true;
    if (released_ends && i == n - 1) b.releases[10] = b.releases[11] = true;
    s.add_beam(b);
  }
  return s;
}

// A pinned-pinned line made by end releases: straight(..., released_ends = true) with node 0 clamped
// and node n clamped but free along x (the axis), so the end rotations are the beams' released dofs.
inline Structure pinned_by_releases(double L, int n, const Section& sec, const Material& mat = kSteel) {
  Structure s = straight(L, n, sec, BeamTheory::kEulerBernoulli, mat, true);
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_support({n, {false, true, true, true, true, true}, Mat3::Identity()});
  return s;
}

}  // namespace kinestat::msa
