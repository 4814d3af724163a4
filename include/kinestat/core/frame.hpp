// Rotations and frames: local element axes, 6-dof transformation blocks, rigid-body transfer.
#pragma once

#include <string>

#include "kinestat/core/types.hpp"

namespace kinestat {

// Skew-symmetric matrix [v]x such that [v]x w = v x w.
Mat3 skew(const Vec3& v);

// Local axes of a line element from node 1 to node 2. Columns of the result are the local
// x (along the element), y and z axes in global coordinates. The local x-y plane contains
// `orientation` (a vector not parallel to the element, as in Frame3DD / OpenSees vecxz is for z).
// Returns false when the element has zero length or orientation is parallel to it.
bool element_axes(const Vec3& p1, const Vec3& p2, const Vec3& orientation, Mat3& axes);

// A default orientation vector for an element along `dir`: global z, or global y when the element
// is (nearly) parallel to z. Gives local z = global z for elements in the x-y plane.
Vec3 default_orientation(const Vec3& dir);

// 6x6 block-diagonal rotation diag(R, R) acting on (translation, rotation) of one node.
Mat6 rotation6(const Mat3& R);

// Rigid-body transfer: the motion (u, theta) of a point at `offset` from a reference point that
// moves by (u_ref, theta_ref) is A * (u_ref, theta_ref), A = [I, -[offset]x; 0, I].
Mat6 rigid_transfer(const Vec3& offset);

// A direction in words for messages: "+y" when it is (within 0.1 %) an axis, else "(0.707, 0.707, 0.000)".
std::string direction_words(const Vec3& v);

// Rotation matrix about a unit axis by an angle (rad).
Mat3 axis_angle(const Vec3& axis, double angle);

}  // namespace kinestat
