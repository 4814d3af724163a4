// Posture kernel of the Orthoglide for sweeps (orthoglide_kernel.hpp): the chains of
// orthoglide_chains written out with fixed-size matrices; the springs' compliances that do not
// depend on the posture are computed once.
#include "kinestat/mechanisms/orthoglide_kernel.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"
#include "kinestat/vjm/link_spring.hpp"
#include "mechanisms/fixed_chain.hpp"
#include "mechanisms/fixed_size_vjm.hpp"

namespace kinestat::mechanisms {
namespace {

using fixed_vjm::couple;
using fixed_vjm::line_force;
using fixed_vjm::rotate6;
using fixed_vjm::transfer_compliance;

Mat6 inverse_spd(const Mat6& K) { return fixed_vjm::spd_inverse<6>(Eigen::LLT<Mat6>(K)); }

class OrthoglideKernel final : public PostureKernel {
 public:
  explicit OrthoglideKernel(const OrthoglideKernelOptions& o) : o_(o) {
    const OrthoglideStiffnessModel& m = o.model;
    geometry_valid_ = validate(OrthoglideGeometry{m.link_length}).ok();
    model_valid_ = validate_stiffness_model(m).ok();
    // orthoglide_chains' springs; the chains' validation (vjm::Chain::validate) refuses a spring that
    // is not symmetric positive definite, which only the overrides can be.
    const Mat6 foot =
        m.foot_spring ? *m.foot_spring
                      : vjm::cantilever_spring(m.foot_material, m.foot_section, m.foot_length, BeamTheory::kTimoshenko);
    const Mat6 bar = m.bar_spring ? *m.bar_spring
                                  : vjm::cantilever_spring(m.bar_material, m.bar_section, m.link_length,
                                                           BeamTheory::kEulerBernoulli);
    const auto spd = [](const Mat6& K) {
      return K.allFinite() && (K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * K.cwiseAbs().maxCoeff() &&
             K.llt().info() == Eigen::Success;
    };
    springs_valid_ = spd(foot) && spd(bar);
    foot_ = foot;
    bar_ = bar;
    for (int i = 0; i < 3; ++i) {
      // Base frame of chain i: x = -e_i, y = -e_(i+1), z = e_(i+2).
      base_[i] << -Vec3::Unit(i), -Vec3::Unit((i + 1) % 3), Vec3::Unit((i + 2) % 3);
      foot_compliance_[i] = rotate6(inverse_spd(foot), base_[i]);
    }
    leg_compliance_ = inverse_spd(2.0 * bar);
    bar_compliance_ = inverse_spd(bar);
  }

  PostureResult evaluate(const Vec3& p) override { return evaluate_loaded_or_not(p, false); }
  PostureResult evaluate_next(const Vec3& p) override { return evaluate_loaded_or_not(p, true); }

  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<OrthoglideKernel>(*this); }
  std::string description() const override {
    const char* mode = o_.wrench ? "loaded under a wrench" : o_.displacement ? "loaded by a displacement" : "unloaded";
    return fmt::format("Orthoglide {} (VJM, {})", o_.architecture == OrthoglideArchitecture::kPUU ? "3-PUU" : "3-PRPaR",
                       mode);
  }

 private:
  // warm: the loaded equilibrium may start from the previous posture's (evaluate_next), which must
  // then have ended kOk.
  PostureResult evaluate_loaded_or_not(const Vec3& p, bool warm) {
    PostureResult r = evaluate(p, warm);
    if (r.status != PostureStatus::kOk) loaded_.forget();
    return r;
  }

  PostureResult evaluate(const Vec3& p, bool warm) {
    PostureResult r;
    if (!geometry_valid_) return r;
    const std::optional<Vec3> rho = try_inverse_kinematics(OrthoglideGeometry{o_.model.link_length}, p);
    if (!rho || serial_singular(p, *rho)) return r;  // kUnreachable, as velocity_transmission_at fails
    r.singularity_measure = singularity_measure(p, *rho);
    if (!model_valid_) return r;  // orthoglide_chains fails: kUnreachable
    r.status = springs_valid_ ? PostureStatus::kSingular : PostureStatus::kFailed;
    if (!springs_valid_) return r;
    Mat6 K;
    double length_scale = 0.0;  // of the platform: the largest chain's
    // The loaded mode needs the unloaded stiffness only for its warm start's branch test.
    const bool unloaded = !(o_.wrench || o_.displacement) || warm;
    const bool regular = unloaded && unloaded_stiffness(p, *rho, K, length_scale);
    if (o_.wrench || o_.displacement) return loaded(p, *rho, regular ? &K : nullptr, warm, r);
    if (regular) fixed_vjm::set_platform_result(K, fixed_vjm::twist_scale(length_scale), Vec6::Zero(), r);
    return r;
  }

