// MSA results for ParaView: one VTK XML unstructured grid (.vtu) per load case and a .pvd
// collection that steps through them. Arrays and units: docs/results-json.md, section "VTK output".
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::io {

// Element types in the "element_type" cell array.
inline constexpr int kVtkBeam = 1;
inline constexpr int kVtkJoint = 2;
inline constexpr int kVtkRigidLink = 3;

// Writes DIR/BASENAME_caseN.vtu (N = 1, 2, ... in load-case order) and DIR/BASENAME.pvd. Points
// are the nodes, cells the beams, joints and rigid links. A solution without load cases (a singular
// structure) gives DIR/BASENAME_undeformed.vtu with the free motions as point data
// "free_motion_1", ... so ParaView shows what moves. DIR is created if missing. The paths written
// are appended to `written` when it is not null. kInvalidInput when a file cannot be written;
// kInternal when the Solution's sizes do not match the Structure.
Status write_vtk(const msa::Structure& s, const msa::Solution& sol, const std::string& dir, const std::string& basename,
                 std::vector<std::string>* written);

// Internal-force diagrams (`kinestat solve --stations N --vtk DIR`): DIR/BASENAME_diagram_caseN.vtu
// per load case and DIR/BASENAME_diagram.pvd. Each beam is a polyline through its stations on the
// undeformed axis; point arrays: the scalars N, Vy, Vz, T, My, Mz (N, N m, beam-local, as
// msa::BeamStations), "displacement" (m, global), and the vectors "Mz_diagram" = Mz e_y and
// "My_diagram" = My e_z (N m along the local axis the moment bends towards): Warp By Vector with a
// small scale factor draws the bending-moment diagram beside each beam (field data "warp_factor":
// the largest moment drawn as a tenth of the model's size). `stations` is [case][beam] of
// msa::all_beam_stations for this solution.
Status write_beam_diagrams_vtk(const msa::Structure& s, const msa::Solution& sol,
                               const std::vector<std::vector<msa::BeamStations>>& stations, const std::string& dir,
                               const std::string& basename, std::vector<std::string>* written);

// A mode shape to draw (a buckling mode, a vibration mode): per node, global, translations and
// rotations; `name` is shown by ParaView (e.g. "mode 1: lambda = 2.47").
struct VtkModeShape {
  std::string name;
  std::vector<Vec6> shape;
};

// Writes DIR/BASENAME_modeK.vtu (K = 1, 2, ...) with the model's geometry and point arrays
// "mode_shape" (translation, the active vectors) and "mode_rotation", and DIR/BASENAME.pvd with one
// time step per mode. Shapes are dimensionless ratios (their scale is the caller's normalization,
// said in its "units" field data). Paths appended to `written`; kInvalidInput when a file cannot be
// written or a shape's node count is not the structure's.
Status write_mode_shapes_vtk(const msa::Structure& s, const std::vector<VtkModeShape>& modes, const std::string& dir,
                             const std::string& basename, const std::string& shape_unit,
                             std::vector<std::string>* written);

}  // namespace kinestat::io
