// The loaded mode of the VJM posture kernels on the stack: a serial chain of eq. (1) with fixed
// capacity (the factors, walk, Jacobians of eq. 5 and derivatives of J^T F of eq. 19-20 of
// vjm::Chain, vjm::jacobians and vjm::hessians), its loaded equilibrium (eq. 11) and loaded
// stiffness (eq. 21), and the platform under a prescribed displacement or wrench, as
// vjm::platform_equilibrium(_under_wrench) and vjm::platform_loaded_stiffness compute them for
// regular postures. A kernel rebuilds its chains in place at every posture: no heap allocation.
//
// Differences from the vjm library, which the tests bound: the chain equilibrium is found by
// Newton-Raphson (with chord steps) on all of eq. (11) from the unloaded state (vjm first runs the
// paper's eq. (15) iteration and stops at 1e-12 residuals; these go on to the round-off floor), with
// LU solves where vjm uses rank-revealing decompositions that only matter at singular postures;
// under a wrench the equilibrium is the coupled iteration's (all chains and the platform at once,
// docs/vjm.md "Sweep kernels"), from rest or from a neighbouring posture's equilibrium, with vjm's
// nested iteration (in load increments where it fails) as the fallback from rest; the loaded
// stiffness is the Schur complement of a Newton matrix at the solution (the same eq. 21 by another
// elimination).
#pragma once

#include <array>

#include <Eigen/Dense>

#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"
#include "kinestat/vjm/chain.hpp"
#include "mechanisms/path_extrapolation.hpp"

namespace kinestat::mechanisms::fixed_vjm {

// Room for the bundled robot files' legs (a hexapod's six, a Delta's with two beams each); a larger
// chain takes the vjm library's path (FixedChain::assign).
inline constexpr int kMaxFactors = 32;
inline constexpr int kMaxCoordinates = 24;  // passive + virtual
inline constexpr int kMaxChains = 6;
// A warm-started loaded equilibrium is kept where the load leaves more than this share of the
// unloaded stiffness in every direction, of the platform and of every chain's springs
// (LoadedPlatform::evaluate).
inline constexpr double kBranchSoftening = 0.8;
// Under a wrench, nor where its deflection d departs from the linear one d0 = K0^-1 W_ext by more
// than this share, |W (d - d0)| <= kMaxNonlinearity |W d0| (scaled twists).
inline constexpr double kMaxNonlinearity = 0.05;
// Under a prescribed displacement, none beyond this one (scaled twist: translation / length scale,
// rotation in rad).
inline constexpr double kMaxWarmDeflection = 0.01;

using CoordinateVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxCoordinates, 1>;
using CoordinateMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxCoordinates, kMaxCoordinates>;
using ChainJacobian = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, kMaxCoordinates>;

struct Pose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
};

// A walk of a chain at x: the unit twists of its moving factors in product order (spatial form,
// times the factor's coefficient), each one's tool-point velocity u = v + w x p and coordinate slot,
// and the tool pose; the Jacobian sums the twists by slot, the Hessian of eq. (19)-(20) pairs them.
struct ChainWalk {
  struct Twist {
    Vec3 v, w;
    int slot;
  };
  std::array<Twist, kMaxFactors> tw;
  std::array<Vec3, kMaxFactors> u;
  int count = 0;
  Pose T;
};

// Coordinates x = (q, theta): the passive joints, then the springs' virtual coordinates.
class FixedChain {
 public:
  void clear();
  void add_transform(const Mat3& R, const Vec3& p);
  // A prismatic actuator along `axis` at `value` with a 1-dof spring (a virtual coordinate).
  void add_prismatic_actuator(const Vec3& axis, double value, double stiffness);
  // A 6-dof spring of stiffness K in the current frame (virtual translations x y z, rotations x y z).
  void add_spring(const Mat6& K);
  // Revolute passive joint about `axis` (unit) at `nominal`; returns its index.
  int add_passive(const Vec3& axis, double nominal);
  // A revolute factor repeating passive joint `index` times `coefficient` (eq. 22's parallelogram).
  void add_coupled(const Vec3& axis, int index, double coefficient);

  // The same chain as a vjm::Chain at its current posture (its factors, nominal passive coordinates
  // and springs): false, and this chain unspecified, where it exceeds the capacity above.
  bool assign(const vjm::Chain& chain);

  int num_passive() const { return n_; }
  int num_virtual() const { return m_; }
  CoordinateVector nominal() const;  // (q0, 0)
  // K_theta (m x m).
  auto spring_stiffness() const { return K_.topLeftCorner(m_, m_); }
  // vjm::Chain::length_scale: the constant translations and the prismatic offsets.
  double length_scale() const;

  // Tool pose at x, the Jacobian [J_q J_theta] (eq. 5) and, with F, H = d(J^T F)/dx (eq. 19-20).
  Pose kinematics(const CoordinateVector& x, ChainJacobian& J, const Vec6* F = nullptr,
                  CoordinateMatrix* H = nullptr) const;
  // The same in two parts: the walk and J at x, then H at F from the walk (a chord step of the
  // equilibrium needs no H).
  void walk(const CoordinateVector& x, ChainWalk& w, ChainJacobian& J) const;
  void hessian(const ChainWalk& w, const Vec6& F, CoordinateMatrix& H) const;

