// MSA stiffness of robot files (issue #19, item 3; mechanisms/robot_msa.hpp) against the VJM of
// the same files, and the generic five-bar's MSA against the built-in five-bar's MSA kernel.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/robot_msa.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat {
namespace {

using namespace mechanisms;

std::string robot_file(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/models/robots/" + name; }

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::shared_ptr<const RobotModel> load_path(const std::string& path) {
  auto m = io::read_robot_model(path);
  EXPECT_TRUE(m.ok()) << m.status().message();
  if (!m.ok()) return nullptr;
  return std::make_shared<const RobotModel>(std::move(*m));
}

// The bundled hexapod with each leg's strut a steel tube from its slider to its platform joint:
// the MSA model needs an element in every leg but one (robot_msa.hpp), which the bundled file,
// rigid but for its actuators, does not have.
std::string hexapod_with_struts() {
  std::string text = read_text(robot_file("hexapod.yaml"));
  text = std::regex_replace(text, std::regex("\ntask:"),
                            "\nmaterials: {steel: {E: 210000, nu: 0.3}}\nsections: {strut: {type: tube, d: 40, t: 4}}"
                            "\ntask:");
  text = std::regex_replace(text, std::regex("( *)- spherical: \\{at: (\\[[^\\n]*\\])\\}"),
                            "$1- link: {to: $2, beam: {material: steel, section: strut}}\n$1- spherical: {at: $2}");
  const std::string path = ::testing::TempDir() + "/hexapod_struts.yaml";
  std::ofstream(path) << text;
  return path;
}

// The same with the universal joints actuated (their first axis, 1e9 N mm/rad) about axes 69 deg
// apart, the prismatic legs passive: the MSA joint's actuator component is k / sin^2 of that angle.
std::string hexapod_with_actuated_universal_joints() {
  std::string text = read_text(hexapod_with_struts());
  text = std::regex_replace(text, std::regex("axes: \\[\\[1, 0, 0\\], \\[0, 1, 0\\]\\]\\}"),
                            "axes: [[1, 0, 0], [0.4, 1, 0.2]], actuated: true, stiffness: 1e9}");
  text = std::regex_replace(text, std::regex(" *actuated: true\n *stiffness: leg_stiffness\n"), "");
  const std::string path = ::testing::TempDir() + "/hexapod_u.yaml";
  std::ofstream(path) << text;
  return path;
}

struct Case {
  std::string name;
  std::string path;
  Vec3 orientation_deg = Vec3::Zero();  // set where the task has the angle
};

// Relative difference of two 6x6 (Frobenius), 0 when both are 0.
double relative(const Mat6& a, const Mat6& b) {
  const double n = std::max(a.norm(), b.norm());
  return n == 0.0 ? 0.0 : (a - b).norm() / n;
}

// The part of a stiffness on the complement of the rigid directions (the null space of the
// compliance): P K P. The VJM's finite part sums the legs' finite parts, which may have components
// along the platform's rigid directions; the MSA kernel's is the pseudo-inverse of the compliance,
// which is P K P.
Mat6 on_complement(const Mat6& K, const Mat6& C) {
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(C);
  const double cmax = eig.eigenvalues().cwiseAbs().maxCoeff();
  Mat6 P = Mat6::Zero();
  for (int i = 0; i < 6; ++i)
    if (eig.eigenvalues()(i) > 1e-13 * cmax) P += eig.eigenvectors().col(i) * eig.eigenvectors().col(i).transpose();
  return P * K * P;
}

// The five-bar's 2e11 N/m (N m/rad) joint springs in series with ~1e4 N/m of link bending cost an
// MSA on nodal unknowns ~7 digits (tests/mechanisms/posture_kernels_test.cpp): the built-in
// five-bar's MSA reference (CHOLMOD on its 36 nodal unknowns) is off its VJM reference by up to
// ~1e-5 in compliance. The generic MSA has the same matrix in other unknowns and round-off of the
// same size, not at the same points: it is held to twice the reference's largest error over the
// grid of the five-bar tests (points with singularity measure above 0.01), plus 1e-9:
// {stiffness, compliance}.
std::pair<double, double> five_bar_msa_bound() {
  static const std::pair<double, double> bound = [] {
    FiveBarKernelOptions f;
    f.mode = WorkingMode{1, -1};  // the file's home drawing
    f.method = StiffnessMethod::kMsa;
    const auto msa = make_reference_five_bar_kernel(f);
    f.method = StiffnessMethod::kVjm;
    const auto vjm = make_reference_five_bar_kernel(f);
    double k = 0.0, c = 0.0;
    for (double x = -0.2; x <= 0.2001; x += 0.02)
      for (double y = 0.0; y <= 0.2001; y += 0.02) {
        const PostureResult m = msa->evaluate(Vec3(x, y, 0)), v = vjm->evaluate(Vec3(x, y, 0));
        if (m.status != PostureStatus::kOk || v.status != PostureStatus::kOk || v.singularity_measure <= 0.01) continue;
        k = std::max(k, relative(m.stiffness, v.stiffness));
        c = std::max(c, relative(m.compliance, v.compliance));
      }
    return std::pair{2 * k + 1e-9, 2 * c + 1e-9};
  }();
  return bound;
}

// The same model by both methods at points of each robot's workspace (its box at 1/4, 1/2 and 3/4
// of each range) and, where the task has angles, a tilted platform: the same status and the same
// stiffness and compliance. The two methods share the posture and the model's data only: VJM
// multiplies the chains' Jacobians and springs (cantilever springs for beams), MSA assembles beams,
// joints and ties and factors the reduced matrix (CHOLMOD). A beam in series is exactly its
// cantilever spring, and a joint's free and actuated components in their frame exactly the VJM's
// passive and actuated coordinates, so they differ by round-off: measured up to ~1.5e-12 relative
// in stiffness; bound 1e-9, and for the compliance 1e-9 + 1e-12 x the condition number (the
// inverse amplifies the stiffness's difference by it: 1e-9 measured on the hexapod with actuated
// universal joints, condition number ~6e3). Except the five-bar, whose stiff joints cost MSA digits:
// five_bar_msa_bound (measured 3e-8 in stiffness, 3e-7 in compliance at these points).
TEST(RobotMsa, EqualsVjmOnBundledRobots) {
  const std::vector<Case> cases = {
      {"delta", robot_file("delta.yaml"), Vec3::Zero()},
      {"five-bar", robot_file("five_bar.yaml"), Vec3::Zero()},
      {"3-RPR", robot_file("planar_3rpr.yaml"), Vec3(0, 0, 10)},
      {"3-PRS", robot_file("prs_head.yaml"), Vec3(4, -3, 0)},
      {"hexapod", robot_file("hexapod.yaml"), Vec3(3, -2, 5)},
      {"Orthoglide 3-PUU", robot_file("orthoglide_puu.yaml"), Vec3::Zero()},
      {"Orthoglide 3-PRPaR", robot_file("orthoglide_prpar.yaml"), Vec3::Zero()},
      {"hexapod with struts", hexapod_with_struts(), Vec3(3, -2, 5)},
      {"hexapod with struts, actuated universal joints", hexapod_with_actuated_universal_joints(), Vec3(3, -2, 5)},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto model = load_path(c.path);
    ASSERT_TRUE(model);
    const RobotDescription& d = model->description();
    RobotKernelOptions o;
    o.model = model;
    o.task = model->home_task();
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {  // tilted, where the task has angles
        bool any = false;
        for (std::size_t t = 0; t < d.task.size(); ++t)
          if (d.task[t] >= TaskCoordinate::kRx) {
            o.task(static_cast<int>(t)) = c.orientation_deg(static_cast<int>(d.task[t]) - 3) * M_PI / 180.0;
            any = true;
          }
        if (!any) continue;
      }
      // A workspace of angles (the 3-PRS's tilts): the box's axes set the task's rx, ry, rz.
      if (d.workspace_angular) {
        std::array<int, 3> axes{-1, -1, -1};
        for (std::size_t t = 0; t < d.task.size(); ++t)
          if (d.task[t] >= TaskCoordinate::kRx) axes[static_cast<int>(d.task[t]) - 3] = static_cast<int>(t);
        o.map_axes = axes;
        if (pass == 1) continue;  // the box already tilts it
      }
      RobotKernelOptions ov = o, om = o;
      ov.method = StiffnessMethod::kVjm;
      om.method = StiffnessMethod::kMsa;
      ASSERT_TRUE(validate(om).ok()) << validate(om).message();
      auto vjm = make_robot_kernel(ov), msa = make_robot_kernel(om);
      const auto& box = *d.workspace;
      const bool stiff_joints = c.name == "five-bar";
      double worst_k = 0.0, worst_c = 0.0, worst_kappa = 0.0;
      int ok = 0;
      for (double fx : {0.25, 0.5, 0.75})
        for (double fy : {0.25, 0.5, 0.75})
          for (double fz : {0.25, 0.5, 0.75}) {
            const Vec3 f(fx, fy, fz);
            Vec3 point;
            for (int a = 0; a < 3; ++a) point(a) = box[a].first + f(a) * (box[a].second - box[a].first);
            const PostureResult v = vjm->evaluate(point), m = msa->evaluate(point);
            const std::string where =
                fmt::format("{} at ({:.6g}, {:.6g}, {:.6g}) m", msa->description(), point.x(), point.y(), point.z());
            ASSERT_EQ(m.status, v.status) << where;
            if (v.status != PostureStatus::kOk) continue;
            ++ok;
            const double dk = relative(m.stiffness, v.stiffness), dc = relative(m.compliance, v.compliance);
            // The compliance inherits the stiffness's difference times its condition number.
            const double kappa = v.indices.condition_number;
            const auto [bk, bc] = stiff_joints ? five_bar_msa_bound() : std::pair{1e-9, 1e-9 + 1e-12 * kappa};
            worst_kappa = std::max(worst_kappa, kappa);
            EXPECT_LT(dk, bk) << where << "\nMSA\n" << m.stiffness << "\nVJM\n" << v.stiffness;
            EXPECT_LT(dc, bc) << where << "\nMSA\n" << m.compliance << "\nVJM\n" << v.compliance;
            worst_k = std::max(worst_k, dk);
            worst_c = std::max(worst_c, dc);
          }
      fmt::print(
          "{}{}: {} points, worst relative difference MSA - VJM: stiffness {:.1e}, compliance {:.1e} "
          "(condition number up to {:.1e})\n",
          c.name, pass ? " (tilted)" : "", ok, worst_k, worst_c, worst_kappa);
      EXPECT_GT(ok, 0);
    }
  }
}

// The generic five-bar's MSA (robot_msa_structure of models/robots/five_bar.yaml) against the
// built-in MSA kernel (make_five_bar_kernel, MSA, working mode +-, assembly up: the file's home
// drawing) over a grid. The models are the same: the built-in structure's joints are diagonal
// springs in global axes with rz released (2e11 N/m, N m/rad), beams between the joint nodes, the
// actuated nodes A1, A2 fixed; the file's joints are the same 6x6 springs (placed before the joint,
// a series that equals one joint with rz released) and locked actuators (the beams start on the
// base). The built-in kernel solves a well-conditioned change of variables (~1e-9, its own tests);
// the generic one goes through CHOLMOD on nodal unknowns, which loses digits to the stiff joints as
// the built-in's MSA reference does: held to that reference's own error (five_bar_msa_bound).
TEST(RobotMsa, FiveBarEqualsBuiltInMsaKernel) {
  RobotKernelOptions o;
  o.model = load_path(robot_file("five_bar.yaml"));
  ASSERT_TRUE(o.model);
  o.method = StiffnessMethod::kMsa;
  const auto generic = make_robot_kernel(o);
  FiveBarKernelOptions f;
  f.mode = WorkingMode{1, -1};
  f.method = StiffnessMethod::kMsa;
  const auto builtin = make_five_bar_kernel(f);
  int ok = 0;
  double worst_k = 0.0, worst_c = 0.0;
  for (double x = -0.2; x <= 0.2001; x += 0.02)
    for (double y = 0.0; y <= 0.2001; y += 0.02) {
      const Vec3 point(x, y, 0);
      const PostureResult g = generic->evaluate(point), e = builtin->evaluate(point);
      if (e.status == PostureStatus::kOk && e.singularity_measure > 0.01) {
        ASSERT_EQ(g.status, PostureStatus::kOk) << point.transpose();
        const double dk = relative(g.stiffness, e.stiffness), dc = relative(g.compliance, e.compliance);
        EXPECT_LT(dk, five_bar_msa_bound().first) << point.transpose();
        EXPECT_LT(dc, five_bar_msa_bound().second) << point.transpose();
        worst_k = std::max(worst_k, dk);
        worst_c = std::max(worst_c, dc);
        ++ok;
      } else if (e.status == PostureStatus::kUnreachable) {
        EXPECT_NE(g.status, PostureStatus::kOk) << point.transpose();
      }
    }
  fmt::print(
      "five-bar, generic MSA - built-in MSA kernel: {} points, stiffness {:.1e}, compliance {:.1e} (the MSA "
      "reference's own error, doubled: up to {:.1e}, {:.1e})\n",
      ok, worst_k, worst_c, five_bar_msa_bound().first, five_bar_msa_bound().second);
  EXPECT_GT(ok, 15);
}

// A parallelogram and an actuated prismatic joint, which no bundled robot has: a planar robot whose
// slider leg (P actuated, then a parallelogram to the platform) holds the orientation and whose
// arm leg (R actuated, beams, R, R) closes the loop. The slider leg is rigid out of the plane and
// about z (exact ties in MSA, infinite stiffness in the VJM): both methods must find the same
// compliance (zero along those four directions) and the same finite part on their complement, to
// round-off (bound 1e-9).
TEST(RobotMsa, ParallelogramAndSliderEqualVjm) {
  const std::string path = ::testing::TempDir() + "/p_pa_rrr.yaml";
  std::ofstream(path) << R"(robot: P-Pa and RRR planar test
units: mm-N-s
planar: true
task: [x, y]
tool: [300, 300, 0]
workspace: {x: [260, 340], y: [260, 340], z: [0, 0]}
materials: {steel: {E: 210000, nu: 0.3}}
sections: {rod: {type: circle, d: 20}}
legs:
  - name: slider leg
    chain:
      - prismatic: {at: [0, 0, 0], axis: [1, 0, 0], actuated: true, stiffness: 1e4}
      - parallelogram: {at: [0, 0, 0], axis: [0, 0, 1], to: [300, 300, 0]}
  - name: arm leg
    chain:
      - revolute: {at: [800, 0, 0], axis: [0, 0, 1], actuated: true, stiffness: 1e8}
      - link: {to: [800, 300, 0], beam: {material: steel, section: rod}}
      - revolute: {at: [800, 300, 0], axis: [0, 0, 1]}
      - link: {to: [300, 300, 0], beam: {material: steel, section: rod, roll: 30}}
      - revolute: {at: [300, 300, 0], axis: [0, 0, 1]}
)";
  RobotKernelOptions o;
  o.model = load_path(path);
  ASSERT_TRUE(o.model);
  ASSERT_TRUE(validate(o).ok());
  RobotKernelOptions om = o;
  om.method = StiffnessMethod::kMsa;
  ASSERT_TRUE(validate(om).ok()) << validate(om).message();
  auto vjm = make_robot_kernel(o), msa = make_robot_kernel(om);
  int ok = 0;
  for (double x : {0.27, 0.3, 0.33})
    for (double y : {0.27, 0.3, 0.33}) {
      const Vec3 point(x, y, 0);
      const PostureResult v = vjm->evaluate(point), m = msa->evaluate(point);
      ASSERT_EQ(v.status, PostureStatus::kOk) << point.transpose();
      ASSERT_EQ(m.status, PostureStatus::kOk) << point.transpose();
      const Mat6 finite = on_complement(v.stiffness, v.compliance);
      EXPECT_LT(relative(m.stiffness, finite), 1e-9) << point.transpose() << "\nMSA\n"
                                                     << m.stiffness << "\nVJM\n"
                                                     << finite;
      EXPECT_LT(relative(m.compliance, v.compliance), 1e-9) << point.transpose();
      ++ok;
    }
  EXPECT_EQ(ok, 9);
}

