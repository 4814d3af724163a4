// The robot files of models/robots/ against independent routes (issue #19, item 7): the hexapod
// against K = J^T diag(k) J (Gosselin 1990), the Delta against its closed-form loop closure, the
// generic five-bar against the built-in kernel, home closure, and the checks of a robot file.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/orthoglide_frame.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/robot_msa.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "mechanisms/robot_equations.hpp"

namespace kinestat {
namespace {

using namespace mechanisms;

std::string robot_file(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/models/robots/" + name; }

RobotModel load(const std::string& name, const io::ParamOverrides& o = {}) {
  auto m = io::read_robot_model(robot_file(name), o);
  EXPECT_TRUE(m.ok()) << m.status().message();
  return std::move(*m);
}

double param(const RobotModel& m, const std::string& name) {
  for (const auto& [n, v] : m.description().params)
    if (n == name) return v;
  ADD_FAILURE() << "no parameter " << name;
  return 0.0;
}

// Every bundled robot closes at home: each leg's chain ends at the tool pose to round-off.
TEST(RobotFiles, HomeClosesEveryLeg) {
  for (const char* name : {"hexapod.yaml", "delta.yaml", "five_bar.yaml", "planar_3rpr.yaml", "prs_head.yaml",
                           "orthoglide_puu.yaml", "orthoglide_prpar.yaml"}) {
    SCOPED_TRACE(name);
    const RobotModel m = load(name);
    for (int l = 0; l < m.num_legs(); ++l) {
      const vjm::Transform T = m.kinematic_chain(l).forward(VecX::Zero(m.leg_coordinates(l)), VecX());
      EXPECT_LT((T.translation() - m.description().tool).norm(), 1e-12 * m.length_scale());
      EXPECT_LT((T.linear() - Mat3::Identity()).norm(), 1e-12);
    }
  }
}

// The hexapod with axial leg springs only: K = J^T diag(k) J, J's rows (u_i, r_i x u_i) from the
// unit leg directions u_i and the platform joints r_i relative to the tool point (Gosselin 1990).
// The two routes share no code beyond the solved posture's joint positions, which are recomputed
// here from the platform pose. Round-off of the VJM's SVD-based stiffness: ~1e-12; bound 1e-9. MSA
// too: its legs, rigid but for their joints, close loops of exact ties, which msa eliminates as
// constraints after the trees of ties (msa/dof_map.hpp); measured MEASURED relative.
TEST(RobotFiles, HexapodMatchesGosselin) {
  auto model = std::make_shared<const RobotModel>(load("hexapod.yaml"));
  const double k = param(*model, "leg_stiffness") * 1e3;  // N/mm -> N/m
  RobotData data = make_robot_data(*model);
  for (const Vec6& pose : {Vec6((Vec6() << 0, 0, 0.8, 0, 0, 0).finished()),
                           Vec6((Vec6() << 0.05, -0.08, 0.75, 0.1, -0.05, 0.2).finished()),
                           Vec6((Vec6() << -0.1, 0.02, 0.86, -0.08, 0.12, -0.3).finished())}) {
    RobotPosture p = model->home();
    const KinematicsResult r = solve_posture(*model, pose, p, data);
    ASSERT_EQ(r.status, KinematicsStatus::kOk) << r.message;
    auto K = vjm::platform_unloaded_stiffness(robot_vjm_chains(*model, p));
    ASSERT_TRUE(K.ok());
    ASSERT_TRUE(K->status.ok()) << K->status.message();
    // Base and platform joints: the legs' first and last joint points, the platform's moved.
    MatX J(6, 6);
    for (int l = 0; l < 6; ++l) {
      const auto& items = model->description().legs[l].items;
      const Vec3 b = std::get<RobotJoint>(items.front()).at;
      const Vec3 s_home = std::get<RobotJoint>(items.back()).at;
      const Vec3 r_i = p.tool.linear() * (s_home - model->description().tool);
      const Vec3 s = p.tool.translation() + r_i;
      const Vec3 u = (s - b).normalized();
      J.row(l) << u.transpose(), r_i.cross(u).transpose();
    }
    const Mat6 expected = k * J.transpose() * J;
    EXPECT_LT((K->stiffness - expected).norm(), 1e-9 * expected.norm());
    const auto s = robot_msa_structure(*model, p);
    ASSERT_TRUE(s.ok()) << s.status().message();
    msa::Workspace ws;
    const auto Km = msa::cartesian_stiffness(*s, ws, *s->report_node());
    ASSERT_TRUE(Km.ok() && Km->stiffness_defined) << (Km.ok() ? Km->note : Km.status().message());
    const double d = (Km->stiffness - expected).norm() / expected.norm();
    EXPECT_LT(d, 1e-9);
    std::printf("hexapod at (%g, %g, %g): MSA - J^T diag(k) J %.1e relative\n", pose(0), pose(1), pose(2), d);
  }
}

// The map kernel's regular path (vjm::regular_platform_unloaded_stiffness on chains built once and
// moved per posture) against vjm::platform_unloaded_stiffness of robot_vjm_chains at the same
// solved postures of each bundled robot's workspace: where the regular path answers, the same
// stiffness and compliance to round-off (measured up to 4.1e-13 relative, the Orthoglide; bound 1e-10,
// 250 times that), and it
// answers only where the reference's status is ok with no rigid direction; the rigid Delta (rigid
// rotations) never takes it.
TEST(RobotFiles, RegularStiffnessEqualsReference) {
  RobotDescription rigid_delta = load("delta.yaml").description();
  for (RobotLeg& leg : rigid_delta.legs)
    for (auto& item : leg.items)
      if (auto* link = std::get_if<RobotLink>(&item)) link->spring.reset();
  for (const char* name :
       {"delta.yaml", "hexapod.yaml", "orthoglide_puu.yaml", "orthoglide_prpar.yaml", "five_bar.yaml", "rigid delta"}) {
    SCOPED_TRACE(name);
    const bool rigid = std::string(name) == "rigid delta";
    auto built = rigid ? make_robot_model(rigid_delta) : StatusOr<RobotModel>(load(name));
    ASSERT_TRUE(built.ok());
    const RobotModel& model = *built;
    RobotData data = make_robot_data(model);
    RobotVjmChains chains = make_robot_vjm_chains(model);
    vjm::RegularStiffnessData regular;
    ASSERT_TRUE(vjm::prepare_regular_stiffness(chains.chains, regular).ok());
    const auto& ws = *model.description().workspace;
    const VecX home_task = model.home_task();
    const auto axes = default_map_axes(model);
    int answered = 0, points = 0;
    double worst = 0.0;
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; j <= 6; ++j)
        for (int k = 0; k <= 2; ++k) {
          const Vec3 f(i / 6.0, j / 6.0, k / 2.0);
          VecX task = home_task;
          for (int a = 0; a < 3; ++a)
            if (axes[a] >= 0) task(axes[a]) = ws[a].first + f(a) * (ws[a].second - ws[a].first);
          RobotPosture p = model.home();
          if (solve_posture(model, task, p, data).status != KinematicsStatus::kOk) continue;
          ++points;
          const auto reference = vjm::platform_unloaded_stiffness(robot_vjm_chains(model, p));
          set_robot_vjm_posture(model, p, chains);
          CartesianStiffness fast;
          if (!vjm::regular_platform_unloaded_stiffness(chains.chains, regular, fast)) continue;
          ++answered;
          ASSERT_TRUE(reference.ok());
          ASSERT_TRUE(reference->status.ok()) << reference->status.message();
          ASSERT_TRUE(reference->rigid_directions.empty());
          const double dk = (fast.stiffness - reference->stiffness).norm() / reference->stiffness.norm();
          const double dc = (fast.compliance - reference->compliance).norm() / reference->compliance.norm();
          EXPECT_LT(dk, 1e-10) << task.transpose();
          EXPECT_LT(dc, 1e-10) << task.transpose();
          worst = std::max({worst, dk, dc});
        }
    std::printf("%s: the regular path answered at %d of %d solved postures, up to %.1e from the reference\n", name,
                answered, points, worst);
    if (rigid)
      EXPECT_EQ(answered, 0);
    else
      EXPECT_EQ(answered, points);
    EXPECT_GT(points, 10);
  }
}

// The generic kernel's loaded mode takes the sweep kernels' equilibrium (fixed_chain.hpp: the
// coupled iteration, warm-started along a row) where it converges, and the reference (vjm) elsewhere:
// along rows of each file's workspace, the same status as the reference at the same posture at every
// point, and its stiffness and deflection within 1e-7: the reference's iterations stop at relative
// residuals of 1e-12 (chains) and 1e-10 (the platform's wrench), the fast path's at the round-off
// floor, and the gap is those residuals times the loaded system's conditioning (measured 1.6e-8 on
// the hexapod, 7e-10 on the 3-RPR, 5e-11 on the Orthoglide; printed). The points follow a map's
// serpentine path from one start at home (13 x 7 x 3), so the kinematics extrapolates the platform's
// rotation along rows, as in a map: before the extrapolated rotation was made a rotation again
// (RobotKernel::evaluate_next) its error grew by 1 + sqrt 2 per point and the Orthoglide's loaded
// equilibrium failed from the 20th point on. Every point is answered by the fast path
// (newton_iterations > 0 only there).
TEST(RobotFiles, LoadedKernelEqualsTheReference) {
  const Vec6 wrench = (Vec6() << 10.0, -20.0, -30.0, 0.5, -0.2, 0.3).finished();
  for (const char* name : {"hexapod.yaml", "planar_3rpr.yaml", "orthoglide_puu.yaml", "orthoglide_prpar.yaml"}) {
    SCOPED_TRACE(name);
    const auto model = std::make_shared<const RobotModel>(load(name));
    RobotKernelOptions o;
    o.model = model;
    o.wrench = wrench;
    const auto kernel = make_robot_kernel(o);
    RobotData data = make_robot_data(*model);
    const auto& ws = *model->description().workspace;
    const auto axes = default_map_axes(*model);
    int ok = 0, fast = 0, points = 0;
    double worst = 0.0;
    for (int k = 0; k <= 2; ++k)
      for (int j = 0; j <= 6; ++j)
        for (int n = 0; n <= 12; ++n) {
          const int row = k * 7 + j, i = row % 2 ? 12 - n : n;  // serpentine
          const Vec3 f(i / 12.0, j / 6.0, k / 2.0);
          Vec3 point = Vec3::Zero();
          VecX task = model->home_task();
          for (int a = 0; a < 3; ++a)
            if (axes[a] >= 0) task(axes[a]) = point(a) = ws[a].first + f(a) * (ws[a].second - ws[a].first);
          const PostureResult r = row == 0 && n == 0 ? kernel->evaluate(point) : kernel->evaluate_next(point);
          RobotPosture p = model->home();
          if (solve_posture(*model, task, p, data).status != KinematicsStatus::kOk) continue;
          ++points;
          const std::vector<vjm::Chain> chains = robot_vjm_chains(*model, p);
          const auto state = vjm::platform_equilibrium_under_wrench(chains, wrench);
          const auto K = state.ok() ? vjm::platform_loaded_stiffness(chains, *state)
                                    : StatusOr<CartesianStiffness>(state.status());
          const bool reference_ok = K.ok() && K->compliance_defined;
          ASSERT_EQ(r.status == PostureStatus::kOk, reference_ok) << task.transpose();
          if (!reference_ok) continue;
          ++ok;
          fast += r.newton_iterations > 0;
          const double dk = (r.stiffness - K->stiffness).norm() / K->stiffness.norm();
          const double dd = (r.deflection - state->displacement).norm() / state->displacement.norm();
          EXPECT_LT(dk, 1e-7) << task.transpose();
          EXPECT_LT(dd, 1e-7) << task.transpose();
          worst = std::max({worst, dk, dd});
        }
    std::printf("%s loaded: %d of %d postures ok, %d by the fast path, up to %.1e from the reference\n", name, ok,
                points, fast, worst);
    EXPECT_GT(ok, 20);
    EXPECT_EQ(fast, ok);
  }
}

// The Delta with rigid links and parallelograms and its motor springs: the translational stiffness
// is k_a J^T J, J = d(theta)/dp from the closed-form loop closure |W_i - E_i(theta_i)| = forearm;
// the rotations are rigid. The actuated angles of the generic kinematics equal the closed-form
// roots on the home branch at every point of a grid walked as a map walks it (no branch jump).
TEST(RobotFiles, DeltaMatchesClosedForm) {
  // Rigid arms and forearms: the same file with stiff beams would still bend a little, so the
  // check builds the chains without link springs (the model's joints and actuators only).
  auto model = std::make_shared<const RobotModel>(load("delta.yaml"));
  const double R = param(*model, "base_radius") / 1e3, a = param(*model, "arm") / 1e3,
               b = param(*model, "forearm") / 1e3, r = param(*model, "platform_radius") / 1e3;
  const double ka = param(*model, "motor_stiffness") * 1e-3;  // N mm/rad -> N m/rad
  RobotDescription rigid = model->description();
  for (RobotLeg& leg : rigid.legs)
    for (auto& item : leg.items)
      if (auto* link = std::get_if<RobotLink>(&item)) link->spring.reset();
  auto rigid_model = make_robot_model(rigid);
  ASSERT_TRUE(rigid_model.ok()) << rigid_model.status().message();
  RobotData data = make_robot_data(*rigid_model);
  RobotPosture p = rigid_model->home();
  int compared = 0;
  for (double z = -0.95; z <= -0.55; z += 0.1)
    for (double x = -0.3; x <= 0.3001; x += 0.1)
      for (double y = -0.3; y <= 0.3001; y += 0.1) {
        const Vec3 point(x, y, z);
        // Closed form per leg i (turned by 120 deg i): E = shoulder + a (cos t, 0, -sin t) in the
        // leg's frame, W = p + r e_x; wx cos t - wz sin t = (|w|^2 + a^2 - b^2) / (2a), w = W - shoulder.
        Mat3 dg_dp, dg_dt = Mat3::Zero();
        Vec3 theta;
        bool reachable = true;
        for (int i = 0; i < 3; ++i) {
          const Mat3 Rz = Eigen::AngleAxisd(2.0 * M_PI * i / 3.0, Vec3::UnitZ()).toRotationMatrix();
          const Vec3 w = Rz.transpose() * point + Vec3(r - R, 0, 0);
          const double c = (w.squaredNorm() + a * a - b * b) / (2 * a), A = w.x(), B = -w.z();
          const double rho = std::hypot(A, B);
          if (std::abs(c) > rho) {
            reachable = false;
            break;
          }
          theta(i) = std::atan2(B, A) - std::acos(c / rho);  // the root of the home drawing (0 at home)
          const Vec3 E(a * std::cos(theta(i)), 0, -a * std::sin(theta(i)));
          const Vec3 dE(-a * std::sin(theta(i)), 0, -a * std::cos(theta(i)));
          dg_dp.row(i) = (Rz * (w - E)).transpose();  // d/dp of |w - E|^2 / 2
          dg_dt(i, i) = -(w - E).dot(dE);
        }
        const KinematicsResult k = solve_posture(*rigid_model, point, p, data, compared > 0);
        if (!reachable) continue;
        if (std::abs(theta.maxCoeff()) > 80 * M_PI / 180 || std::abs(theta.minCoeff()) > 80 * M_PI / 180) continue;
        ASSERT_EQ(k.status, KinematicsStatus::kOk) << k.message << " at " << point.transpose();
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.q(rigid_model->leg_offset(i)), theta(i), 1e-10);
        const Mat3 J = -dg_dt.inverse() * dg_dp;  // dtheta/dp
        const Mat3 expected = ka * J.transpose() * J;
        auto K = vjm::platform_unloaded_stiffness(robot_vjm_chains(*rigid_model, p));
        ASSERT_TRUE(K.ok());
        EXPECT_EQ(K->rigid_directions.size(), 3u);
        EXPECT_LT((K->stiffness.topLeftCorner<3, 3>() - expected).norm(), 1e-9 * expected.norm())
            << "at " << point.transpose();
        ++compared;
      }
  EXPECT_GT(compared, 100);
}

// A map crosses the regions where the loop closes on home's working mode at an unreachable point (a
// joint beyond its limits: the Delta's shoulders past +-80 deg; another assembly mode: the
// five-bar's) by Newton from the neighbouring closure, with no walk from home per point
// (RobotKernel::evaluate_next, KinematicsResult::closed): along serpentine rows, every point has the
// status of the walk from home (evaluate), and the same stiffness where kOk and not near-singular
// (1e-9 relative: the closures agree to Newton's 1e-12 tolerance; measured 1e-10 over the Delta
// file's whole map; at the five-bar's points of singularity measure ~1e-7, 8e-8, the conditioning).
TEST(RobotFiles, MapAcrossUnreachableClosuresEqualsWalksFromHome) {
  struct Case {
    const char* file;
    std::vector<double> slices;  // z (m)
    std::array<double, 5> rows;  // x from, x to, y from, y to, step (m)
    KinematicsStatus status;
    const char* message;
  };
  const Case delta{
      "delta.yaml", {-0.55, -0.95}, {-0.4, 0.4, -0.4, 0.4, 0.05}, KinematicsStatus::kUnreachable, "outside its limits"};
  const Case five_bar{
      "five_bar.yaml", {0.0}, {-0.2, 0.2, 0.0, 0.2, 0.01}, KinematicsStatus::kOtherBranch, "another assembly mode"};
  for (const Case& c : {delta, five_bar}) {
    SCOPED_TRACE(c.file);
    RobotKernelOptions o;
    o.model = std::make_shared<const RobotModel>(load(c.file));
    const auto path = make_robot_kernel(o), single = make_robot_kernel(o);
    const auto axes = default_map_axes(*o.model);
    RobotData data = make_robot_data(*o.model);
    const auto [x0, x1, y0, y1, step] = c.rows;
    const int nx = static_cast<int>(std::lround((x1 - x0) / step)),
              ny = static_cast<int>(std::lround((y1 - y0) / step));
    int closed = 0, ok = 0, points = 0;
    for (double z : c.slices)
      for (int j = 0; j <= ny; ++j)
        for (int n = 0; n <= nx; ++n) {
          const int i = j % 2 == 0 ? n : nx - n;
          const Vec3 point(x0 + step * i, y0 + step * j, z);
          const PostureResult r = points++ == 0 ? path->evaluate(point) : path->evaluate_next(point);
          const PostureResult e = single->evaluate(point);
          ASSERT_EQ(r.status, e.status) << point.transpose();
          if (e.status == PostureStatus::kOk && e.singularity_measure > 0.01) {
            ++ok;
            EXPECT_LT((r.stiffness - e.stiffness).norm(), 1e-9 * e.stiffness.norm()) << point.transpose();
          }
          VecX task = o.model->home_task();
          for (int a = 0; a < 3; ++a)
            if (axes[a] >= 0) task(axes[a]) = point(a);
          RobotPosture p = o.model->home();
          const KinematicsResult k = solve_posture(*o.model, task, p, data);
          if (k.closed && k.status != KinematicsStatus::kOk) {
            ++closed;
            EXPECT_EQ(k.status, c.status);
            EXPECT_NE(k.message.find(c.message), std::string::npos) << k.message;
          }
        }
    std::printf("%s: %d points, %d ok, %d closed but unreachable\n", c.file, points, ok, closed);
    EXPECT_GT(ok, 50);
    EXPECT_GT(closed, 20);
  }
}

// The singularity measure (the rcond estimate of the length-scaled Jacobians, over home's) is a
// function of the posture, not of the path to it: along serpentine rows of each file's workspace
// (7 x 7 x 3 points), the map's value equals the walk from home's to 1e-9 relative (the two closures
// agree to Newton's tolerance). Before the estimator broke its ties alike (robot_kinematics.cpp,
// block_rcond), this failed on the hexapod; over whole maps, two routes to the same closures (the
// walk with and without a secant predictor) gave measures 2.7 % apart (median) on the hexapod, up to
// 82 % elsewhere.
TEST(RobotFiles, SingularityMeasureIsTheSameAlongAMap) {
  for (const char* name : {"hexapod.yaml", "orthoglide_puu.yaml", "delta.yaml", "planar_3rpr.yaml"}) {
    SCOPED_TRACE(name);
    RobotKernelOptions o;
    o.model = std::make_shared<const RobotModel>(load(name));
    const auto path = make_robot_kernel(o), single = make_robot_kernel(o);
    const auto& ws = *o.model->description().workspace;
    const auto axes = default_map_axes(*o.model);
    int compared = 0;
    for (int k = 0; k <= 2; ++k)
      for (int j = 0; j <= 6; ++j)
        for (int n = 0; n <= 6; ++n) {
          const int i = j % 2 == 0 ? n : 6 - n;
          const Vec3 f(i / 6.0, j / 6.0, k / 2.0);
          Vec3 point = Vec3::Zero();
          for (int a = 0; a < 3; ++a)
            if (axes[a] >= 0) point(a) = ws[a].first + f(a) * (ws[a].second - ws[a].first);
          const PostureResult r = k + j + n == 0 ? path->evaluate(point) : path->evaluate_next(point);
          const PostureResult e = single->evaluate(point);
          ASSERT_EQ(r.status, e.status) << point.transpose();
          if (e.status != PostureStatus::kOk) continue;
          EXPECT_NEAR(r.singularity_measure, e.singularity_measure, 1e-9 * e.singularity_measure) << point.transpose();
          ++compared;
        }
    EXPECT_GT(compared, 40);
  }
}

// The singularity measure is the condition estimate over home's (robot_model.hpp, KinematicsResult):
// 1 at home, and against an independent route, the exact reciprocal 2-norm condition numbers of the
// same length-scaled Jacobians (JacobiSVD), the smaller of the inverse and direct ones over home's,
// it agrees within a factor of 2 over each file's workspace (7 x 7 x 3 points; measured: within
// 1.30). The 1-norm estimate alone was ~0.005 at every hexapod posture (every point of its map
// near-singular at the default 0.01); over home's, the hexapod's workspace reads 0.85-1.
TEST(RobotFiles, SingularityMeasureIsRelativeToHome) {
  for (const char* name : {"hexapod.yaml", "delta.yaml", "planar_3rpr.yaml"}) {
    SCOPED_TRACE(name);
    const RobotModel m = load(name);
    RobotData data = make_robot_data(m);
    const auto exact = [&](const RobotPosture& p, const VecX& task) {
      const RobotJacobians J = robot_jacobians(m, p, data, task);
      double r = 1.0;
      for (const MatX* A : {&J.inverse, &J.direct}) {
        const VecX s = Eigen::JacobiSVD<MatX>(*A).singularValues();
        r = std::min(r, s(s.size() - 1) / s(0));
      }
      return r;
    };
    RobotPosture home = m.home();
    EXPECT_EQ(solve_posture(m, m.home_task(), home, data).singularity_measure, 1.0);
    const double at_home = exact(m.home(), m.home_task());
    const auto& ws = *m.description().workspace;
    const auto axes = default_map_axes(m);
    int compared = 0;
    for (int k = 0; k <= 2; ++k)
      for (int j = 0; j <= 6; ++j)
        for (int i = 0; i <= 6; ++i) {
          const Vec3 f(i / 6.0, j / 6.0, k / 2.0);
          VecX task = m.home_task();
          for (int a = 0; a < 3; ++a)
            if (axes[a] >= 0) task(axes[a]) = ws[a].first + f(a) * (ws[a].second - ws[a].first);
          RobotPosture p = m.home();
          const KinematicsResult r = solve_posture(m, task, p, data);
          if (r.status != KinematicsStatus::kOk) continue;
          const double e = std::min(1.0, exact(p, task) / at_home);
          EXPECT_LT(r.singularity_measure, 2.0 * e) << task.transpose();
          EXPECT_GT(r.singularity_measure, 0.5 * e) << task.transpose();
          ++compared;
        }
    EXPECT_GT(compared, 20);
  }
}

// The generic five-bar and the built-in kernel's VJM (working mode +-, assembly up: the file's home
// drawing) at every point of a grid: the same status, and the same 6x6 to 1e-9 relative.
TEST(RobotFiles, FiveBarEqualsBuiltInKernel) {
  RobotKernelOptions o;
  o.model = std::make_shared<const RobotModel>(load("five_bar.yaml"));
  const auto generic = make_robot_kernel(o);
  FiveBarKernelOptions f;
  f.mode = WorkingMode{1, -1};
  f.method = StiffnessMethod::kVjm;
  const auto builtin = make_five_bar_kernel(f);
  int ok = 0;
  for (double x = -0.2; x <= 0.2001; x += 0.01)
    for (double y = 0.0; y <= 0.2001; y += 0.01) {
      const Vec3 point(x, y, 0);
      const PostureResult g = generic->evaluate(point), e = builtin->evaluate(point);
      if (e.status == PostureStatus::kOk && e.singularity_measure > 0.01) {
        ASSERT_EQ(g.status, PostureStatus::kOk) << point.transpose();
        EXPECT_LT((g.stiffness - e.stiffness).norm(), 1e-9 * e.stiffness.norm()) << point.transpose();
        ++ok;
      } else if (e.status == PostureStatus::kUnreachable) {
        EXPECT_NE(g.status, PostureStatus::kOk) << point.transpose();
      }
    }
  EXPECT_GT(ok, 50);
}

// A leg's reach (robot_model.hpp), from the geometry: the five-bar's left leg turns about A1 = (-r3, 0)
// with links r1 + r2 = 0.2 m; 1 um beyond it the task is refused before any Newton step, with the
// leg named. The hexapod's legs have prismatic actuators: no reach.
TEST(RobotFiles, ReachOfALeg) {
  const RobotModel m = load("five_bar.yaml");
  EXPECT_LT((m.leg_reach(0).origin - Vec3(-0.1, 0, 0)).norm(), 1e-15);
  EXPECT_NEAR(m.leg_reach(0).radius, 0.2, 1e-15);
  EXPECT_FALSE(std::isfinite(load("hexapod.yaml").leg_reach(0).radius));
  RobotData data = make_robot_data(m);
  RobotPosture p = m.home();
  VecX task(2);
  task << 0.1 + 1e-6, 0.0;
  const KinematicsResult k = solve_posture(m, task, p, data);
  EXPECT_EQ(k.status, KinematicsStatus::kUnreachable);
  EXPECT_EQ(k.iterations, 0);
  EXPECT_NE(k.message.find("beyond the reach of left leg"), std::string::npos) << k.message;
}

// The ring of a leg whose first joint is a revolute, from the Delta's geometry: leg 1's shoulder at
// (0.2, 0, 0) turns about y, its elbow 0.3 m (the arm) out along x, so on the circle of radius 0.3 m
// about the shoulder in the x-z plane; from the elbow the forearm (0.8 m) and the platform's offset
// (0.05 m) reach 0.85 m. The point 1 m along the shoulder's axis is within the ball of 1.15 m, but
// sqrt(1 + 0.3^2) = 1.044 m from the circle: refused before any Newton step, the leg named.
// Tolerances: round-off of lengths of ~1 m (1e-15), 1e-12 where the forearm's length comes from the
// file's square roots.
TEST(RobotFiles, RingOfALegsFirstRevolute) {
  const RobotModel m = load("delta.yaml");
  const RobotModel::Reach& r = m.leg_reach(0);
  EXPECT_NEAR(r.radius, 1.15, 1e-12);
  EXPECT_LT((r.ring_center - Vec3(0.2, 0, 0)).norm(), 1e-15);
  EXPECT_NEAR(std::abs(r.axis.y()), 1.0, 1e-15);
  EXPECT_NEAR(r.ring_radius, 0.3, 1e-15);
  EXPECT_NEAR(r.ring_reach, 0.85, 1e-12);
  EXPECT_NEAR(r.ring_distance(Vec3(0.2, 1.0, 0)), std::sqrt(1.09), 1e-15);
  EXPECT_NEAR(r.ring_distance(Vec3(0.2, 0, -0.3)), 0.0, 1e-15);
  RobotData data = make_robot_data(m);
  RobotPosture p = m.home();
  const KinematicsResult k = solve_posture(m, Vec3(0.2, 1.0, 0), p, data);
  EXPECT_EQ(k.status, KinematicsStatus::kUnreachable);
  EXPECT_EQ(k.iterations, 0);
  EXPECT_NE(k.message.find("beyond the reach of leg 1: its tool point is 1.04403 m from the circle"), std::string::npos)
      << k.message;
}

// Each check of a robot file fails with its message on a planted fault.
std::string write_robot(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

const char* const kGoodPlanar = R"(robot: test 3-RPR
units: mm-N-s
params: {a: 300, px: 25, py: 43.3}
planar: true
task: [x, y, rz]
tool: [0, 0, 0]
legs:
  - copies: 3
    chain:
      - revolute: {at: [a, 0, 0], axis: [0, 0, 1]}
      - prismatic: {at: [a, 0, 0], axis: [px - a, py, 0], actuated: true, stiffness: 1e4}
      - link: {to: [px, py, 0]}
      - revolute: {at: [px, py, 0], axis: [0, 0, 1]}
)";

TEST(RobotFiles, GoodPlanarFileReads) {
  auto m = io::read_robot_model(write_robot("good.yaml", kGoodPlanar));
  ASSERT_TRUE(m.ok()) << m.status().message();
  EXPECT_EQ(m->num_coordinates(), 9);
}

// `good` with `from` replaced by `to` is refused, the message saying `message` and naming the file.
struct PlantedFault {
  std::string from, to, message;
};
void expect_refused(const std::string& good, const PlantedFault& c) {
  std::string text = good;
  const auto at = text.find(c.from);
  ASSERT_NE(at, std::string::npos) << c.from;
  text.replace(at, c.from.size(), c.to);
  auto m = io::read_robot_model(write_robot("bad.yaml", text));
  ASSERT_FALSE(m.ok()) << c.message;
  EXPECT_NE(m.status().message().find(c.message), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("bad.yaml"), std::string::npos) << m.status().message();
}

TEST(RobotFiles, PlantedFaultsNamed) {
  const PlantedFault cases[] = {
      {"      - link: {to: [px, py, 0]}", "      - link: {to: [px, py, 0], length: 20}",
       "between its ends in the drawing, `length` says 20 mm"},
      {", actuated: true, stiffness: 1e4", "", "0 actuated joints for 3 task coordinates"},
      {"actuated: true, ", "", "'stiffness' is the actuator's"},
      {"axis: [0, 0, 1]}\n      - prismatic", "axis: [0, 0, 0]}\n      - prismatic", "the zero vector"},
      {"params: {a: 300,", "params: {a: 300 +,", "cannot evaluate"},
      {"task: [x, y, rz]", "task: [x, y]", "3 actuated joints for 2 task coordinates"},
      {"      - revolute: {at: [px, py, 0], axis: [0, 0, 1]}\n", "", "over-constrain"},
      {"axis: [0, 0, 1]}\n      - prismatic", "axis: [1, 0, 0]}\n      - prismatic", "a planar robot has revolute"},
      {"copies: 3", "copies: 2.5", "whole number"},
      {"revolute: {at: [a, 0, 0]", "revolute: {at: [b, 0, 0]", "cannot evaluate"},
      // A spring that does not resist every deflection: refused when the file is read (before, a map
      // failed at every posture and blamed a load it was not given).
      {"      - link: {to: [px, py, 0]}", "      - link: {to: [px, py, 0], spring: {diagonal: [1, 1, 1, 0, 1, 1]}}",
       "not positive definite (smallest eigenvalue 0)"},
      // Names the file chooses given twice (the last one silently won), angles beyond the range of
      // an angle, limits the wrong way round.
      {"params: {a: 300,", "params: {a: 300, a: 200,", "'a' is given twice"},
      {"copies: 3", "copies: 3\n    turn: 1e300", "'turn' = 1e+300 deg is too large for an angle"},
      {"stiffness: 1e4}", "stiffness: 1e4, limits: [[50, -50]]}", "this one's low is above its high"},
      {"task: [x, y, rz]", "task: [x, y, y]", "'y' is named twice"},
      {"task: [x, y, rz]", "task: [x, y]\nworkspace: {rx: [0, 0], ry: [0, 0], rz: [-5, 5]}",
       "the task commands no angle"},
      {"params: {a: 300,", "params: {2a: 1, a: 300,", "'2a' is not a usable name: a name starts with a letter"},
  };
  for (const PlantedFault& c : cases) expect_refused(kGoodPlanar, c);
  // A parameter set from outside must exist.
  auto m = io::read_robot_model(write_robot("good.yaml", kGoodPlanar), {{"b", 1.0}});
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("no parameter 'b'"), std::string::npos) << m.status().message();
}

