// kinestat example 2: a posture sweep of the five-bar with one reused workspace.
//
// Run: build/examples/ex2_five_bar_sweep
//
// The 5R planar parallel robot of Gonçalves et al. 2010 (links 0.1 m, steel rods of 5 mm, joint
// springs 2e11): its stiffness changes with the posture, so a designer evaluates it over a grid of
// input angles. Each posture is a new msa::Structure (same topology, new geometry); all of them are
// solved with ONE msa::Workspace, which keeps the sparse Cholesky object: the symbolic analysis
// (ordering, elimination tree) of the first posture is reused by all others, because the pattern of
// the reduced stiffness matrix depends on the topology only. The sweep covers theta1 = 50..80 deg and
// theta2 = 60..90 deg in 1 deg steps. On the diagonal theta1 = theta2 the robot (r1 = r2 = r3) has
// |B1B2| = 2 r3 = 2 r2: the distal links B1P and PB2 are aligned, a parallel singularity, which
// kinestat detects and skips without numbers (kSingular, with the free motion in words).
//
// Checks (exit status 1 when one fails): the paper's Table 1, row 14 (theta1 = 64 deg, theta2 = 75 deg):
// the platform node moves 2.3946e-5 m along x under Fx = 1 N, i.e. C_xx = 2.3946e-5 m/N; exactly the
// diagonal postures are singular; one symbolic analysis for the whole sweep. The rate (postures per
// second) depends on the machine and is not checked.
//
// Expected output (the rate depends on the machine):
//   961 input-angle pairs: 210 do not close the loop, 21 singular (theta1 = theta2), 730 solved; 1 symbolic analysis
//   C_xx at theta1 = 64 deg, theta2 = 75 deg: 2.3946e-05 m/N (Table 1, row 14: 2.3946e-05)
//   stiffest posture: theta1 = 60 deg, theta2 = 90 deg, smallest translational stiffness 4.0684e+04 N/m
//   rate: 3491 postures per second (one thread)
#include <chrono>
#include <cmath>
#include <cstdio>

#include "kinestat/core/units.hpp"
#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/msa/static_analysis.hpp"

int main() {
  using namespace kinestat;
  using units::kDeg;
  const mechanisms::FiveBarParams params;  // the paper's robot (section 5)

  // One workspace for the whole sweep: it owns the solver object (CHOLMOD by default; see
  // solver/linear_solver_factory.hpp for the backends) and its symbolic analysis.
  msa::Workspace workspace;
  int open = 0, solved = 0, singular = 0, diagonal = 0, singular_off_diagonal = 0;
  double c_xx_row14 = 0.0, best_stiffness = 0.0, best_theta1 = 0.0, best_theta2 = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int t1 = 50; t1 <= 80; ++t1) {
    for (int t2 = 60; t2 <= 90; ++t2) {
      // The MSA model at this posture (direct kinematics, "up" assembly mode): 8 nodes, 4 beams,
      // 3 joint springs, the platform point P is node "5" (kFiveBarPlatformNode).
      StatusOr<msa::Structure> s =
          mechanisms::make_five_bar_structure(params, t1 * kDeg, t2 * kDeg, mechanisms::Assembly::kUp);
      if (!s.ok()) {  // the loop cannot close at these angles (|B1B2| > 2 r2)
        ++open;
        continue;
      }
      if (t1 == t2) ++diagonal;
      // The 6x6 at P by static condensation; kSingular at a singular posture (no numbers then).
      StatusOr<CartesianStiffness> k = msa::cartesian_stiffness(*s, workspace, mechanisms::kFiveBarPlatformNode);
      if (!k.ok() || !k->stiffness_defined) {
        ++singular;
        if (t1 != t2) ++singular_off_diagonal;
        continue;
      }
      ++solved;
      if (t1 == 64 && t2 == 75) c_xx_row14 = k->compliance(0, 0);
      // The smallest translational stiffness: the lowest eigenvalue of the 2x2 in-plane block of
      // the stiffness (x, y) is the stiffness in the robot's weakest direction.
      const double weakest =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(k->stiffness.topLeftCorner<2, 2>()).eigenvalues().minCoeff();
      if (weakest > best_stiffness) {
        best_stiffness = weakest;
        best_theta1 = t1;
        best_theta2 = t2;
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int analyses = workspace.num_symbolic_analyses();
  std::printf(
      "%d input-angle pairs: %d do not close the loop, %d singular (theta1 = theta2), %d solved; "
      "%d symbolic analysis\n",
      open + singular + solved, open, singular, solved, analyses);
  std::printf("C_xx at theta1 = 64 deg, theta2 = 75 deg: %.4e m/N (Table 1, row 14: 2.3946e-05)\n", c_xx_row14);
  std::printf("stiffest posture: theta1 = %.0f deg, theta2 = %.0f deg, smallest translational stiffness %.4e N/m\n",
              best_theta1, best_theta2, best_stiffness);
  std::printf("rate: %.0f postures per second (one thread)\n", (solved + singular) / seconds);

  const bool table_ok = std::abs(c_xx_row14 - 2.3946e-5) <= 0.5e-9;  // to the paper's 5 printed digits
  return table_ok && singular_off_diagonal == 0 && singular == diagonal && analyses == 1 ? 0 : 1;
}
