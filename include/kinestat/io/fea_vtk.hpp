// VTK XML unstructured grids (.vtu, readable in ParaView) of a link analysed by FEA: the mesh in
// its undeformed position (m) with, per unit load case, the node displacements (point vector
// "displacement", m per N or per N m: use ParaView's "Warp By Vector" to see the deformed link)
// and the element von Mises stress at the centroid (cell scalar "von_mises", Pa per N or N m). Each
// file carries its units as the field data "units" and its load case as "load_case".
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::io {

// Names of the six unit load cases, in compliance-column order: "Fx", "Fy", "Fz", "Mx", "My", "Mz".
const char* link_load_case_name(int k);

// One file for load case k (0..5). Needs the fields (LinkStiffnessOptions::keep_fields).
Status write_link_vtu(const std::string& path, const fea::TetMesh& mesh, const fea::LinkStiffness& result, int k);

// The six files DIR/PREFIX_Fx.vtu ... PREFIX_Mz.vtu and DIR/PREFIX.pvd, which groups them (timesteps
// 0..5 in that order) so that ParaView's time slider steps through the load cases. DIR is created;
// the paths are appended to `written`.
Status write_link_vtu_files(const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh,
                            const fea::LinkStiffness& result, std::vector<std::string>* written);

// The link's vibration modes (LinkStiffnessOptions::modes with keep_fields): one file per mode with
// the point vector "mode_shape" (mass-normalized, m/sqrt(kg): Warp By Vector with the file's
// "warp_factor") and the field data "frequency_Hz" and "mode" (what the mode is), written as
// DIR/PREFIX_modes_modeK.vtu (K = 1, 2, ...) and DIR/PREFIX_modes.pvd, which groups them (timesteps
// 0, 1, ... in ascending frequency) as `kinestat modes` does for frames. DIR is created; the paths are
// appended to `written`.
Status write_link_mode_vtu(const std::string& path, const fea::TetMesh& mesh, const fea::LinkStiffness& result, int k);
Status write_link_mode_vtu_files(const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh,
                                 const fea::LinkStiffness& result, std::vector<std::string>* written);

}  // namespace kinestat::io
