// Posture kernels of the five-bar for sweeps (five_bar_kernel.hpp): the models of
// make_five_bar_structure (MSA) and five_bar_vjm_chains (VJM) with everything that does not depend
// on the posture built once, and fixed-size dense algebra per posture (no heap allocation).
#include "kinestat/mechanisms/five_bar_kernel.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/vjm/link_spring.hpp"
#include "mechanisms/fixed_size_vjm.hpp"

namespace kinestat::mechanisms {
namespace {

Vec3 at(const Vec2& v) { return {v.x(), v.y(), 0.0}; }

// What the reference's model validation (msa::Structure::validate, vjm::Chain::validate) rejects
// whatever the posture: such a model gives kFailed at every reachable point, as there.
bool link_properties_valid(const FiveBarParams& p) {
  const Material& m = p.link_material;
  const Section& s = p.link_section;
  return m.E > 0 && m.G > 0 && std::isfinite(m.E) && std::isfinite(m.G) && s.A > 0 && s.Iy > 0 && s.Iz > 0 && s.J > 0 &&
         s.Asy >= 0 && s.Asz >= 0;
}

// What both five-bar kernels share: the options, the validity of the model, the inverse
// kinematics and the singularity measure.
class FiveBarKernelBase : public PostureKernel {
 public:
  FiveBarKernelBase(const FiveBarKernelOptions& o, bool model_valid)
      : o_(o), params_valid_(validate(o.params).ok()), model_valid_(model_valid) {}
  std::string description() const override {
    return fmt::format("five-bar {} {} ({})", to_string(o_.mode), to_string(o_.assembly), to_string(o_.method));
  }

 protected:
  // The posture at `point` in the kernel's working and assembly modes, with its singularity measure
  // in r and r.status = kSingular (the kernel sets kOk when it finds a stiffness); nullopt where the
  // reference kernel finds none (r kUnreachable) or refuses the model (kFailed).
  std::optional<FiveBarPosture> reach(const Vec3& point, PostureResult& r) const {
    if (!params_valid_) return std::nullopt;
    std::optional<FiveBarPosture> q = try_inverse_kinematics(o_.params, Vec2(point.x(), point.y()), o_.mode);
    if (!q || q->assembly != o_.assembly) return std::nullopt;
    const FiveBarJacobians jac = five_bar_jacobians(*q);
    r.singularity_measure = std::min(jac.parallel_measure, jac.serial_measure);
    r.status = model_valid_ ? PostureStatus::kSingular : PostureStatus::kFailed;
    if (!model_valid_) return std::nullopt;
    return q;
  }

  FiveBarKernelOptions o_;

