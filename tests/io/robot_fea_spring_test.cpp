// The `fea:` springs of robot files (docs/robots.md, issue #19 item 1): a planar 3-RPR whose links
// (then whose platform joints) are the bar of meshes/bar.off, against the same robot with the links
// as `beam:` (within the FEA-vs-beam tolerance of vjm_fea_spring_test) and with the FEA's 6x6
// written in as a `matrix:` (exact: the plumbing), and by the MSA (a coupled joint element); an
// unresolved spring refused by make_robot_model, a missing mesh at read time, both by FILE:LINE.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kinestat/core/units.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "kinestat/mechanisms/robot_msa.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat {
namespace {

using namespace mechanisms;
namespace fs = std::filesystem;

const fs::path kBar = fs::path(KINESTAT_SOURCE_DIR) / "meshes" / "bar.off";  // x 0-200, y +-10, z +-15 mm

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 3-RPR whose links (base joint to platform joint) are 200 mm long, the bar's length; rigid
// actuators, so that the platform's compliance is the links' and the platform joints'. `spring` is
// the link's `beam:` or `spring:` entry, on line 14 (none: a rigid link); `joint_spring` the platform
// joint's `spring:` entry.
std::string robot(const std::string& spring, const std::string& joint_spring = "") {
  return "robot: 3-RPR of bars\n"
         "units: mm-N-s\n"
         "params: {px: 25, py: 43.30127, a: px + sqrt(200^2 - py^2)}\n"
         "planar: true\n"
         "task: [x, y, rz]\n"
         "tool: [0, 0, 0]\n"
         "materials: {steel: {E: 210000, nu: 0.3}}\n"
         "sections: {bar: {type: rectangle, b: 20, h: 30}}\n"
         "legs:\n"
         "  - copies: 3\n"
         "    chain:\n"
         "      - revolute: {at: [a, 0, 0], axis: [0, 0, 1]}\n"
         "      - prismatic: {at: [a, 0, 0], axis: [px - a, py, 0], actuated: true}\n"
         "      - link: {to: [px, py, 0], length: 200" +
         (spring.empty() ? "" : ", " + spring) +
         "}\n"
         "      - revolute: {at: [px, py, 0], axis: [0, 0, 1]" +
         (joint_spring.empty() ? "" : ", " + joint_spring) + "}\n";
}
constexpr int kLinkLine = 14;
const std::string kFea =
    "spring: {fea: {mesh: bar.off, material: steel, clamp: x=0, reference: x=200, size: 6, "
    "cache: cache}}";

StatusOr<RobotModel> build(const std::string& path, std::vector<std::string>* stages = nullptr) {
  StatusOr<RobotDescription> d = io::read_robot_description(path);
  if (!d.ok()) return d.status();
  auto progress = [&](const std::string& s) {
    if (stages) stages->push_back(s);
  };
  if (Status s = resolve_robot_fea_springs(*d, progress); !s.ok()) return s;
  return make_robot_model(std::move(*d));
}

// The platform's 6x6 at home and at two other postures (translated, turned), by the VJM or the MSA.
std::vector<Mat6> stiffness_at_postures(const RobotModel& m, bool msa = false) {
  std::vector<Mat6> out;
  RobotData data = make_robot_data(m);
  for (const Vec3& t : {Vec3(0, 0, 0), Vec3(0.015, -0.01, 0), Vec3(-0.01, 0.005, 8 * units::kDeg)}) {
    RobotPosture p = m.home();
    const KinematicsResult k = solve_posture(m, t, p, data);
    EXPECT_EQ(k.status, KinematicsStatus::kOk) << k.message;
    StatusOr<CartesianStiffness> K = Status::Internal("no structure");
    if (msa) {
      StatusOr<msa::Structure> s = robot_msa_structure(m, p);
      EXPECT_TRUE(s.ok()) << s.status().message();
      msa::Workspace ws;
      if (s.ok()) K = msa::cartesian_stiffness(*s, ws, *s->report_node());
    } else {
      K = vjm::platform_unloaded_stiffness(robot_vjm_chains(m, p));
    }
    EXPECT_TRUE(K.ok()) << K.status().message();
    out.push_back(K.ok() ? K->stiffness : Mat6::Zero());
  }
  return out;
}

const Mat6& link_stiffness(const RobotModel& m, int leg) {
  for (const auto& item : m.description().legs[leg].items)
    if (const auto* l = std::get_if<RobotLink>(&item)) return l->spring->stiffness;
  ADD_FAILURE() << "no link";
  static const Mat6 none = Mat6::Zero();
  return none;
}

// A 6x6 (SI) as a robot file's `spring: {matrix: ...}` in mm-N-s (N/mm, N, N mm/rad).
std::string matrix_spring(const Mat6& K) {
  std::string rows;
  for (int i = 0; i < 6; ++i) {
    rows += i ? ", [" : "[";
    for (int j = 0; j < 6; ++j) {
      const double scale = (i < 3 && j < 3) ? 1e-3 : (i >= 3 && j >= 3) ? 1e3 : 1.0;
      rows += fmt::format("{}{:.17g}", j ? ", " : "", K(i, j) * scale);
    }
    rows += "]";
  }
  return "spring: {matrix: [" + rows + "]}";
}

int count_meshings(const std::vector<std::string>& stages) {
  int meshings = 0;
  for (const std::string& s : stages) meshings += s.find("meshing") != std::string::npos;
  return meshings;
}

TEST(RobotFeaSpring, MatchesTheBeamRobotAndTheMatrixRobot) {
  const fs::path dir = fresh_dir("robot_fea_spring");
  fs::copy_file(kBar, dir / "bar.off");
  std::ofstream(dir / "fea.yaml") << robot(kFea);
  std::vector<std::string> stages;
  StatusOr<RobotModel> fea = build((dir / "fea.yaml").string(), &stages);
  ASSERT_TRUE(fea.ok()) << fea.status().message();
  // The three copies share one entry of the file: one mesh, one solve, the same 6x6.
  EXPECT_EQ(count_meshings(stages), 1) << fmt::format("{}", fmt::join(stages, " | "));
  const Mat6 K_link = link_stiffness(*fea, 0);
  EXPECT_EQ(link_stiffness(*fea, 1), K_link);
  EXPECT_EQ(link_stiffness(*fea, 2), K_link);

  // The same robot with the links as Timoshenko beams of the bar's section and length: the FEA's
  // diagonal is within 3 % of the beam's (vjm_fea_spring_test, docs/fea.md: 1.008 .. 1.023), and so
  // is the platform's stiffness made of three of them.
  std::ofstream(dir / "beam.yaml") << robot("beam: {material: steel, section: bar, theory: timoshenko}");
  StatusOr<RobotModel> beam = io::read_robot_model((dir / "beam.yaml").string());
  ASSERT_TRUE(beam.ok()) << beam.status().message();
  const Mat6 K_beam_link = link_stiffness(*beam, 0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(K_link(i, i) / K_beam_link(i, i), 1.0, 0.03) << "dof " << i;
  const std::vector<Mat6> K_fea = stiffness_at_postures(*fea), K_beam = stiffness_at_postures(*beam);
  for (std::size_t p = 0; p < K_fea.size(); ++p) {
    // Measured: 1.008 (ux, uy, rz) .. 1.018 (uz); 0.8 % in the Frobenius norm.
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(K_fea[p](i, i) / K_beam[p](i, i), 1.0, 0.03) << "posture " << p << " dof " << i;
      EXPECT_GT(K_fea[p](i, i), K_beam[p](i, i)) << "posture " << p << " dof " << i;  // the FEA's stiffening
    }
    EXPECT_LT((K_fea[p] - K_beam[p]).norm() / K_beam[p].norm(), 0.03) << "posture " << p;
  }

  // The FEA's 6x6 written as the links' `matrix:` (N/mm, N, N mm/rad): the same robot to round-off.
  std::ofstream(dir / "matrix.yaml") << robot(matrix_spring(K_link));
  StatusOr<RobotModel> matrix = io::read_robot_model((dir / "matrix.yaml").string());
  ASSERT_TRUE(matrix.ok()) << matrix.status().message();
  const std::vector<Mat6> K_matrix = stiffness_at_postures(*matrix);
  for (std::size_t p = 0; p < K_fea.size(); ++p)
    EXPECT_LT((K_fea[p] - K_matrix[p]).norm() / K_fea[p].norm(), 1e-12) << "posture " << p;

  // A second read comes from the cache (no meshing) and gives the same robot.
  stages.clear();
  StatusOr<RobotModel> again = build((dir / "fea.yaml").string(), &stages);
  ASSERT_TRUE(again.ok()) << again.status().message();
  for (const std::string& s : stages) EXPECT_EQ(s.find("meshing"), std::string::npos) << s;
  EXPECT_EQ(link_stiffness(*again, 0), K_link);

  // The MSA keeps the full 6x6 as a joint element's coupling (msa::Joint::coupling): the same
  // linear model as the VJM's spring, so the two agree to round-off, as on the bundled robots
  // (measured 5.7e-13 relative; held to robot_msa_test's 1e-9).
  const std::vector<Mat6> K_msa = stiffness_at_postures(*fea, true);
  double worst = 0.0;
  for (std::size_t p = 0; p < K_fea.size(); ++p) {
    const double diff = (K_msa[p] - K_fea[p]).norm() / K_fea[p].norm();
    EXPECT_LT(diff, 1e-9) << "posture " << p;
    worst = std::max(worst, diff);
  }
  fmt::print("fea links: worst relative difference MSA - VJM over 3 postures: {:.1e}\n", worst);
}

// Reading records the spring (NaN until resolved): make_robot_model refuses it by FILE:LINE and
// says to resolve it; a missing mesh is refused at read time, by FILE:LINE.
TEST(RobotFeaSpring, UnresolvedAndMissingMeshNamedByFileAndLine) {
  const fs::path dir = fresh_dir("robot_fea_spring_errors");
  const std::string path = (dir / "robot.yaml").string();
  std::ofstream(path) << robot("spring: {fea: {mesh: " + kBar.string() +
                               ", material: steel, clamp: x=0, "
                               "reference: x=200, size: 20}}");
  StatusOr<RobotDescription> d = io::read_robot_description(path);
  ASSERT_TRUE(d.ok()) << d.status().message();
  StatusOr<RobotModel> m = make_robot_model(*d);
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(m.status().message().find(fmt::format("{}:{}: leg 1 link 1 spring fea", path, kLinkLine)),
            std::string::npos)
      << m.status().message();
  EXPECT_NE(m.status().message().find("resolve_robot_fea_springs"), std::string::npos) << m.status().message();
  EXPECT_FALSE(io::read_robot_model(path).ok());  // the same through the io shortcut

  std::ofstream(path, std::ios::trunc) << robot(
      "spring: {fea: {mesh: missing.off, material: steel, clamp: x=0, "
      "reference: x=200}}");
  StatusOr<RobotDescription> missing = io::read_robot_description(path);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find(fmt::format("{}:{}:", path, kLinkLine)), std::string::npos)
      << missing.status().message();
  EXPECT_NE(missing.status().message().find("missing.off: no such mesh file"), std::string::npos)
      << missing.status().message();
}