  // The sum of the chains' stiffnesses (eq. 10); false where a chain's is not defined.
  bool unloaded_stiffness(const Vec3& p, const Vec3& rho, Mat6& K, double& length_scale) const {
    K.setZero();
    for (int i = 0; i < 3; ++i) {
      Mat6 Ki;
      if (!chain_stiffness(i, p, rho[i], Ki)) return false;
      K += Ki;
      length_scale = std::max(length_scale, chain_length_scale(rho[i]));
    }
    return true;
  }

  // sigma_min / sigma_max of J^-1 (eq. 5), as velocity_transmission; 0 where not finite.
  static double singularity_measure(const Vec3& p, const Vec3& rho) {
    Mat3 Jinv;
    for (int i = 0; i < 3; ++i) {
      Vec3 bar = p;
      bar[i] -= rho[i];
      Jinv.row(i) = bar.transpose() / bar[i];
    }
    const Vec3 sv = Eigen::JacobiSVD<Mat3>(Jinv).singularValues();
    const double measure = sv[2] / sv[0];
    return std::isfinite(measure) ? measure : 0.0;
  }

  // vjm::Chain::length_scale of chain i: its translations (leg L, platform d) and the actuator's
  // prismatic offset rho_i + d.
  double chain_length_scale(double rho) const {
    const double d = o_.model.platform_offset;
    return o_.model.link_length + d + std::abs(rho + d);
  }

  // Stiffness of chain i at the tool point p (eq. 10). Its factors (orthoglide_stiffness.hpp): base
  // frame R, actuator along e_i with its spring, foot spring at the slider o_f = (rho_i + d) e_i,
  // U joint (q1 about z = R e_z, q2 about y1), the leg of direction u to o_l = o_f + L u, then
  //   3-PUU: the leg spring in the leg's axes R2 = (u, y1, u x y1), U joint (q3 about y1, q4 about z);
  //   3-PRPaR: the coupled -q2 (with q2: a translation y1 x L u), the parallelogram spring in the
  //   axes R1 = (x1, y1, z) at bar angle q2, the platform R joint q4 about z;
  // then the platform (o_l - d e_i = p). R1 = R R_z(q1) and R2 = R1 R_y(q2) are built from u (the
  // angles of orthoglide_chains without the trigonometry).
  bool chain_stiffness(int i, const Vec3& p, double rho, Mat6& K) const {
    const double L = o_.model.link_length, d = o_.model.platform_offset;
    const Vec3 e = Vec3::Unit(i);
    const Vec3 z = base_[i].col(2);
    const Vec3 u = (p - rho * e).normalized();
    const Vec3 h = u - u.dot(z) * z;
    const Vec3 x1 = h.normalized(), y1 = z.cross(x1);
    const Vec3 of = (rho + d) * e, ol = of + L * u, t = ol - d * e;
    Mat6 S = transfer_compliance(foot_compliance_[i], t - of);
    S.topLeftCorner<3, 3>() += e * e.transpose() / o_.model.actuator_stiffness;
    // Both legs transmit the force along the leg line; the U joints (axes z, y1) the moment about
    // z x y1 = -x1, the parallelogram and R joint the moments about x1 and y1.
    if (o_.architecture == OrthoglideArchitecture::kPUU) {
      Mat3 R2;
      R2 << u, y1, u.cross(y1);
      S += transfer_compliance(rotate6(leg_compliance_, R2), t - ol);
      Eigen::Matrix<double, 6, 2> N;
      N << line_force(u, ol, t), couple(x1);
      return fixed_vjm::chain_stiffness<2>(N, S, K);
    }
    Mat3 R1;
    R1 << x1, y1, z;
    // q2 = atan2(-u.z, |h|): the bar angle of the parallelogram.
    Mat6 plg;
    if (!parallelogram_stiffness(h.norm(), -u.dot(z), plg)) return false;
    S += transfer_compliance(rotate6(inverse_spd(plg), R1), t - ol);
    Eigen::Matrix<double, 6, 3> N;
    N << line_force(u, ol, t), couple(x1), couple(y1);
    return fixed_vjm::chain_stiffness<3>(N, S, K);
  }