 private:
  bool params_valid_, model_valid_;
};

// Rotation about z whose x axis is the direction from `a` to `b`.
Mat3 link_axes(const Vec2& a, const Vec2& b) {
  const Vec2 e = (b - a).normalized();
  Mat3 R;
  R << e.x(), -e.y(), 0.0, e.y(), e.x(), 0.0, 0.0, 0.0, 1.0;
  return R;
}

// ---------------------------------------------------------------------------------------------
// MSA. The structure of make_five_bar_structure: nodes 0..7 = A1, B1, B1', P, P', B2, B2', A2;
// beams 0-1, 2-3, 4-5, 6-7; joints 1-2, 3-4, 5-6 with springs in global axes; nodes 0 and 7 fixed;
// the stiffness is asked at node 4 (kFiveBarPlatformNode). Every beam lies in the plane z = 0 with
// local z = global z (default orientation) and the joints are diagonal in global axes, so the
// reduced matrix splits exactly into an in-plane system (ux, uy, rz) and an out-of-plane one
// (uz, rx, ry) of 18 unknowns each: two 18x18 instead of one 36x36.
//
// Unknowns: the joints' deformations d12 = u2 - u1, d34 = u3 - u4, d65 = u6 - u5 and the nodes
// u1, u5, u4, in that order (u2 = u1 + d12, u3 = u4 + d34, u6 = u5 + d65: an exact change of
// variables). The 2e11 N/m joint springs then sit alone on the diagonal of the d's instead of
// being added to and subtracted from ~1e4 N/m of link bending, which in nodal unknowns costs ~7 of
// the 16 digits (the reference's compliance is off by up to ~1e-5 for that reason, see the tests).
// A rigid (infinite) joint component is a zero deformation: its unknown is dropped (a unit
// diagonal padding that the factorization passes through).
//
// With u4 last, the Cholesky factor L of a plane's matrix gives the Cartesian stiffness without a
// solve: its trailing 3x3 block satisfies L_44 L_44^T = the Schur complement of the other unknowns,
// the static condensation onto node 4, whose inverse is the compliance.
constexpr int kPlaneSize = 18;
using PlaneMatrix = Eigen::Matrix<double, kPlaneSize, kPlaneSize>;
constexpr std::array<std::array<int, 3>, 2> kPlaneComponents = {{{0, 1, 5}, {2, 3, 4}}};  // of ux..rz
constexpr std::array<std::array<int, 6>, 2> kPlaneBeamDofs = {{{0, 1, 5, 6, 7, 11}, {2, 3, 4, 8, 9, 10}}};
constexpr std::array<std::array<int, 2>, 4> kBeams = {{{0, 1}, {2, 3}, {4, 5}, {6, 7}}};
// Unknown blocks (3 per plane) whose sum is each node's displacement; -1: none.
constexpr int kD12 = 0, kD34 = 1, kD65 = 2, kU1 = 3, kU5 = 4, kU4 = 5;
constexpr std::array<std::array<int, 2>, 8> kNodeBlocks = {
    {{-1, -1}, {kU1, -1}, {kU1, kD12}, {kU4, kD34}, {kU4, -1}, {kU5, -1}, {kU5, kD65}, {-1, -1}}};

// Singularity test of the MSA kernel (five_bar_kernel.hpp).
constexpr double kMsaSingularRatio = 2e-13;

class FiveBarMsaKernel final : public FiveBarKernelBase {
 public:
  explicit FiveBarMsaKernel(const FiveBarKernelOptions& o)
      : FiveBarKernelBase(o, link_properties_valid(o.params) && (o.params.joint_stiffness.array() >= 0.0).all()) {
    const FiveBarParams& p = o.params;
    const Mat12 k1 = beam_local_stiffness(p.link_material, p.link_section, p.r1, BeamTheory::kEulerBernoulli);
    const Mat12 k2 = beam_local_stiffness(p.link_material, p.link_section, p.r2, BeamTheory::kEulerBernoulli);
    for (int plane = 0; plane < 2; ++plane)
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          proximal_[plane](i, j) = k1(kPlaneBeamDofs[plane][i], kPlaneBeamDofs[plane][j]);
          distal_[plane](i, j) = k2(kPlaneBeamDofs[plane][i], kPlaneBeamDofs[plane][j]);
        }
    for (int plane = 0; plane < 2; ++plane) build_plane(plane);
  }

