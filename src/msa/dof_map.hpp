// Reduction of the 6N nodal dofs to the independent unknowns: u = C q + u0.
// C removes supported dofs (also in a rotated support frame) and eliminates rigid links and the rigid
// components of joints (master-slave elimination, exact, no penalty); u0 holds prescribed displacements.
// Ties that close a loop of ties (a node tied twice, or a cycle; the legs of a robot rigid but for
// their joints) are linear constraints on the other ties' unknowns, eliminated after them: their
// independent rows solved for as many unknowns (a pivoted LU), the dependent ones dropped.
#pragma once

#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/structure.hpp"
#include "kinestat/solver/linear_solver.hpp"

namespace kinestat::msa {

struct ReducedDof {
  int node = -1;
  int component = 0;              // 0..5 in `frame`
  Mat3 frame = Mat3::Identity();  // axes in which the component is measured (support or tie frame)
};

struct DofMap {
  solver::SparseMatrix C;            // 6N x n_free
  std::vector<ReducedDof> reduced;   // what each column of C is
  std::vector<bool> supported_node;  // node has a support
  std::vector<int> slave_of_tie;     // per node: index into ties, or -1
  struct Tie {
    int master, slave;
    DofMask mask;
    Mat3 frame;
    int joint = -1;      // the joint it comes from, or -1 (a rigid link)
    std::string source;  // that item's source ("file:line"), for messages
  };
  std::vector<Tie> ties;
  // The loops' independent constraints: tie ties[tie]'s component `component` (in its frame), whose
  // rows over the tree's unknowns (C before the loops' elimination: tree_C) are loop_G. Their forces
  // (Lagrange multipliers) are recovered from the residual (loop_forces) for reactions and joint forces.
  struct LoopRow {
    int tie = -1, component = 0;
  };
  std::vector<LoopRow> loop_rows;
  solver::SparseMatrix tree_C;
  MatX loop_G;
  int num_free() const { return static_cast<int>(C.cols()); }
};

StatusOr<DofMap> build_dof_map(const Structure& s);

// A tie's rigid transfer from its master's motion to its slave's point (core/frame.hpp), A, and the
// tie itself in global axes, R P_tied R^T A: u_s = that u_m + the slave's own free components.
Mat6 tie_transfer(const Structure& s, const DofMap::Tie& tie);
Mat6 tied_transfer(const Structure& s, const DofMap::Tie& tie);

// The trees' slaves (nodes with slave_of_tie >= 0), masters before their slaves (by depth).
std::vector<int> tied_nodes_by_depth(const DofMap& map);

// The residual K u - f (6N) with the loops' constraint forces taken out, and those forces (one per
// loop_rows entry, in its tie's frame: the force on the slave); the residual as it is without loops.
VecX remove_loop_forces(const Structure& s, const DofMap& map, const VecX& residual, VecX& forces);

// Prescribed nodal displacements of a load case (6N, global axes): at the supported nodes, and
// carried by the ties to their slaves (a slave's tied components follow its master's prescribed
// motion) and by the loops' constraints (u0 + tree_C dq with loop_G dq = -(the constraints at u0)),
// so that u = C q + u0 satisfies every tie for any q.
VecX prescribed_displacements(const Structure& s, const DofMap& map, const LoadCase& lc);

// Nodal loads of a load case (6N, global axes).
VecX nodal_loads(const Structure& s, const LoadCase& lc);

}  // namespace kinestat::msa
