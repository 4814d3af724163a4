// The benchmark bar shared by bench_fea and export_calculix (so CalculiX solves exactly kinestat's
// mesh): 200 x 20 x 30 mm, n quadratic-tet cells across the 20 mm side, clamped at x = 0, rigid
// reference coupling of the x = 0.2 m face to a node at (0.2, 0, 0) m.
#pragma once

#include "fea/elasticity_assembly.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::bench {

inline fea::TetMesh bar(int n) {
  return fea::to_quadratic(
      fea::make_box_mesh(Vec3(0, -0.01, -0.015), Vec3(0.2, 0.01, 0.015), 10 * n, n, (3 * n + 1) / 2));
}

inline fea::DofMap clamped_bar_map(const fea::TetMesh& mesh) {
  return fea::make_dof_map(mesh, fea::select_nodes(mesh, fea::Region::plane(Vec3::Zero(), Vec3::UnitX())),
                           fea::select_nodes(mesh, fea::Region::plane(Vec3(0.2, 0, 0), Vec3::UnitX())),
                           Vec3(0.2, 0, 0));
}

}  // namespace kinestat::bench