  PostureResult evaluate(const Vec3& point) override {
    PostureResult r;
    const std::optional<FiveBarPosture> q = reach(point, r);
    if (!q) return r;
    const std::array<Vec2, 8> x = {q->A1, q->B1, q->B1, q->P, q->P, q->B2, q->B2, q->A2};
    Mat6 K = Mat6::Zero(), C = Mat6::Zero();
    for (int plane = 0; plane < 2; ++plane) {
      const Vec3 D = assemble(plane, x);
      llt_.compute(K_);
      if (llt_.info() != Eigen::Success) return r;
      const Mat3 L44 = llt_.matrixLLT().bottomRightCorner<3, 3>().triangularView<Eigen::Lower>();
      const Mat3 S = L44 * L44.transpose();
      if (!regular(S, D)) return r;
      const Mat3 Linv = fixed_vjm::lower_solve<3, 3>(L44, Mat3::Identity());
      const Mat3 Cp = Linv.transpose() * Linv;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          K(kPlaneComponents[plane][i], kPlaneComponents[plane][j]) = S(i, j);
          C(kPlaneComponents[plane][i], kPlaneComponents[plane][j]) = Cp(i, j);
        }
    }
    r.status = PostureStatus::kOk;
    set_stiffness(r, K, C);
    r.deflection = C * o_.load;
    return r;
  }

  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<FiveBarMsaKernel>(*this); }

 private:
  // The singularity test (five_bar_kernel.hpp): the condensed stiffness S at node 4, scaled by the
  // diagonal D of the nodal stiffness matrix there (as msa's mode ratio u'Ku / u'Du), has no
  // eigenvalue below kMsaSingularRatio.
  static bool regular(const Mat3& S, const Vec3& D) {
    const Vec3 s = D.cwiseSqrt().cwiseInverse();
    const Mat3 Ss = s.asDiagonal() * S * s.asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Mat3>(Ss, Eigen::EigenvaluesOnly).eigenvalues()(0) >= kMsaSingularRatio;
  }

  // What assembly needs of each plane, from the joints alone: the joint springs on the diagonal of
  // the deformations (a dropped rigid component: a unit pad), where each beam end dof goes (the
  // unknown blocks summing to its node, dropped components left out), and node 4's nodal diagonal
  // from the joint 3-4.
  void build_plane(int plane) {
    const auto component = [&](int k) { return o_.params.joint_stiffness(kPlaneComponents[plane][k]); };
    PlaneMatrix& K = constant_[plane];
    K.setZero();
    for (int block : {kD12, kD34, kD65})
      for (int k = 0; k < 3; ++k) K(3 * block + k, 3 * block + k) = std::isinf(component(k)) ? 1.0 : component(k);
    for (int k = 0; k < 3; ++k) node4_joint_[plane](k) = std::isinf(component(k)) ? 0.0 : component(k);
    for (std::size_t b = 0; b < kBeams.size(); ++b)
      for (int end = 0; end < 2; ++end)
        for (int k = 0; k < 3; ++k) {
          std::array<int, 2>& t = targets_[plane][b][3 * end + k];
          t = {-1, -1};
          int used = 0;
          for (int block : kNodeBlocks[kBeams[b][end]])
            if (block >= kU1 || (block >= 0 && !std::isinf(component(k)))) t[used++] = 3 * block + k;
        }
  }

  // K_ of one plane at the posture whose joint centres (node positions) are x; returns the
  // diagonal of the nodal stiffness matrix at node 4 (joint 3-4's spring and beam 4-5).
  Vec3 assemble(int plane, const std::array<Vec2, 8>& x) {
    K_ = constant_[plane];
    Vec3 D = node4_joint_[plane];
    for (std::size_t b = 0; b < kBeams.size(); ++b) {
      const auto [n1, n2] = kBeams[b];
      const Vec2 e = (x[n2] - x[n1]).normalized();
      // Ke = T^T K_local T with u_local = T u_global per node: a rotation by the link's direction of
      // the components (c, c + 1) of each node, (ux, uy) in plane and (rx, ry) out of plane.
      Mat6 Ke = (b == 0 || b == 3 ? proximal_ : distal_)[plane];
      const int c = plane == 0 ? 0 : 1;
      for (int end = 0; end < 2; ++end) {
        const int i = 3 * end + c;
        const Eigen::Matrix<double, 6, 1> col = Ke.col(i);
        Ke.col(i) = e.x() * col - e.y() * Ke.col(i + 1);
        Ke.col(i + 1) = e.y() * col + e.x() * Ke.col(i + 1);
      }
      for (int end = 0; end < 2; ++end) {
        const int i = 3 * end + c;
        const Eigen::Matrix<double, 1, 6> row = Ke.row(i);
        Ke.row(i) = e.x() * row - e.y() * Ke.row(i + 1);
        Ke.row(i + 1) = e.y() * row + e.x() * Ke.row(i + 1);
      }
      if (n1 == kFiveBarPlatformNode) D += Ke.diagonal().head<3>();
      const auto& t = targets_[plane][b];
      for (int i = 0; i < 6; ++i)
        for (int row : t[i])
          if (row >= 0)
            for (int j = 0; j < 6; ++j)
              for (int col : t[j])
                if (col >= 0) K_(row, col) += Ke(i, j);
    }
    return D;
  }

  std::array<Mat6, 2> proximal_, distal_;  // local beam stiffness of each plane (r1, r2)
  std::array<PlaneMatrix, 2> constant_;
  std::array<std::array<std::array<std::array<int, 2>, 6>, 4>, 2> targets_;  // plane, beam, end dof: rows
  std::array<Vec3, 2> node4_joint_;
  PlaneMatrix K_;
  Eigen::LLT<PlaneMatrix> llt_;
};

