// Reference posture kernels: today's single-posture library paths called once per point. Slow
// (a sparse solve or a full VJM build per posture), but independent of the sweep kernels, which
// tests compare against them.
#include <cmath>

#include <fmt/format.h>

#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::mechanisms {

const char* to_string(StiffnessMethod m) { return m == StiffnessMethod::kMsa ? "MSA" : "VJM"; }

namespace {

// Fills stiffness, compliance and indices from a regular 6x6 compliance.
void set_from_compliance(PostureResult& r, const Mat6& C, const Vec6& load) {
  set_stiffness(r, C.inverse(), C);
  r.deflection = C * load;
  r.status = PostureStatus::kOk;
}

class ReferenceFiveBarKernel final : public PostureKernel {
 public:
  explicit ReferenceFiveBarKernel(const FiveBarKernelOptions& o) : o_(o) {}

  PostureResult evaluate(const Vec3& point) override {
    PostureResult r;
    auto q = inverse_kinematics(o_.params, Vec2(point.x(), point.y()), o_.mode);
    if (!q.ok() || q->assembly != o_.assembly) return r;  // kUnreachable
    const FiveBarJacobians jac = five_bar_jacobians(*q);
    r.singularity_measure = std::min(jac.parallel_measure, jac.serial_measure);
    r.status = PostureStatus::kSingular;
    if (o_.method == StiffnessMethod::kMsa) {
      const msa::Structure s = make_five_bar_structure(o_.params, *q);
      auto cs = msa::cartesian_stiffness(s, ws_, kFiveBarPlatformNode);
      if (!cs.ok()) {
        if (cs.status().code() != StatusCode::kSingular) r.status = PostureStatus::kFailed;
        return r;
      }
      if (!cs->stiffness_defined) return r;
      set_from_compliance(r, cs->compliance, o_.load);
    } else {
      auto k = vjm::platform_unloaded_stiffness(five_bar_vjm_chains(o_.params, *q));
      if (!k.ok()) {
        if (k.status().code() != StatusCode::kSingular) r.status = PostureStatus::kFailed;
        return r;
      }
      if (!k->status.ok() || !k->compliance_defined || !k->rigid_directions.empty()) return r;
      set_from_compliance(r, k->compliance, o_.load);
    }
    return r;
  }
  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<ReferenceFiveBarKernel>(o_); }
  std::string description() const override {
    return fmt::format("five-bar {} {} ({}, reference path)", to_string(o_.mode), to_string(o_.assembly),
                       to_string(o_.method));
  }

 private:
  FiveBarKernelOptions o_;
  msa::Workspace ws_;
};

class ReferenceOrthoglideKernel final : public PostureKernel {
 public:
  explicit ReferenceOrthoglideKernel(const OrthoglideKernelOptions& o) : o_(o) {}

  PostureResult evaluate(const Vec3& point) override {
    PostureResult r;
    auto vt = velocity_transmission_at(OrthoglideGeometry{o_.model.link_length}, point);
    if (!vt.ok()) return r;                           // kUnreachable (outside a leg's cylinder)
    r.singularity_measure = vt->mu_min / vt->mu_max;  // sigma_min / sigma_max
    if (!std::isfinite(r.singularity_measure)) r.singularity_measure = 0.0;
    auto chains = orthoglide_chains(o_.model, o_.architecture, point);
    if (!chains.ok()) return r;
    r.status = PostureStatus::kSingular;
    StatusOr<CartesianStiffness> k = Status::Internal("not computed");
    Vec6 deflection = Vec6::Zero();
    if (o_.wrench || o_.displacement) {
      auto state = o_.wrench ? vjm::platform_equilibrium_under_wrench(*chains, *o_.wrench)
                             : vjm::platform_equilibrium(*chains, *o_.displacement);
      if (!state.ok()) {
        r.status = PostureStatus::kFailed;
        return r;
      }
      deflection = state->displacement;
      k = vjm::platform_loaded_stiffness(*chains, *state);
    } else {
      k = vjm::platform_unloaded_stiffness(*chains);
    }
    if (!k.ok()) {
      if (k.status().code() != StatusCode::kSingular) r.status = PostureStatus::kFailed;
      return r;
    }
    if (!k->status.ok() || !k->compliance_defined || !k->rigid_directions.empty()) return r;
    set_from_compliance(r, k->compliance, Vec6::Zero());
    r.deflection = deflection;
    return r;
  }
  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<ReferenceOrthoglideKernel>(o_); }
  std::string description() const override {
    const char* mode = o_.wrench ? "loaded under a wrench" : o_.displacement ? "loaded by a displacement" : "unloaded";
    return fmt::format("Orthoglide {} (VJM, {}, reference path)",
                       o_.architecture == OrthoglideArchitecture::kPUU ? "3-PUU" : "3-PRPaR", mode);
  }

 private:
  OrthoglideKernelOptions o_;
};

}  // namespace

std::unique_ptr<PostureKernel> make_reference_five_bar_kernel(const FiveBarKernelOptions& options) {
  return std::make_unique<ReferenceFiveBarKernel>(options);
}

std::unique_ptr<PostureKernel> make_reference_orthoglide_kernel(const OrthoglideKernelOptions& options) {
  return std::make_unique<ReferenceOrthoglideKernel>(options);
}

}  // namespace kinestat::mechanisms