// The hexapod's MSA structure (legs rigid but for their joints: the spherical joints close loops of
// ties) solved under a load at the tool: msa::solve's equilibrium check passes, the reactions balance
// the load, and every leg is a two-force member: its spherical joint's constraint force (a loop's
// force, or the tree tie's for the leg whose joint is not one) equals its actuator's spring force in
// magnitude (measured MEASURED relative; bound 1e-9).
TEST(RobotMsa, HexapodLoopsCarryTheLegForces) {
  const auto hexapod = load_path(robot_file("hexapod.yaml"));
  ASSERT_TRUE(hexapod);
  RobotData data = make_robot_data(*hexapod);
  RobotPosture p = hexapod->home();
  ASSERT_EQ(solve_posture(*hexapod, (Vec6() << 0.05, -0.03, 0.8, 0.05, -0.1, 0.2).finished(), p, data).status,
            KinematicsStatus::kOk);
  auto s = robot_msa_structure(*hexapod, p);
  ASSERT_TRUE(s.ok()) << s.status().message();
  const Vec6 load = (Vec6() << 300, -200, -1000, 20, 40, -30).finished();
  s->add_load_case({.name = "tool", .loads = {{*s->report_node(), load}}});
  const msa::Solution sol = msa::solve(*s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const msa::LoadCaseResult& r = sol.cases[0];
  Vec3 force = load.head<3>();
  for (const Vec6& reaction : r.reaction) force += reaction.head<3>();
  EXPECT_LT(force.norm(), 1e-9 * load.head<3>().norm());
  double worst = 0.0;
  for (const RobotLeg& leg : hexapod->description().legs) {
    double spherical = -1.0, actuator = -1.0;
    for (std::size_t j = 0; j < s->joints().size(); ++j) {
      const msa::Joint& jt = s->joints()[j];
      if (jt.source.find(leg.name + " joint") == std::string::npos) continue;
      if (jt.source.find("spherical") != std::string::npos) spherical = r.joint_forces[j].head<3>().norm();
      if (jt.source.find("prismatic") != std::string::npos)
        for (int i = 0; i < 6; ++i)
          if (std::isfinite(jt.stiffness(i))) actuator = std::abs(r.joint_forces[j](i));
    }
    ASSERT_GT(spherical, 0.0) << leg.name;
    ASSERT_GT(actuator, 0.0) << leg.name;
    worst = std::max(worst, std::abs(spherical - actuator) / actuator);
  }
  EXPECT_LT(worst, 1e-9);
  std::printf("hexapod by MSA: spherical joints' forces - actuators' %.1e relative\n", worst);
}

// What the MSA model cannot express is refused with a message, before any map: MSA with a load. (The
// bundled hexapod, every leg rigid but for its joints' motions, closes loops of exact ties, which
// msa eliminates: RobotFiles.HexapodMatchesGosselin.)
TEST(RobotMsa, RefusalsNamed) {
  RobotKernelOptions o;
  o.method = StiffnessMethod::kMsa;
  o.model = load_path(robot_file("hexapod.yaml"));
  ASSERT_TRUE(validate(o).ok()) << validate(o).message();
  o.model = load_path(robot_file("delta.yaml"));
  ASSERT_TRUE(validate(o).ok()) << validate(o).message();
  o.wrench = Vec6::Zero();
  const Status st = validate(o);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("VJM only"), std::string::npos) << st.message();
}

// The structure itself: the Delta at home has its platform node at the tool point, three fixed
// base nodes, a beam per arm (the forearms are the parallelograms' 6x6 springs: joint elements), and
// solves to the VJM's 6x6 through msa::solve's report.
TEST(RobotMsa, DeltaStructureAtHome) {
  const auto delta = load_path(robot_file("delta.yaml"));
  ASSERT_TRUE(delta);
  auto s = robot_msa_structure(*delta, delta->home());
  ASSERT_TRUE(s.ok()) << s.status().message();
  ASSERT_TRUE(s->report_node());
  EXPECT_LT((s->nodes()[*s->report_node()].position - delta->description().tool).norm(), 1e-15);
  EXPECT_EQ(s->beams().size(), 3u);
  EXPECT_EQ(s->supports().size(), 3u);
  msa::Workspace ws;
  auto K = msa::cartesian_stiffness(*s, ws, *s->report_node());
  ASSERT_TRUE(K.ok()) << K.status().message();
  auto V = vjm::platform_unloaded_stiffness(robot_vjm_chains(*delta, delta->home()));
  ASSERT_TRUE(V.ok());
  EXPECT_LT(relative(K->stiffness, V->stiffness), 1e-9);
}

}  // namespace
}  // namespace kinestat