// ---------------------------------------------------------------------------------------------
// VJM. The chains of five_bar_vjm_chains: leg 1 = motor A1, link spring at B1, joint spring and
// passive joint at B1, link spring at P, joint spring and passive joint at P; leg 2 = motor A2,
// link spring at B2, joint spring and passive joint at B2, link spring at P. Springs in the link's
// axes; passive joints about z. Per posture: each leg's S (eq. 9) from the springs' constant
// compliances moved to P, its stiffness (eq. 10), their sum (section 3.3).
class FiveBarVjmKernel final : public FiveBarKernelBase {
 public:
  // The joint spring (kr_z replaced by kr_x) must be finite and positive definite.
  explicit FiveBarVjmKernel(const FiveBarKernelOptions& o)
      : FiveBarKernelBase(o, link_properties_valid(o.params) && o.params.joint_stiffness.head<5>().allFinite() &&
                                 (o.params.joint_stiffness.head<5>().array() > 0.0).all()) {
    const FiveBarParams& p = o.params;
    const auto compliance = [](const Mat6& K) { return fixed_vjm::spd_inverse<6>(K.llt()); };
    proximal_ = compliance(vjm::cantilever_spring(p.link_material, p.link_section, p.r1, BeamTheory::kEulerBernoulli));
    distal_ = compliance(vjm::cantilever_spring(p.link_material, p.link_section, p.r2, BeamTheory::kEulerBernoulli));
    // The joint spring of five_bar_vjm.cpp: kr_z set to kr_x (the passive joint makes it irrelevant).
    Vec6 k = p.joint_stiffness;
    k(5) = k(3);
    joint_ = k.cwiseInverse().asDiagonal();
    w_ = fixed_vjm::twist_scale(p.r3 + p.r1 + p.r2);  // Chain::length_scale of either leg
  }

  PostureResult evaluate(const Vec3& point) override {
    PostureResult r;
    const std::optional<FiveBarPosture> q = reach(point, r);
    if (!q) return r;
    const Vec3 P = at(q->P), x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
    Mat6 K1, K2;
    {
      // Passive joints about z at B1 and P transmit any force along B1P or z and moments about x, y.
      const Mat3 R0 = link_axes(q->A1, q->B1), R1 = link_axes(q->B1, q->P);
      const Mat6 S = fixed_vjm::transfer_compliance(fixed_vjm::rotate6(proximal_ + joint_, R0), P - at(q->B1)) +
                     fixed_vjm::rotate6(distal_ + joint_, R1);
      Eigen::Matrix<double, 6, 4> N;
      N << fixed_vjm::line_force(R1.col(0), P, P), fixed_vjm::line_force(z, P, P), fixed_vjm::couple(x),
          fixed_vjm::couple(y);
      if (!fixed_vjm::chain_stiffness<4>(N, S, K1)) return r;
    }
    {
      // The passive joint about z at B2 transmits forces along B2P and z, moments about x and y, and
      // a force normal to B2P in the plane with the moment about z that balances it at B2.
      const Mat3 R0 = link_axes(q->A2, q->B2), R1 = link_axes(q->B2, q->P);
      const Mat6 S = fixed_vjm::transfer_compliance(fixed_vjm::rotate6(proximal_ + joint_, R0), P - at(q->B2)) +
                     fixed_vjm::rotate6(distal_, R1);
      Eigen::Matrix<double, 6, 5> N;
      N << fixed_vjm::line_force(R1.col(0), P, P), fixed_vjm::line_force(z, P, P), fixed_vjm::couple(x),
          fixed_vjm::couple(y), fixed_vjm::line_force(R1.col(1), at(q->B2), P);
      if (!fixed_vjm::chain_stiffness<5>(N, S, K2)) return r;
    }
    fixed_vjm::set_platform_result(K1 + K2, w_, o_.load, r);
    return r;
  }

  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<FiveBarVjmKernel>(*this); }

 private:
  Mat6 proximal_, distal_, joint_;  // spring compliances in their own axes
  Vec6 w_;
};

}  // namespace

Status validate(const FiveBarKernelOptions& options) {
  if (Status s = validate(options.params); !s.ok()) return s;
  if (Status s = check_entries(options.load.head<3>(), Quantity::kForce, "load (force, N)"); !s.ok()) return s;
  return check_entries(options.load.tail<3>(), Quantity::kMoment, "load (moment, N m)");
}

std::unique_ptr<PostureKernel> make_five_bar_kernel(const FiveBarKernelOptions& options) {
  if (options.method == StiffnessMethod::kMsa) return std::make_unique<FiveBarMsaKernel>(options);
  return std::make_unique<FiveBarVjmKernel>(options);
}

}  // namespace kinestat::mechanisms