// A home drawn 1e-5 mm from the five-bar's full stretch (its inverse Jacobian's sigma_min/sigma_max
// 3.2e-5, printed by the message) is refused: the map's singularity measure is relative to home, and would call the
// whole workspace regular. The bundled home (py = 150 mm) is 0.052.
TEST(RobotFiles, NearlySingularHomeRefused) {
  const double stretched = std::sqrt(200.0 * 200.0 - 100.0 * 100.0);
  auto m = io::read_robot_model(robot_file("five_bar.yaml"), {{"py", stretched - 1e-5}});
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("nearly singular at home"), std::string::npos) << m.status().message();
  EXPECT_TRUE(io::read_robot_model(robot_file("five_bar.yaml"), {{"py", 150.0}}).ok());
}

// A leg with two spherical joints spins about itself: the count check names the idle motion.
TEST(RobotFiles, IdleMotionNamed) {
  std::string text = kGoodPlanar;
  auto m = io::read_robot_model(write_robot("idle.yaml", R"(robot: idle
task: [x, y, z]
tool: [0, 0, 1]
legs:
  - copies: 3
    chain:
      - revolute: {at: [1, 0, 0], axis: [0, 1, 0], actuated: true}
      - spherical: {at: [2, 0, 0]}
      - spherical: {at: [0.2, 0, 1]}
)"));
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("idle motions"), std::string::npos) << m.status().message();
}

}  // namespace
}  // namespace kinestat

