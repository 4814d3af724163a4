#include "kinestat/elements/joint_element.hpp"

#include <cmath>

#include "kinestat/core/frame.hpp"

namespace kinestat {

Mat6 joint_spring_block(const Mat3& frame, const Vec6& k) {
  Vec6 finite = k;
  for (int i = 0; i < 6; ++i)
    if (std::isinf(finite(i))) finite(i) = 0.0;
  const Mat6 R = rotation6(frame);
  return R * finite.asDiagonal() * R.transpose();
}

Mat12 joint_global_stiffness(const Mat3& frame, const Vec6& k) {
  const Mat6 kc = joint_spring_block(frame, k);
  Mat12 K;
  K << kc, -kc, -kc, kc;
  return K;
}

}  // namespace kinestat