// A joint's `fea:` spring (a flexure hinge's mesh, say) is the mesh's 6x6 at the joint's point, in
// the joint spring's axes: the 3-RPR with rigid links and the bar as the spring of each platform
// joint equals the same robot with the FEA's 6x6 written as those joints' `matrix:` (the plumbing:
// to round-off), by the VJM and by the MSA (a coupled joint element, held to robot_msa_test's 1e-9).
TEST(RobotFeaSpring, JointSpringIsItsMatrix) {
  const fs::path dir = fresh_dir("robot_fea_joint_spring");
  fs::copy_file(kBar, dir / "bar.off");
  std::ofstream(dir / "fea.yaml") << robot("", kFea);
  std::vector<std::string> stages;
  StatusOr<RobotModel> fea = build((dir / "fea.yaml").string(), &stages);
  ASSERT_TRUE(fea.ok()) << fea.status().message();
  EXPECT_EQ(count_meshings(stages), 1) << fmt::format("{}", fmt::join(stages, " | "));
  std::vector<Mat6> K_joint;
  for (int leg = 0; leg < 3; ++leg)
    for (const auto& item : fea->description().legs[leg].items)
      if (const auto* j = std::get_if<RobotJoint>(&item); j && j->spring) K_joint.push_back(j->spring->stiffness);
  ASSERT_EQ(K_joint.size(), 3u);
  EXPECT_EQ(K_joint[1], K_joint[0]);
  EXPECT_EQ(K_joint[2], K_joint[0]);
  EXPECT_GT(K_joint[0](0, 0), 0.0);

  std::ofstream(dir / "matrix.yaml") << robot("", matrix_spring(K_joint[0]));
  StatusOr<RobotModel> matrix = io::read_robot_model((dir / "matrix.yaml").string());
  ASSERT_TRUE(matrix.ok()) << matrix.status().message();
  const std::vector<Mat6> K_fea = stiffness_at_postures(*fea), K_matrix = stiffness_at_postures(*matrix);
  const std::vector<Mat6> K_msa = stiffness_at_postures(*fea, true);
  double worst = 0.0;
  for (std::size_t p = 0; p < K_fea.size(); ++p) {
    EXPECT_LT((K_fea[p] - K_matrix[p]).norm() / K_fea[p].norm(), 1e-12) << "posture " << p;
    const double diff = (K_msa[p] - K_fea[p]).norm() / K_fea[p].norm();
    EXPECT_LT(diff, 1e-9) << "posture " << p;
    worst = std::max(worst, diff);
  }
  fmt::print("fea joints: worst relative difference MSA - VJM over 3 postures: {:.1e}\n", worst);
}

}  // namespace
}  // namespace kinestat