namespace kinestat {
namespace {

using namespace mechanisms;

// The generic Orthoglide 3-PUU and 3-PRPaR and the built-in kernel on the same model file's inputs:
// the same status at every point, the 6x6 and the deflection to 1e-9 unloaded and in loaded mode (a
// prescribed displacement; an external wrench): measured 2.0e-13 and 8.4e-15 unloaded, 1.3e-11 and
// 9.2e-12 by a displacement, 6.8e-12 and 1.7e-11 under a wrench (printed): the loaded equilibria's
// conditioning. It was 1e-6 loaded while the files' legs 2 and 3 had their springs' axes by the
// beam convention from their turned direction, not the first leg's axes turned as the built-in
// chains have them: a roll about the beam that a symmetric section does not feel unloaded, but the
// VJM's springs (elementary rotations about their axes) feel at second order, so loaded. The
// 3-PRPaR's legs over-constrain the platform (three of the closure equations are redundant) and its
// parallelograms' spring follows their angle.
class OrthoglideFiles : public testing::TestWithParam<const char*> {};
INSTANTIATE_TEST_SUITE_P(RobotFiles, OrthoglideFiles, testing::Values("orthoglide_puu.yaml", "orthoglide_prpar.yaml"));

TEST_P(OrthoglideFiles, EqualBuiltInKernel) {
  const std::string name = GetParam();
  auto vjm_model = io::read_vjm_model_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/" + name);
  ASSERT_TRUE(vjm_model.ok() && vjm_model->orthoglide);
  const auto shared = std::make_shared<const RobotModel>(load(name));
  for (int mode = 0; mode < 3; ++mode) {
    OrthoglideKernelOptions b;
    b.model = *vjm_model->orthoglide;
    b.architecture = vjm_model->architecture;
    if (mode == 1) b.displacement = (Vec6() << 1e-4, -2e-4, 1e-4, 1e-3, -2e-3, 1e-3).finished();
    if (mode == 2) b.wrench = (Vec6() << 30, -20, -50, 1, 2, -1).finished();
    RobotKernelOptions g;
    g.model = shared;
    g.displacement = b.displacement;
    g.wrench = b.wrench;
    const auto builtin = make_orthoglide_kernel(b), generic = make_robot_kernel(g);
    const double tol = 1e-9;
    int ok = 0;
    double worst = 0.0;
    for (double x = -0.1; x <= 0.1001; x += 0.05)
      for (double y = -0.1; y <= 0.1001; y += 0.05)
        for (double z = -0.1; z <= 0.1001; z += 0.1) {
          const Vec3 p(x, y, z);
          const PostureResult e = builtin->evaluate(p), r = generic->evaluate(p);
          ASSERT_EQ(r.status, e.status) << p.transpose();
          if (e.status != PostureStatus::kOk) continue;
          EXPECT_LT((r.stiffness - e.stiffness).norm(), tol * e.stiffness.norm()) << mode << ": " << p.transpose();
          worst = std::max(worst, (r.stiffness - e.stiffness).norm() / e.stiffness.norm());
          EXPECT_LE((r.deflection - e.deflection).norm(), tol * e.deflection.norm()) << mode << ": " << p.transpose();
          ++ok;
        }
    std::printf("%s, %s: generic - built-in stiffness up to %.1e relative over %d points\n", name.c_str(),
                mode == 0   ? "unloaded"
                : mode == 1 ? "loaded by a displacement"
                            : "loaded under a wrench",
                worst, ok);
    EXPECT_GT(ok, 40);
  }
}

}  // namespace
}  // namespace kinestat

