// Joint element: a 6-dof spring between two coincident nodes (Gonçalves et al. 2010, eq. (1), (5)).
// Stiffnesses are in the joint's own frame: kt (N/m) along its x, y, z and kr (N m/rad) about them.
// 0 releases a component (a revolute joint about local z has kr_z = 0). A rigid component is
// +infinity here; it carries no spring term and is enforced as an exact constraint by the method
// that assembles the joint (see msa/constraints.hpp).
#pragma once

#include "kinestat/core/types.hpp"

namespace kinestat {

// 12x12 global stiffness [kc -kc; -kc kc], kc = R6 (diag(k) + coupling) R6^T, with R the joint
// frame's axes (columns) in global coordinates. Infinite (rigid) components contribute nothing.
// `coupling`: the off-diagonal terms of a spring that couples its components in the joint frame (a
// link's 6x6 from FEA), zero on the diagonal and in the rows and columns of rigid components.
Mat12 joint_global_stiffness(const Mat3& frame, const Vec6& k, const Mat6& coupling = Mat6::Zero());

// The 6x6 kc block alone (global coordinates).
Mat6 joint_spring_block(const Mat3& frame, const Vec6& k, const Mat6& coupling = Mat6::Zero());

}  // namespace kinestat
