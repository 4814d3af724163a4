// The beam's mass matrix (elements/beam_element.hpp): symmetry, the beam's mass under a rigid
// translation, definiteness. Its frequencies against closed forms: tests/msa/modes_test.cpp.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {
namespace {

TEST(BeamMass, ConsistentIsSymmetricPositiveDefiniteWithTheBeamsMass) {
  const Material m{"steel", 2.1e11, 0.81e11, 7850.0};
  const Section sec = rectangle_section(0.02, 0.03);
  const double L = 0.7, mass = m.density * sec.A * L;
  for (bool lumped : {false, true}) {
    const Mat12 M = beam_local_mass(m, sec, L, lumped);
    EXPECT_EQ((M - M.transpose()).norm(), 0.0);
    // A rigid translation carries the whole mass rho A L (both forms, to round-off).
    for (int d = 0; d < 3; ++d) {
      Vec12 r = Vec12::Zero();
      r(d) = r(6 + d) = 1.0;
      EXPECT_NEAR(r.dot(M * r), mass, 1e-14 * mass) << d;
    }
    Eigen::SelfAdjointEigenSolver<Mat12> eig(M);
    if (!lumped) {
      EXPECT_GT(eig.eigenvalues()(0), 0.0);  // positive definite
    } else {
      EXPECT_GE(eig.eigenvalues()(0), 0.0);  // no mass on the bending rotations
    }
  }
}

}  // namespace
}  // namespace kinestat