namespace kinestat {
namespace {

using namespace mechanisms;

// Loaded mode of a robot file against central differences of its loaded equilibrium: the Delta's
// chains displaced by t0 (translation only, so that a rotation vector and an angular velocity agree
// to first order about it), K^F(t0) = dF/dt column by column from equilibria at t0 +- h e_j (h = 1e-7
// m, 1e-6 rad). Measured 7e-10 relative (Frobenius norm): the equilibria's residuals (1e-12
// relative) divided by h; bound 1e-8.
TEST(RobotFiles, DeltaLoadedStiffnessIsTheDerivativeOfTheEquilibrium) {
  const RobotModel model = load("delta.yaml");
  RobotData data = make_robot_data(model);
  RobotPosture p = model.home();
  ASSERT_EQ(solve_posture(model, Vec3(0.05, -0.08, -0.85), p, data).status, KinematicsStatus::kOk);
  const std::vector<vjm::Chain> chains = robot_vjm_chains(model, p);
  const Vec6 t0 = (Vec6() << 2e-4, -1e-4, 3e-4, 0, 0, 0).finished();
  auto state = vjm::platform_equilibrium(chains, t0);
  ASSERT_TRUE(state.ok()) << state.status().message();
  auto K = vjm::platform_loaded_stiffness(chains, *state);
  ASSERT_TRUE(K.ok()) << K.status().message();
  Mat6 numeric;
  for (int j = 0; j < 6; ++j) {
    const double h = j < 3 ? 1e-7 : 1e-6;
    auto plus = vjm::platform_equilibrium(chains, t0 + h * Vec6::Unit(j));
    auto minus = vjm::platform_equilibrium(chains, t0 - h * Vec6::Unit(j));
    ASSERT_TRUE(plus.ok() && minus.ok());
    numeric.col(j) = (plus->wrench - minus->wrench) / (2 * h);
  }
  const double rel = (K->stiffness - numeric).norm() / numeric.norm();
  std::printf("Delta loaded stiffness against central differences: %.2e relative\n", rel);
  EXPECT_LT(rel, 1e-8);
}

}  // namespace
}  // namespace kinestat

