// kinestat — core numeric types. SI units throughout (m, N, rad, Pa) unless a file declares otherwise.
#pragma once

#include <Eigen/Dense>

namespace kinestat {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;

// Six dofs per node, ordered ux, uy, uz, rx, ry, rz (translations then rotations).
inline constexpr int kDofsPerNode = 6;

// Name of a nodal dof, for messages: "ux", ..., "rz".
const char* dof_name(int dof);

}  // namespace kinestat
