#include "kinestat/mechanisms/robot_kernel.hpp"

#include <algorithm>
#include <array>

#include <fmt/format.h>

#include "kinestat/mechanisms/robot_msa.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "mechanisms/fixed_chain.hpp"
#include "mechanisms/path_extrapolation.hpp"

namespace kinestat::mechanisms {

std::array<int, 3> default_map_axes(const RobotModel& model) {
  std::array<int, 3> axes{-1, -1, -1};
  const auto& task = model.description().task;
  for (std::size_t t = 0; t < task.size(); ++t)
    if (task[t] <= TaskCoordinate::kZ) axes[static_cast<int>(task[t])] = static_cast<int>(t);
  return axes;
}

Status validate(const RobotKernelOptions& o) {
  if (!o.model) return Status::Invalid("robot kernel: no model");
  const int n = static_cast<int>(o.model->description().task.size());
  if (o.task.size() != 0 && o.task.size() != n)
    return Status::Invalid(fmt::format("robot kernel: {} task values for {} task coordinates", o.task.size(), n));
  if (!o.task.allFinite()) return Status::Invalid("robot kernel: a task value is not finite");
  if (o.map_axes) {
    for (int a = 0; a < 3; ++a) {
      const int t = (*o.map_axes)[a];
      if (t < -1 || t >= n)
        return Status::Invalid(
            fmt::format("robot kernel: map axis {} names task coordinate {}, "
                        "which does not exist",
                        "xyz"[a], t));
      for (int b = 0; b < a; ++b)
        if (t >= 0 && (*o.map_axes)[b] == t)
          return Status::Invalid(
              fmt::format("robot kernel: map axes {} and {} set the same task coordinate", "xyz"[b], "xyz"[a]));
    }
  }
  if (o.wrench && o.displacement) return Status::Invalid("robot kernel: give a wrench or a displacement, not both");
  if ((o.wrench && !o.wrench->allFinite()) || (o.displacement && !o.displacement->allFinite()))
    return Status::Invalid("robot kernel: the load is not finite");
  if (o.method == StiffnessMethod::kMsa) {
    if (o.wrench || o.displacement)
      return Status::Invalid(
          "robot kernel: the loaded mode (a wrench or a displacement) is computed by the VJM only; "
          "use the VJM method (--method vjm), or drop the load for MSA");
    // The structure at home: a model MSA cannot express is refused here, not point by point.
    if (auto s = robot_msa_structure(*o.model, o.model->home()); !s.ok()) return s.status();
  }
  return Status::Ok();
}

namespace {

// The inverse of a symmetric compliance on its range (eigenvalues above 1e-13 of the largest, as
// cartesian_from_compliance finds rigid directions).
Mat6 pseudo_inverse(const Mat6& C) {
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(C);
  const double cmax = eig.eigenvalues().cwiseAbs().maxCoeff();
  Vec6 inv = Vec6::Zero();
  for (int i = 0; i < 6; ++i)
    if (eig.eigenvalues()(i) > 1e-13 * cmax) inv(i) = 1.0 / eig.eigenvalues()(i);
  return eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
}

class RobotKernel final : public PostureKernel {
 public:
  explicit RobotKernel(const RobotKernelOptions& o)
      : o_(o), axes_(o.map_axes ? *o.map_axes : default_map_axes(*o.model)), data_(make_robot_data(*o.model)) {
    if (o_.task.size() == 0) o_.task = o_.model->home_task();
    task_ = o_.task;
    posture_ = o_.model->home();
    if (o_.method == StiffnessMethod::kVjm) {
      chains_ = make_robot_vjm_chains(*o_.model);
      // The regular path's data (K_theta factored; loaded, the unloaded stiffness that the warm
      // start's branch test needs); a model whose chains do not validate leaves it empty, and every
      // posture takes the reference path, which says why.
      if (!vjm::prepare_regular_stiffness(chains_.chains, regular_).ok()) regular_.chains.clear();
      loaded_.fallbacks = false;  // loaded(): the reference is the fallback
    }
  }

  PostureResult evaluate(const Vec3& point) override {
    warm_ = false;
    posture_ = o_.model->home();
    set_task(point);
    history_.clear();
    const KinematicsResult k = solve_posture(*o_.model, task_, posture_, data_, true);
    record(point);
    return finish(k);
  }