namespace kinestat {
namespace {

using namespace mechanisms;

// The 3-PRPaR file by MSA (its parallelogram: the bars' spring, robot_parallelogram_spring) against
// the built-in frame (orthoglide_frame: the two bars as beams pinned at both plates, an independent
// route to that spring) over a grid of the workspace: both are exact for beams, linear springs and
// ideal joints, so they agree to round-off (measured 5.7e-13 relative, printed; bound 1e-9). The
// legs over-constrain the platform (six constraint moments for three rotations): the file's
// kinematics solves the independent closure equations, three are redundant.
TEST(RobotFiles, PrparFileMsaEqualsBuiltInFrame) {
  auto vjm_model = io::read_vjm_model_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/orthoglide_prpar.yaml");
  ASSERT_TRUE(vjm_model.ok() && vjm_model->orthoglide);
  auto model = io::read_robot_model(std::string(KINESTAT_SOURCE_DIR) + "/models/robots/orthoglide_prpar.yaml");
  ASSERT_TRUE(model.ok()) << model.status().message();
  EXPECT_EQ(model->redundant_equations().size(), 3u);
  RobotData data = make_robot_data(*model);
  double worst = 0.0;
  int points = 0;
  for (double x = -0.1; x <= 0.1001; x += 0.1)
    for (double y = -0.1; y <= 0.1001; y += 0.1)
      for (double z = -0.1; z <= 0.1001; z += 0.1) {
        const Vec3 p(x, y, z);
        RobotPosture posture = model->home();
        ASSERT_EQ(solve_posture(*model, p, posture, data).status, KinematicsStatus::kOk) << p.transpose();
        auto file = robot_msa_structure(*model, posture);
        ASSERT_TRUE(file.ok()) << file.status().message();
        auto frame = orthoglide_frame(*vjm_model->orthoglide, OrthoglideArchitecture::kPRPaR, p);
        ASSERT_TRUE(frame.ok()) << frame.status().message();
        msa::Workspace ws1, ws2;
        const auto Kf = msa::cartesian_stiffness(*file, ws1, *file->report_node());
        const auto Kb = msa::cartesian_stiffness(*frame, ws2, *frame->report_node());
        ASSERT_TRUE(Kf.ok() && Kb.ok() && Kf->stiffness_defined && Kb->stiffness_defined) << p.transpose();
        const double d = (Kf->stiffness - Kb->stiffness).norm() / Kb->stiffness.norm();
        EXPECT_LT(d, 1e-9) << p.transpose();
        worst = std::max(worst, d);
        ++points;
      }
  std::printf("3-PRPaR file by MSA - built-in frame: up to %.1e relative over %d points\n", worst, points);
}

// A parallelogram's bars checked when read, each fault named with the file (the 3-PRPaR file, changed).
TEST(RobotFiles, ParallelogramBarsChecked) {
  std::ifstream in(std::string(KINESTAT_SOURCE_DIR) + "/models/robots/orthoglide_prpar.yaml");
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const PlantedFault cases[] = {
      {"axis: [0, -1, 0],", "axis: [0.1, -1, 0],", "must be normal to its axis"},
      {"width: w}", "width: 0}", "width"},
      {"width: w}", "width: w, colour: red}", "colour"},
      {"axis: [0, 0, 1]}\n      - parallelogram",
       "axis: [0, 0, 1], bars: {material: steel, section: bar, width: w}}\n"
       "      - parallelogram",
       "'bars' belong to a parallelogram"},
  };
  for (const PlantedFault& c : cases) expect_refused(good, c);
  // At 90 deg the two bars lie on one line: no spring, said so.
  const RobotModel model = load("orthoglide_prpar.yaml");
  const RobotJoint& pa = std::get<RobotJoint>(model.description().legs[0].items[3]);
  ASSERT_EQ(pa.type, RobotJointType::kParallelogram);
  const auto K = robot_parallelogram_spring(pa, M_PI / 2);
  ASSERT_FALSE(K.ok());
  EXPECT_EQ(K.status().code(), StatusCode::kSingular);
  EXPECT_TRUE(robot_parallelogram_spring(pa, 0.3).ok());
}

}  // namespace
}  // namespace kinestat
