#include "kinestat/vjm/stiffness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/small_qr.hpp"
#include "kinestat/core/small_triangular.hpp"
#include "kinestat/vjm/platform.hpp"
#include "vjm/bordered_system.hpp"

namespace kinestat::vjm {

namespace {

std::string list_twists(const std::vector<Vec6>& dirs) {
  std::string s;
  for (const Vec6& d : dirs) s += (s.empty() ? "" : "; ") + describe_twist(d);
  return s;
}

// Orthonormal basis (scaled twist space) of the complement of the given rigid directions.
MatX complement_of(const std::vector<Vec6>& rigid, const Vec6& w, double tol, std::vector<Vec6>* rigid_out, double L) {
  if (rigid.empty()) return Mat6::Identity();
  MatX R(6, rigid.size());
  for (size_t k = 0; k < rigid.size(); ++k) R.col(k) = rigid[k].cwiseProduct(w).normalized();
  Eigen::JacobiSVD<MatX> svd(R, Eigen::ComputeFullU);
  int r = 0;
  while (r < svd.singularValues().size() && svd.singularValues()[r] > tol * svd.singularValues()[0]) ++r;
  rigid_out->clear();
  for (int k = 0; k < r; ++k) rigid_out->push_back(unscaled_direction(svd.matrixU().col(k), L));
  return svd.matrixU().rightCols(6 - r);
}

// Free directions, compliance, indices and status of a (finite-part) stiffness K with the given
// rigid directions and passive self-motions. A chain's free directions are its mobility; a
// platform's are a singularity.
void finish(CartesianStiffness& out, const std::vector<Vec6>& rigid, int self_motions, double L, double tol,
            bool platform, const std::string& who) {
  const Vec6 w = twist_scale(L);
  const MatX Uc = complement_of(rigid, w, tol, &out.rigid_directions, L);
  const Mat6 Kt = w.cwiseInverse().asDiagonal() * out.stiffness * w.cwiseInverse().asDiagonal();
  const MatX Kc = Uc.transpose() * Kt * Uc;
  out.free_directions.clear();
  int rank = 0;
  if (Kc.size() > 0) {
    Eigen::JacobiSVD<MatX> svd(Kc, Eigen::ComputeFullV);
    const VecX& sv = svd.singularValues();
    while (rank < sv.size() && sv[rank] > tol * sv[0]) ++rank;
    for (int k = rank; k < sv.size(); ++k)
      out.free_directions.push_back(unscaled_direction(Uc * svd.matrixV().col(k), L));
  }
  out.compliance_defined = out.free_directions.empty();
  out.stiffness_defined = out.rigid_directions.empty();
  out.indices = stiffness_indices(out.stiffness);
  out.compliance.setZero();
  if (out.compliance_defined && Kc.size() > 0) {
    // C = W^-1 Uc Kc^-1 Uc^T W^-1: zero along rigid directions.
    const MatX Ct = Uc * Eigen::FullPivLU<MatX>(Kc).solve(Uc.transpose());
    out.compliance = w.cwiseInverse().asDiagonal() * Ct * w.cwiseInverse().asDiagonal();
  }
  std::string msg;
  if (!out.rigid_directions.empty())
    msg += fmt::format("{} is rigid (infinite stiffness, left out of the matrix) along: {}. ", who,
                       list_twists(out.rigid_directions));
  if (platform && !out.free_directions.empty())
    msg += fmt::format(
        "{} has zero stiffness (a free motion: singular posture or missing constraint) along: {}; "
        "the compliance is undefined. ",
        who, list_twists(out.free_directions));
  if (self_motions > 0)
    out.note = fmt::format("the passive joints have {} self-motion(s) that do not move the tool (no effect on K)",
                           self_motions);
  if (!msg.empty() && self_motions > 0)
    msg += fmt::format("The passive joints also have {} self-motion(s) that do not move the tool.", self_motions);
  out.status = msg.empty() ? Status::Ok() : Status::Singular(msg);
}

std::string chain_label(const Chain& c) { return fmt::format("chain '{}'", c.name()); }

}  // namespace

StatusOr<CartesianStiffness> unloaded_stiffness(const Chain& chain, const StiffnessOptions& opt) {
  if (Status s = chain.validate(opt.max_chain_coordinates); !s.ok()) return s;
  const ChainJacobians J = jacobians(chain, chain.nominal_passive(), VecX::Zero(chain.num_virtual()));
  const BorderedSystem B = factor_bordered_system(J.Jq, spring_compliance(J.Jtheta, chain.spring_stiffness()),
                                                  chain.length_scale(), opt.rank_tolerance);
  CartesianStiffness out;
  out.point = J.pose.translation();
  out.stiffness = B.K;
  finish(out, B.rigid_directions, static_cast<int>(B.self_motions.size()), chain.length_scale(), opt.rank_tolerance,
         false, chain_label(chain));
  return out;
}

StatusOr<CartesianStiffness> loaded_stiffness(const Chain& chain, const ChainState& state,
                                              const StiffnessOptions& opt) {
  if (Status s = chain.validate(opt.max_chain_coordinates); !s.ok()) return s;
  const int n = chain.num_passive(), m = chain.num_virtual();
  if (state.q.size() != n || state.theta.size() != m)
    return Status::Invalid(fmt::format("{}: the state has {} passive and {} virtual coordinates, the chain {} and {}",
                                       chain_label(chain), state.q.size(), state.theta.size(), n, m));
  const double L = chain.length_scale();
  const Vec6 w = twist_scale(L);
  const ChainJacobians J = jacobians(chain, state.q, state.theta);
  const ChainHessians H = hessians(chain, state.q, state.theta, state.wrench);

  // k_theta^F = (K_theta - H_thetatheta)^-1 of eq. (21), applied by LU solves.
  const MatX Ath = chain.spring_stiffness() - H.Hthetatheta;
  const Eigen::FullPivLU<MatX> lu(Ath);
  if (m > 0 && !lu.isInvertible())
    return Status::Singular(
        fmt::format("{}: K_theta - H_thetatheta is singular under this load: the springs are at "
                    "their buckling load and the loaded stiffness does not exist",
                    chain_label(chain)));
  // Scaled Jacobians (W J) make the rank decisions unit-free; the unknown is then W^-1 dF.
  const MatX Jq = w.asDiagonal() * J.Jq, Jth = w.asDiagonal() * J.Jtheta;
  const MatX kJt = m > 0 ? MatX(lu.solve(Jth.transpose())) : MatX::Zero(0, 6);
  // No LU solve on an empty block (a chain without passive joints: H_thetaq is m x 0).
  const MatX kH = m > 0 && n > 0 ? MatX(lu.solve(H.Hthetaq)) : MatX::Zero(m, n);
  const MatX S = Jth * kJt;                         // J_theta k J_theta^T
  const MatX B = Jq + Jth * kH;                     // J_q + J_theta k K_thetaq
  const MatX C = Jq.transpose() + H.Hqtheta * kJt;  // J_q^T + K_qtheta k J_theta^T
  const MatX D = H.Hqq + H.Hqtheta * kH;            // K_qq + K_qtheta k K_thetaq

  // Rigid directions: left null space of [J_q J_theta]. The force along them is a reaction, so (21)
  // is solved on the complement Uc: dF~ = Uc f, rows projected by Uc^T.
  const ToolSpaceSplit split = split_tool_space(J.Jq, J.Jtheta, w, opt.rank_tolerance);
  const int c = split.rank;
  const Mat6& U = split.U;
  std::vector<Vec6> rigid;
  for (int k = c; k < 6; ++k) rigid.push_back(unscaled_direction(U.col(k), L));
  const MatX Uc = U.leftCols(c);
  MatX A(c + n, c + n);
  A << Uc.transpose() * S * Uc, Uc.transpose() * B, C * Uc, D;
  MatX rhs = MatX::Zero(c + n, c);
  rhs.topRows(c).setIdentity();
  // Minimum-norm solution: a passive self-motion (a null vector with dF = 0) does not change K.
  const MatX X = Eigen::CompleteOrthogonalDecomposition<MatX>(A).solve(rhs);
  CartesianStiffness out;
  out.point = J.pose.translation();
  out.stiffness = w.asDiagonal() * (Uc * X.topRows(c) * Uc.transpose()) * w.asDiagonal();
  finish(out, rigid, 0, L, opt.rank_tolerance, false, chain_label(chain));
  return out;
}

CartesianStiffness aggregate(const std::vector<CartesianStiffness>& chains, double L, const StiffnessOptions& opt) {
  CartesianStiffness out;
  if (!chains.empty()) out.point = chains.front().point;  // validate_platform: the chains share it
  std::vector<Vec6> rigid;
  for (const CartesianStiffness& c : chains) {
    out.stiffness += c.stiffness;
    rigid.insert(rigid.end(), c.rigid_directions.begin(), c.rigid_directions.end());
  }
  finish(out, rigid, 0, L, opt.rank_tolerance, true, "the platform");
  return out;
}

namespace {

template <class PerChain>
StatusOr<CartesianStiffness> platform_stiffness(const std::vector<Chain>& chains, const StiffnessOptions& opt,
                                                PerChain per_chain) {
  if (Status s = validate_platform(chains, opt.max_chain_coordinates); !s.ok()) return s;
  std::vector<CartesianStiffness> parts;
  for (size_t i = 0; i < chains.size(); ++i) {
    StatusOr<CartesianStiffness> k = per_chain(i);
    if (!k.ok()) return k.status();
    parts.push_back(std::move(*k));
  }
  return aggregate(parts, platform_length_scale(chains), opt);
}

}  // namespace

StatusOr<CartesianStiffness> platform_unloaded_stiffness(const std::vector<Chain>& chains,
                                                         const StiffnessOptions& opt) {
  return platform_stiffness(chains, opt, [&](size_t i) { return unloaded_stiffness(chains[i], opt); });
}

StatusOr<CartesianStiffness> platform_loaded_stiffness(const std::vector<Chain>& chains, const PlatformState& state,
                                                       const StiffnessOptions& opt) {
  if (state.chains.size() != chains.size())
    return Status::Invalid(
        fmt::format("the platform state has {} chains, the platform {}", state.chains.size(), chains.size()));
  return platform_stiffness(chains, opt, [&](size_t i) { return loaded_stiffness(chains[i], state.chains[i], opt); });
}

}  // namespace kinestat::vjm