  // Newton from the previous point's posture; along a row of the map's path (the same grid step as
  // the last ones) from the extrapolation of the last two to five postures, whose error is of
  // that order in the step: from four, Newton's first step mostly lands within the tolerance on the
  // Delta's 10 mm grid (the line through two left 3e-4, the parabola through three 6e-6, and a step
  // from either 1e-11, above the tolerance: one Newton iteration more; benchmarks/README.md). A start that
  // fails is retried from the previous posture, then by the walk from home: the same branch tests
  // accept the answer either way. A regular closure on home's working mode beyond a joint's limits
  // or on another assembly mode is the point's answer too (unreachable, with no walk from home,
  // which would end at the same closure: KinematicsResult::closed) and the next point's start: a map
  // crosses those regions as it crosses the reachable one.
  PostureResult evaluate_next(const Vec3& point) override {
    if (!solved_) return evaluate(point);
    const RobotPosture& start = history_[0].posture;  // posture_'s
    set_task(point);
    const int order = extrapolation_order(
        point, [&](int k) { return history_[k].point; }, history_.size());
    if (order >= 2) {
      const auto P = [&](int k) -> const RobotPosture& { return history_[k].posture; };
      const std::array<double, kMaxExtrapolationOrder>& c = kExtrapolationWeights[order - 1];
      posture_.q = c[0] * start.q;
      posture_.tool.translation() = c[0] * start.tool.translation();
      for (int k = 1; k < order; ++k) {
        posture_.q += c[k] * P(k).q;
        posture_.tool.translation() += c[k] * P(k).tool.translation();
      }
      // The rotation by its increments w_k = log(R_k R_(k+1)^T), extrapolated one order lower, then
      // exp(w) R_0. (R_0 R_1^T R_0, the line's, is a rotation to round-off only, and extrapolating
      // from it again multiplied its departure from one by 1 + sqrt 2 per point, which Newton's steps
      // (exp(w) R) keep and its residual does not see: the Orthoglide file's 2.6e-8 after 80 points
      // of a map's path stalled a loaded equilibrium on the chains' tool factor R^T.)
      Vec3 w = Vec3::Zero();
      for (int k = 0; k + 1 < order; ++k) {
        const Eigen::AngleAxisd aa(Mat3(P(k).tool.linear() * P(k + 1).tool.linear().transpose()));
        w += kExtrapolationWeights[order - 2][k] * aa.angle() * aa.axis();
      }
      const double angle = w.norm();
      const Mat3 turn = angle > 0 ? Mat3(Eigen::AngleAxisd(angle, w / angle)) : Mat3::Identity();
      posture_.tool.linear() = Eigen::Quaterniond(turn * start.tool.linear()).normalized().toRotationMatrix();
      const KinematicsResult k = solve_posture(*o_.model, task_, posture_, data_, false);
      if (k.closed) return next(point, k);
      posture_ = start;
    }
    const KinematicsResult k = solve_posture(*o_.model, task_, posture_, data_, false);
    if (k.closed) return next(point, k);
    posture_ = start;
    return evaluate(point);
  }

  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<RobotKernel>(o_); }

  std::string description() const override {
    const char* mode = o_.wrench ? "loaded under a wrench" : o_.displacement ? "loaded by a displacement" : "unloaded";
    return fmt::format("{} ({}, {})", o_.model->description().name, to_string(o_.method), mode);
  }

 private:
  void set_task(const Vec3& point) {
    for (int a = 0; a < 3; ++a)
      if (axes_[a] >= 0) task_(axes_[a]) = point(a);
  }

  // A solved neighbour: the path goes on.
  PostureResult next(const Vec3& point, const KinematicsResult& k) {
    warm_ = true;
    record(point);
    return finish(k);
  }

  // posture_ at `point`, the path's latest (a start for the next point once finish() finds it solved).
  void record(const Vec3& point) {
    PathEntry& e = history_.push();
    e.point = point;
    e.posture = posture_;
  }

  // A loaded warm start continues only a point that ended kOk.
  PostureResult finish(const KinematicsResult& k) {
    PostureResult r = stiffness(k);
    if (r.status != PostureStatus::kOk) loaded_.forget();
    return r;
  }