 private:
  enum class Kind : std::uint8_t { kConstant, kRevolute, kPrismatic };
  struct Factor {
    Kind kind = Kind::kConstant;
    Mat3 R = Mat3::Identity();  // constant factor
    Vec3 p = Vec3::Zero();
    Vec3 axis = Vec3::UnitZ();  // motion factor
    int unit_axis = -1;         // k where axis is the coordinate axis e_k
    double offset = 0.0;
    bool passive = false;  // which coordinate drives it (index < 0: none)
    int index = -1;
    double coefficient = 1.0;
  };
  void add_motion(Kind kind, const Vec3& axis, double offset, bool passive, int index, double coefficient);

  std::array<Factor, kMaxFactors> f_;
  int size_ = 0, n_ = 0, m_ = 0;
  std::array<double, kMaxCoordinates> q0_{};
  CoordinateMatrix K_ = CoordinateMatrix::Zero(kMaxCoordinates, kMaxCoordinates);
};

// One chain's loaded state (vjm::ChainState without the report).
struct FixedChainState {
  CoordinateVector x;
  Vec6 wrench = Vec6::Zero();
  // When `linearized`: the Jacobian [J_q J_theta] and H = d(J^T F)/dx at (x, wrench), as the
  // equilibrium's last step left them, so that the loaded stiffness does not walk the chain again;
  // when `condensed` too, that stiffness K (dF/dt, eq. 21), condensed from a Newton matrix there.
  bool linearized = false, condensed = false;
  ChainJacobian J;
  CoordinateMatrix H;
  Mat6 K;
};

// The platform in loaded mode: its chains, built by the kernel for each posture.
struct LoadedPlatform {
  std::array<FixedChain, kMaxChains> chains;
  int num_chains = 0;
  double equilibrium_tolerance = 1e-12;  // vjm::EquilibriumOptions
  int max_iterations = 50;
  double rank_tolerance = 1e-10;  // vjm::StiffnessOptions
  // From rest, where the first start fails, the nested iteration and the load in increments
  // (equilibrium()); off, kFailed at once (a caller with a reference path of its own).
  bool fallbacks = true;

  // The loaded stiffness and deflection with the platform displaced by `displacement` or under
  // `wrench` (exactly one given), into r: kFailed where the equilibrium is not found, kSingular
  // where the loaded stiffness does not exist or has a free direction, else kOk; the Newton steps in
  // r.newton_iterations. From rest (each chain at its nominal state, the platform undisplaced), or,
  // with `warm` and the unloaded platform stiffness `unloaded` of this posture, from the equilibrium
  // of the last posture that ended kOk (the chains rebuilt for the new posture since), carried over:
  // each passive joint keeps its deflection from its nominal angle, each spring its deflection, each
  // chain its wrench, the platform its displacement (extrapolated from the two to five postures
  // before when `point` continues their line at their spacing). A warm start that does not
  // converge, or whose answer fails the branch test against `unloaded` (fixed_chain.cpp), is redone
  // from rest. `point`: the posture's tool point (m), which tells whether the path goes straight on.
  void evaluate(const Vec3& point, const Vec6* displacement, const Vec6* wrench, const Mat6* unloaded, bool warm,
                PostureResult& r);
  // The next warm start starts from rest (the previous posture had no equilibrium to carry over).
  void forget() { solved_.clear(); }

 private:
  bool solve_chain(int i, const Pose& target, FixedChainState& s, int& steps) const;
  // K: the loaded platform stiffness at the solution, from the last Newton step's Schur complements.
  bool coupled_equilibrium(const Vec6& wrench, Vec6& d, Mat6& K, int& steps, bool monotone);
  bool nested_equilibrium(const Vec6& wrench, Vec6& d, Mat6& K, int& steps);
  // Every chain at the platform displaced by d, from its current state.
  bool solve_chains(const Vec6& d, int& steps);
  void reset_to_rest();
  bool loaded_stiffness(int i, const FixedChainState& s, Mat6& K) const;
  bool platform_stiffness(Mat6& K) const;
  // The equilibrium from states_ and d (at_rest: states_ are the chains' nominal states, their
  // equilibrium at d = 0; under a wrench, the nested iteration of the reference from rest, in load
  // increments where it fails, finished by the coupled one, which alone continues a warm start);
  // have_K: K is the loaded platform stiffness at the solution.
  bool equilibrium(const Vec6* displacement, const Vec6* wrench, bool at_rest, Vec6& d, Mat6& K, bool& have_K,
                   int& steps);
  std::array<FixedChainState, kMaxChains> states_;
  std::array<CoordinateVector, kMaxChains> rest_;  // the chains' nominal coordinates (q0, 0)
  std::array<Pose, kMaxChains> nominal_;
  double length_scale_ = 1.0;
  // The last kOk postures, one after the other on this path (solved_[0] the latest): the point, each
  // chain's deflection from its nominal coordinates and wrench, the platform displacement.
  struct Solved {
    Vec3 point = Vec3::Zero();
    std::array<CoordinateVector, kMaxChains> deflection;
    std::array<Vec6, kMaxChains> wrench;
    Vec6 d = Vec6::Zero();
    double nonlinearity = 0.0;  // its departure from the linear deflection (evaluate(), in units of the bound)
  };
  PathHistory<Solved, kMaxExtrapolationOrder> solved_;
};

}  // namespace kinestat::mechanisms::fixed_vjm
