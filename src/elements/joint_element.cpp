#include "kinestat/elements/joint_element.hpp"

#include <cmath>

#include "kinestat/core/frame.hpp"

namespace kinestat {

Mat6 joint_spring_block(const Mat3& frame, const Vec6& k, const Mat6& coupling) {
  Mat6 local = coupling;
  for (int i = 0; i < 6; ++i) local(i, i) = std::isinf(k(i)) ? 0.0 : k(i);
  const Mat6 R = rotation6(frame);
  return R * local * R.transpose();
}

Mat12 joint_global_stiffness(const Mat3& frame, const Vec6& k, const Mat6& coupling) {
  const Mat6 kc = joint_spring_block(frame, k, coupling);
  Mat12 K;
  K << kc, -kc, -kc, kc;
  return K;
}

}  // namespace kinestat
