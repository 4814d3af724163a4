// Orthoglide workspaces for ParaView (VTK XML unstructured grids, .vtu). Coordinates in m; the
// transmission factors, condition number and manipulability are dimensionless. Each file carries
// its units as the field data "units" ("coordinates: m", "rho: m", "mu_min: -", ...).
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"

namespace kinestat::io {

// Writes, for design strategy N (DIR is created if missing):
//  DIR/orthoglide_sN_joint_workspace.vtu: the joint-bounded workspace W_rho as the image of a regular
//    n x n x n grid of joint coordinates: hexahedral cells in Cartesian space (use Slice or Clip in
//    ParaView), with point data "mu_min", "mu_max" (velocity transmission factors),
//    "condition_number", "manipulability" and "rho" (joint coordinates, m). Joint points with no
//    assembly, at a singularity or beyond the software limit sum(rho) are left out with their cells.
//  DIR/orthoglide_sN_cube.vtu: the cubic workspace as one hexahedron with the same point data at its
//    eight vertices.
// The paths written are appended to `written` when it is not null. kInvalidInput when n < 2, n^3 exceeds
// `max_points` (checked before anything is allocated: ~150 bytes per point), or a file cannot be written.
Status write_orthoglide_workspace_vtk(const mechanisms::OrthoglideDesign& d, int n, const std::string& dir,
                                      std::vector<std::string>* written, double max_points = 2e6);

}  // namespace kinestat::io