  // parallelogram_spring(model, q) for cos q = c, sin q = s (fixed_size_vjm.hpp).
  bool parallelogram_stiffness(double c, double s, Mat6& K) const {
    return fixed_vjm::parallelogram_stiffness(bar_compliance_, o_.model.link_length, o_.model.parallelogram_width, c, s,
                                              K);
  }

  PostureResult loaded(const Vec3& p, const Vec3& rho, const Mat6* unloaded, bool warm, PostureResult& r);

  OrthoglideKernelOptions o_;
  bool geometry_valid_ = false, model_valid_ = false, springs_valid_ = false;
  std::array<Mat3, 3> base_;
  std::array<Mat6, 3> foot_compliance_;   // global axes, about the slider point
  Mat6 leg_compliance_, bar_compliance_;  // in their own axes
  Mat6 foot_, bar_;                       // stiffness in their own axes
  fixed_vjm::LoadedPlatform loaded_;      // the chains of the loaded mode, rebuilt per posture
};

// The chains of orthoglide_chains, factor by factor, for the loaded mode.
PostureResult OrthoglideKernel::loaded(const Vec3& p, const Vec3& rho, const Mat6* unloaded, bool warm,
                                       PostureResult& r) {
  const double L = o_.model.link_length, d = o_.model.platform_offset;
  loaded_.num_chains = 3;
  for (int i = 0; i < 3; ++i) {
    fixed_vjm::FixedChain& c = loaded_.chains[i];
    c.clear();
    const Mat3& R = base_[i];
    c.add_transform(R, Vec3::Zero());
    c.add_prismatic_actuator(-Vec3::UnitX(), rho[i] + d, o_.model.actuator_stiffness);
    c.add_spring(foot_);
    const Vec3 v = R.transpose() * (p - rho[i] * Vec3::Unit(i)) / L;
    const double q1 = std::atan2(v.y(), v.x()), q2 = std::atan2(-v.z(), std::hypot(v.x(), v.y()));
    c.add_passive(Vec3::UnitZ(), q1);
    if (o_.architecture == OrthoglideArchitecture::kPUU) {
      c.add_passive(Vec3::UnitY(), q2);
      c.add_transform(Mat3::Identity(), L * Vec3::UnitX());
      c.add_spring(2.0 * bar_);
      c.add_passive(Vec3::UnitY(), -q2);
    } else {
      Mat6 plg;
      if (!parallelogram_stiffness(std::cos(q2), std::sin(q2), plg)) return r;
      const int k = c.add_passive(Vec3::UnitY(), q2);
      c.add_transform(Mat3::Identity(), L * Vec3::UnitX());
      c.add_coupled(Vec3::UnitY(), k, -1.0);
      c.add_spring(plg);
    }
    c.add_passive(Vec3::UnitZ(), -q1);
    if (d > 0) c.add_transform(Mat3::Identity(), d * Vec3::UnitX());
    c.add_transform(R.transpose(), Vec3::Zero());
  }
  // A wrench wins over a displacement, as in the reference.
  loaded_.evaluate(p, o_.wrench ? nullptr : &*o_.displacement, o_.wrench ? &*o_.wrench : nullptr, unloaded, warm, r);
  return r;
}

}  // namespace

Status validate(const OrthoglideKernelOptions& options) {
  if (Status s = validate_stiffness_model(options.model); !s.ok()) return s;
  if (options.wrench && options.displacement)
    return Status::Invalid(
        "wrench and displacement: the loaded mode takes one of them (an external wrench or a "
        "prescribed tool displacement); set the other to None");
  if (options.wrench) {
    if (Status s = check_entries(options.wrench->head<3>(), Quantity::kForce, "wrench (force, N)"); !s.ok()) return s;
    if (Status s = check_entries(options.wrench->tail<3>(), Quantity::kMoment, "wrench (moment, N m)"); !s.ok())
      return s;
  }
  if (options.displacement) {
    if (Status s = check_entries(options.displacement->head<3>(), Quantity::kLength, "displacement (m)"); !s.ok())
      return s;
    if (Status s = check_entries(options.displacement->tail<3>(), Quantity::kAngle, "displacement (rad)"); !s.ok())
      return s;
  }
  return Status::Ok();
}

std::unique_ptr<PostureKernel> make_orthoglide_kernel(const OrthoglideKernelOptions& options) {
  return std::make_unique<OrthoglideKernel>(options);
}

}  // namespace kinestat::mechanisms