  PostureResult stiffness(const KinematicsResult& k) {
    PostureResult r;
    solved_ = k.closed;
    r.singularity_measure = k.singularity_measure;
    if (k.status == KinematicsStatus::kUnreachable || k.status == KinematicsStatus::kOtherBranch) return r;
    r.status = PostureStatus::kSingular;
    if (k.status == KinematicsStatus::kSingular) return r;
    StatusOr<CartesianStiffness> K = Status::Internal("not computed");
    if (o_.method == StiffnessMethod::kVjm) set_robot_vjm_posture(*o_.model, posture_, chains_);
    const std::vector<vjm::Chain>& chains = chains_.chains;
    if (o_.method == StiffnessMethod::kVjm && !o_.wrench && !o_.displacement &&
        vjm::regular_platform_unloaded_stiffness(chains, regular_, regular_result_)) {
      // A regular posture (vjm/stiffness.hpp): platform_unloaded_stiffness's answer, found faster.
      set_stiffness(r, regular_result_.stiffness, regular_result_.compliance);
      r.status = PostureStatus::kOk;
      return r;
    }
    if (o_.method == StiffnessMethod::kMsa) {
      const StatusOr<msa::Structure> s = robot_msa_structure(*o_.model, posture_);
      if (!s.ok()) {
        r.status = PostureStatus::kFailed;
        return r;
      }
      K = msa::cartesian_stiffness(*s, workspace_, *s->report_node());
      // Rigid directions (exact ties): MSA gives the compliance only; the finite part is its
      // pseudo-inverse, zero along them (the VJM's sum of the legs' finite parts may differ along
      // them, the same on the complement).
      if (K.ok() && K->compliance_defined && !K->stiffness_defined) K->stiffness = pseudo_inverse(K->compliance);
    } else if (o_.wrench || o_.displacement) {
      if (loaded(r)) return r;
      auto state = o_.wrench ? vjm::platform_equilibrium_under_wrench(chains, *o_.wrench)
                             : vjm::platform_equilibrium(chains, *o_.displacement);
      if (!state.ok()) {
        r.status = state.status().code() == StatusCode::kSingular ? PostureStatus::kSingular : PostureStatus::kFailed;
        return r;
      }
      r.deflection = state->displacement;
      K = vjm::platform_loaded_stiffness(chains, *state);
    } else {
      K = vjm::platform_unloaded_stiffness(chains);
    }
    if (!K.ok()) {
      if (K.status().code() != StatusCode::kSingular) r.status = PostureStatus::kFailed;
      return r;
    }
    if (!K->compliance_defined) return r;  // a free direction; rigid ones are kept (header)
    set_stiffness(r, K->stiffness, K->compliance);
    r.status = PostureStatus::kOk;
    return r;
  }

  // The loaded mode by the sweep kernels' equilibrium (fixed_chain.hpp: the coupled iteration,
  // warm-started along the map's path) on the legs' chains at this posture. Its kOk answers are
  // kept (they equal the reference's within the equilibrium's conditioning: robot_test.cpp); every
  // other point, and chains beyond its capacity, take the reference (vjm), whose statuses and rank
  // decisions are the library's.
  bool loaded(PostureResult& r) {
    const std::vector<vjm::Chain>& chains = chains_.chains;
    if (static_cast<int>(chains.size()) > fixed_vjm::kMaxChains) return false;
    loaded_.num_chains = static_cast<int>(chains.size());
    for (std::size_t i = 0; i < chains.size(); ++i)
      if (!loaded_.chains[i].assign(chains[i])) return false;
    const bool regular =
        !regular_.chains.empty() && vjm::regular_platform_unloaded_stiffness(chains, regular_, regular_result_);
    PostureResult fast = r;
    loaded_.evaluate(history_[0].point, o_.displacement ? &*o_.displacement : nullptr,
                     o_.wrench ? &*o_.wrench : nullptr, regular ? &regular_result_.stiffness : nullptr, warm_, fast);
    if (fast.status != PostureStatus::kOk) {
      loaded_.forget();
      return false;
    }
    r = fast;
    return true;
  }

  RobotKernelOptions o_;
  std::array<int, 3> axes_;
  RobotData data_;
  VecX task_;  // the task at the current point
  RobotPosture posture_;
  // The path's points and their postures, posture_'s first (extrapolation, evaluate_next).
  struct PathEntry {
    Vec3 point = Vec3::Zero();
    RobotPosture posture;
  };
  PathHistory<PathEntry, kMaxExtrapolationOrder> history_;
  RobotVjmChains chains_;  // VJM: the legs' chains, moved to each posture
  vjm::RegularStiffnessData regular_;
  CartesianStiffness regular_result_;
  bool solved_ = false;               // posture_ closes on home's working mode: the next start
  bool warm_ = false;                 // the posture continues the previous point's (evaluate_next)
  fixed_vjm::LoadedPlatform loaded_;  // loaded mode: the legs' chains at each posture
  msa::Workspace workspace_;          // MSA: the factorization's symbolic analysis, kept across postures
};

}  // namespace

std::unique_ptr<PostureKernel> make_robot_kernel(const RobotKernelOptions& options) {
  return std::make_unique<RobotKernel>(options);
}

}  // namespace kinestat::mechanisms
