// MSA results for ParaView: one VTK XML unstructured grid (.vtu) per load case and a .pvd
// collection that steps through them. Arrays and units: docs/results-json.md, section "VTK output".
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
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

}  // namespace kinestat::io