namespace kinestat::vjm {

namespace {

// Up to 6 x 6, on the stack.
using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

// The inverse of the lower triangle of `L` (n x n).
Small lower_inverse(const Small& L) {
  Small X = Small::Identity(L.rows(), L.cols());
  lower_solve_in_place(L, X);
  return X;
}

// Eq. (10) of one chain, K = W N (N^T S~ N)^-1 N^T W, when the reference's two rank decisions are
// certainly full (factor_bordered_system: J_q's rank, no rigid direction); false otherwise. L: the
// chain's length scale.
bool regular_chain_stiffness(const Chain& chain, RegularStiffnessData::ChainData& d, double L, double tol, Mat6& K) {
  const int n = d.passive;
  if (n > 6) return false;  // a self-motion: the reference names it
  for (int i = 0; i < n; ++i) d.q(i) = chain.nominal_passive(i);
  jacobians(chain, d.q, d.theta, d.J);
  // S = J_theta K_theta^-1 J_theta^T, as spring_compliance: Y^T Y with Y = L^-1 J_theta^T (K_theta =
  // L L^T, block by block), triangular solves and a product symmetric by construction, coefficient by
  // coefficient (the general product's blocked path is slow at 6 columns).
  Mat6 S = Mat6::Zero();
  if (d.virtual_ > 0) {
    for (const RegularStiffnessData::SpringFactor& f : d.springs) {
      const int k = static_cast<int>(f.factor.rows());
      auto Y = d.compliance_rhs.middleRows(f.first, k);
      Y = d.J.Jtheta.middleCols(f.first, k).transpose();
      lower_solve_in_place(f.factor.matrixLLT(), Y);
    }
    S.noalias() = d.compliance_rhs.transpose().lazyProduct(d.compliance_rhs);
  }
  const Vec6 w = twist_scale(L);
  // J_q scaled, unit columns (factor_bordered_system); sigma_max <= ||Jn||_F = sqrt(n).
  Mat6 A = Mat6::Zero();
  for (int j = 0; j < n; ++j) {
    A.col(j) = w.asDiagonal() * d.J.Jq.col(j);
    const double c = A.col(j).norm();
    if (!(c > 0.0)) return false;
    A.col(j) /= c;
  }
  Mat6 Q;
  householder_qr(A, 6, n, Q);
  if (n > 0) {
    Small R = A.topLeftCorner(n, n).triangularView<Eigen::Upper>();
    // sigma_min >= 1 / ||R^-1||_F; R^-1 = (R^T)^-T, R^T lower.
    const Small Rinv = lower_inverse(R.transpose());
    if (!Rinv.allFinite() || !(1.0 / Rinv.norm() > 10.0 * tol * std::max(1.0, std::sqrt(double(n))))) return false;
  }
  const int c = 6 - n;
  K.setZero();
  if (c == 0) return true;  // the passive joints give every direction for free: K = 0
  const Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6> N = Q.rightCols(c);
  const Mat6 St = w.asDiagonal() * S * w.asDiagonal();
  const Small C = N.transpose() * St * N;
  const Eigen::LLT<Small> llt(C);
  if (llt.info() != Eigen::Success) return false;
  const Small Li = lower_inverse(llt.matrixL());
  // lambda_min >= 1 / trace(C^-1) = 1 / ||L^-1||_F^2, lambda_max <= trace(C).
  if (!Li.allFinite() || !(1.0 / Li.squaredNorm() > 10.0 * tol * C.trace())) return false;
  const Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6> Y = Li * N.transpose();
  const Mat6 Kt = Y.transpose() * Y;
  K = w.asDiagonal() * Kt * w.asDiagonal();
  K = 0.5 * (K + K.transpose()).eval();
  return true;
}

}  // namespace

Status prepare_regular_stiffness(const std::vector<Chain>& chains, RegularStiffnessData& data,
                                 const StiffnessOptions& opt) {
  if (Status s = validate_platform(chains, opt.max_chain_coordinates); !s.ok()) return s;
  data.chains.assign(chains.size(), {});
  for (std::size_t i = 0; i < chains.size(); ++i) {
    RegularStiffnessData::ChainData& d = data.chains[i];
    d.passive = chains[i].num_passive();
    d.virtual_ = chains[i].num_virtual();
    d.springs.clear();
    for (const Spring& s : chains[i].springs()) {
      RegularStiffnessData::SpringFactor& f = d.springs.emplace_back();
      f.first = s.first;
      const int k = static_cast<int>(s.stiffness.rows());
      f.stiffness.topLeftCorner(k, k) = s.stiffness;
      f.factor.compute(f.stiffness.topLeftCorner(k, k));
    }
    d.q = VecX::Zero(d.passive);
    d.theta = VecX::Zero(d.virtual_);
    d.J.Jq = MatX::Zero(6, d.passive);
    d.J.Jtheta = MatX::Zero(6, d.virtual_);
    d.compliance_rhs = MatX::Zero(d.virtual_, 6);
  }
  return Status::Ok();
}

// K_theta's blocks factored again where a spring changed since it was (Chain::set_spring_stiffness per
// posture: a robot file's parallelogram bars); false where one is not positive definite.
bool refresh_spring_factor(const Chain& chain, RegularStiffnessData::ChainData& d) {
  if (chain.springs().size() != d.springs.size()) return false;
  for (std::size_t i = 0; i < d.springs.size(); ++i) {
    const MatX& K = chain.springs()[i].stiffness;
    RegularStiffnessData::SpringFactor& f = d.springs[i];
    const int k = static_cast<int>(K.rows());
    if (k != f.factor.rows() || chain.springs()[i].first != f.first) return false;
    auto block = f.stiffness.topLeftCorner(k, k);
    if (block == K) continue;
    block = K;
    f.factor.compute(block);
  }
  for (const RegularStiffnessData::SpringFactor& f : d.springs)
    if (f.factor.info() != Eigen::Success) return false;
  return true;
}

bool regular_platform_unloaded_stiffness(const std::vector<Chain>& chains, RegularStiffnessData& data,
                                         CartesianStiffness& out, const StiffnessOptions& opt) {
  if (chains.empty() || chains.size() != data.chains.size()) return false;
  const double tol = opt.rank_tolerance;
  Mat6 K = Mat6::Zero();
  // The chains' length scales, once (a walk over each chain's factors; platform_length_scale's
  // largest).
  double L0 = 0.0, platform_L = 0.0;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    RegularStiffnessData::ChainData& d = data.chains[i];
    if (chains[i].num_passive() != d.passive || chains[i].num_virtual() != d.virtual_) return false;
    if (!refresh_spring_factor(chains[i], d)) return false;
    const double L = chains[i].length_scale();
    if (i == 0) L0 = L;
    platform_L = std::max(platform_L, L);
    Mat6 Ki;
    if (!regular_chain_stiffness(chains[i], d, L, tol, Ki)) return false;
    // validate_platform's assembly check on the walks just made.
    const double gap = (d.J.pose.translation() - data.chains[0].J.pose.translation()).norm();
    if (!(gap <= 1e-9 * std::max(L, L0))) return false;
    K += Ki;
  }
  // aggregate's finish without rigid directions: K~ = W^-1 K W^-1 of full rank, C = K^-1.
  const Vec6 w = twist_scale(platform_L);
  const Mat6 Kt = w.cwiseInverse().asDiagonal() * K * w.cwiseInverse().asDiagonal();
  const Eigen::LLT<Mat6> llt(Kt);
  if (llt.info() != Eigen::Success) return false;
  const Small Li = lower_inverse(Small(llt.matrixL()));
  if (!Li.allFinite() || !(1.0 / Li.squaredNorm() > 10.0 * tol * Kt.trace())) return false;
  const Mat6 Ct = Li.transpose() * Li;
  out.point = data.chains[0].J.pose.translation();
  out.stiffness = K;
  out.compliance = w.cwiseInverse().asDiagonal() * Ct * w.cwiseInverse().asDiagonal();
  out.stiffness_defined = true;
  out.compliance_defined = true;
  out.free_directions.clear();
  out.rigid_directions.clear();
  out.indices.reset();
  out.note.clear();
  out.status = Status::Ok();
  return true;
}

}  // namespace kinestat::vjm
