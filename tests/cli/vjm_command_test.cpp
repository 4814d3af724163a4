// kinestat vjm: printed stiffness against closed forms at the Orthoglide's Q0, loaded mode, exit codes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cli_run.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/vjm/equilibrium.hpp"

namespace kinestat::cli {
namespace {

const std::string kSource = KINESTAT_SOURCE_DIR;
const std::string kPuu = kSource + "/models/orthoglide_puu.yaml";
const std::string kPrpar = kSource + "/models/orthoglide_prpar.yaml";

// The 6x6 printed after the line that contains `title`, in the report section headed `section`.
Mat6 printed_matrix(const std::string& out, const std::string& section, const std::string& title) {
  Mat6 M = Mat6::Constant(std::nan(""));
  const std::size_t from = out.find(section);
  const std::size_t at = from == std::string::npos ? from : out.find(title, from);
  if (at == std::string::npos) return M;
  std::istringstream s(out.substr(out.find('\n', at) + 1));
  std::string line, label;
  std::getline(s, line);  // the column names
  for (int i = 0; i < 6; ++i) {
    s >> label;  // the row's dof name
    for (int j = 0; j < 6; ++j) s >> M(i, j);
  }
  return M;
}

// At Q0 a tool translation along x stretches only leg x (legs y and z turn in their U joints), in
// series: actuator, foot (axial, L/EA) and leg (two tube bars, axial). Inputs of models/orthoglide_*.yaml
// (identified so that this is Tables 1-2's 2.78e-4 mm/N; checked below too).
double q0_translational_compliance() {
  const double k_actuator = 4170.3e3;                                   // N/m
  const double foot = 0.63275 / (210e9 * (0.06 * 0.06 - 0.05 * 0.05));  // m/N
  const double d = 0.014873, t = 0.0014873;                             // bar tube (m)
  const double leg = 0.3106 / (70e9 * 2 * std::numbers::pi / 4 * (d * d - (d - 2 * t) * (d - 2 * t)));
  const double c = 1 / k_actuator + foot + leg;
  EXPECT_NEAR(c, 2.78e-7, 1e-4 * 2.78e-7);
  return c;
}

void expect_isotropic_translation(const Mat6& C, double c) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(C(i, i), c, 1e-4 * c) << i;  // printed with 5 significant digits
    for (int j = 0; j < 3; ++j)
      if (j != i) {
        EXPECT_LT(std::abs(C(i, j)), 1e-6 * c) << i << "," << j;
      }
  }
}

TEST(VjmCommand, PuuAtQ0IsIsotropicWithTheSeriesCompliance) {
  const CliRun r = run_cli({"vjm", kPuu});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const Mat6 C = printed_matrix(r.out, "(unloaded", "compliance C = K^-1 [");
  expect_isotropic_translation(C, q0_translational_compliance());
  // Stiffness printed is the inverse of the compliance printed, and symmetric.
  const Mat6 K = printed_matrix(r.out, "(unloaded", "stiffness K [");
  EXPECT_LT((K * C - Mat6::Identity()).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-4 * K.cwiseAbs().maxCoeff());
  EXPECT_NE(r.out.find("condition number"), std::string::npos);
  EXPECT_EQ(r.out.find("LOST"), std::string::npos);
}

TEST(VjmCommand, PrparAtQ0HasTheSameTranslationalCompliance) {
  const CliRun r = run_cli({"vjm", kPrpar, "--point", "0,0,0"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  expect_isotropic_translation(printed_matrix(r.out, "(unloaded", "compliance C = K^-1 ["),
                               q0_translational_compliance());
}

TEST(VjmCommand, WrenchGivesTheComplianceTimesTheForce) {
  // 100 N along x at Q0: dx = c F (the 7 um stretch changes the geometry by ~1e-5 relative).
  const CliRun r = run_cli({"vjm", kPuu, "--wrench", "100,0,0,0,0,0"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("loaded equilibrium"), std::string::npos);
  const std::size_t at = r.out.find("displacement (");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double dx_mm = std::stod(r.out.substr(at + 14));
  EXPECT_NEAR(dx_mm, 100 * q0_translational_compliance() * 1e3, 1e-4 * dx_mm);
  EXPECT_NE(printed_matrix(r.out, "(loaded", "stiffness K [").maxCoeff(), 0.0);
}

TEST(VjmCommand, PrescribedDisplacementReportsTheWrench) {
  // 0.007 mm along x at Q0 needs F = dx / c along x.
  const CliRun r = run_cli({"vjm", kPuu, "--load", "0.007,0,0,0,0,0"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const std::size_t at = r.out.find("wrench F = (");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double Fx = std::stod(r.out.substr(at + 12));
  EXPECT_NEAR(Fx, 7e-6 / q0_translational_compliance(), 1e-4 * Fx);
}

TEST(VjmCommand, WrenchOnVeryStiffSpringsConverges) {
  // Three orthogonal legs, each a 1e9 N/mm (and N mm/rad) spring at the tool point: K = 3e9 N/mm
  // isotropic. The wrench residual's round-off floor (~eps K l) is far above 1e-10 of the load; the
  // solve must still converge and give F / K.
  const std::string path = std::string(KINESTAT_BINARY_DIR) + "/vjm_stiff_legs.yaml";
  {
    std::ofstream f(path);
    f << "units: mm-N-s\nchains:\n";
    // Base point, then a rotation (axis, deg) that turns the local x towards the tool point.
    struct Leg {
      const char* base;
      const char* axis;
      int angle;
    };
    const Leg legs[3] = {
        {"[250, 0, 0]", "[0, 0, 1]", 180}, {"[0, 250, 0]", "[0, 0, 1]", -90}, {"[0, 0, 250]", "[0, 1, 0]", 90}};
    for (int i = 0; i < 3; ++i) {
      f << "  - name: leg " << i << "\n    elements:\n";
      f << "      - {translate: " << legs[i].base << "}\n";
      f << "      - {rotate: {axis: " << legs[i].axis << ", angle: " << legs[i].angle << "}}\n";
      f << "      - {translate: [250, 0, 0]}\n";
      f << "      - {spring: {matrix: [";
      for (int r = 0; r < 6; ++r) {
        f << (r ? ", " : "") << "[";
        for (int c = 0; c < 6; ++c) f << (c ? ", " : "") << (r == c ? "1.0e9" : "0");
        f << "]";
      }
      f << "]}}\n";
      f << "      - {rotate: {axis: " << legs[i].axis << ", angle: " << -legs[i].angle << "}}\n";
    }
  }
  const CliRun r = run_cli({"vjm", path, "--wrench", "1000,-500,800,0,0,0"});
  ASSERT_EQ(r.code, kExitOk) << r.err << r.out;
  const std::size_t at = r.out.find("displacement (");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double dx_mm = std::stod(r.out.substr(at + 14));
  EXPECT_NEAR(dx_mm, 1000 / 3e9, 1e-4 * 1000 / 3e9) << r.out;
}

// A wrench whose equilibrium is not found (200 kN down on the 3-PUU at Q0) is exit 2 with the share of
// it that is found, checked by the library's own solves: an equilibrium at that share of the load,
// none at the next share printed, 1/128 apart.
TEST(VjmCommand, AnUnreachedLoadNamesTheShareThatIsReached) {
  const CliRun r = run_cli({"vjm", kPuu, "--wrench", "0,0,-2e5,0,0,0", "--quiet"});
  ASSERT_EQ(r.code, kExitBadInput) << r.err;
  const std::string key = "The equilibrium is found under ";
  const std::size_t at = r.err.find(key);
  ASSERT_NE(at, std::string::npos) << r.err;
  double found = 0, failed = 0;
  ASSERT_EQ(std::sscanf(r.err.c_str() + at + key.size(), "%lf %% of this load and not under %lf %%", &found, &failed),
            2)
      << r.err;
  EXPECT_GT(found, 0.0);
  EXPECT_NEAR(failed - found, 100.0 / 128, 0.051) << r.err;  // the printed shares are rounded to 0.1 %
  EXPECT_NE(r.err.find("give a smaller --wrench"), std::string::npos) << r.err;
  StatusOr<io::VjmModel> model = io::read_vjm_model_yaml(kPuu);
  ASSERT_TRUE(model.ok()) << model.status().message();
  StatusOr<std::vector<vjm::Chain>> chains = io::vjm_model_chains(*model, std::nullopt);
  ASSERT_TRUE(chains.ok()) << chains.status().message();
  const Vec6 wrench = (Vec6() << 0, 0, -2e5, 0, 0, 0).finished();
  const vjm::LoadShare share = vjm::load_share_reached(*chains, nullptr, &wrench);
  EXPECT_NEAR(100 * share.found, found, 0.051);
  EXPECT_TRUE(vjm::platform_equilibrium_under_wrench(*chains, share.found * wrench).ok());
  EXPECT_EQ(vjm::platform_equilibrium_under_wrench(*chains, share.failed * wrench).status().code(),
            StatusCode::kNotConverged);
}

TEST(VjmCommand, BadInputExitsWith2) {
  CliRun r = run_cli({"vjm", kPuu, "--point", "400,0,0"});  // beyond the leg length: unreachable
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_FALSE(r.err.empty());
  r = run_cli({"vjm", kPuu, "--point", "1,2"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--point takes 3 numbers"), std::string::npos) << r.err;
  r = run_cli({"vjm", kSource + "/tests/io/data/vjm_puu_q0.yaml", "--point", "0,0,0"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("mechanism: orthoglide"), std::string::npos) << r.err;
  r = run_cli({"vjm", kPuu, "--load", "0,0,0,0,0,0", "--wrench", "1,0,0,0,0,0"});
  EXPECT_EQ(r.code, kExitBadInput);
  r = run_cli({"vjm", kSource + "/models/five_bar.yaml"});  // an MSA structure file, not a VJM model
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("five_bar.yaml:"), std::string::npos) << r.err;
  r = run_cli({"vjm", "/nonexistent.yaml"});
  EXPECT_EQ(r.code, kExitBadInput);
}

}  // namespace
}  // namespace kinestat::cli

namespace kinestat::cli {
namespace {

// A robot file at one posture: the joint values solved from home, the same 6x6 as the robot kernel
// (the map's) at that point, and a point out of reach refused with exit 2.
TEST(VjmCommand, RobotFileAtAPoint) {
  const std::string file = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/hexapod.yaml";
  const CliRun r = run_cli({"vjm", file, "--point", "20,-10,790", "--orientation", "3,-2,5", "--json", "-"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  auto model = io::read_robot_model(file);
  ASSERT_TRUE(model.ok());
  mechanisms::RobotKernelOptions o;
  o.model = std::make_shared<const mechanisms::RobotModel>(std::move(*model));
  const double deg = M_PI / 180.0;
  o.task = (VecX(6) << 0.02, -0.01, 0.79, 3 * deg, -2 * deg, 5 * deg).finished();
  const mechanisms::PostureResult p = mechanisms::make_robot_kernel(o)->evaluate(Vec3(0.02, -0.01, 0.79));
  ASSERT_EQ(p.status, mechanisms::PostureStatus::kOk);
  const auto& K = j["unloaded"]["stiffness"];
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(K[i][k].get<double>(), p.stiffness(i, k), 1e-9 * p.stiffness.norm());
  const CliRun text = run_cli({"vjm", file, "--point", "20,-10,790"});
  EXPECT_NE(text.out.find("(actuated)"), std::string::npos) << text.out;
  const CliRun far = run_cli({"vjm", file, "--point", "2000,0,790"});
  EXPECT_EQ(far.code, 2);
  EXPECT_NE(far.err.find("not reached from home"), std::string::npos) << far.err;
}

// An Orthoglide model's point out of reach names --point, the chain and the fix.
TEST(VjmCommand, OrthoglidePointOutOfReachNamesTheOption) {
  const CliRun r =
      run_cli({"vjm", std::string(KINESTAT_SOURCE_DIR) + "/models/orthoglide_puu.yaml", "--point", "500,500,500"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--point 500,500,500 mm: Orthoglide point p = (0.5, 0.5, 0.5) m is out of reach of chain x: "
                       "p_y^2 + p_z^2 exceeds L^2 = (0.3106 m)^2; choose a point inside the workspace"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace kinestat::cli

namespace kinestat::cli {
namespace {

// A robot file whose links are `fea:` springs (docs/robots.md): `vjm` and `map` mesh and solve them
// between reading and building, with the stages on stderr (none with --quiet); `map --method msa`
// maps them too (coupled joint elements); a missing mesh exits 2 naming the file's line.
TEST(VjmCommand, RobotFileWithFeaLinks) {
  const std::string dir = std::string(KINESTAT_BINARY_DIR) + "/vjm_robot_fea";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(kSource + "/meshes/bar.off", dir + "/bar.off",
                             std::filesystem::copy_options::overwrite_existing);
  auto write = [&](const std::string& name, const std::string& mesh) {
    std::ofstream(dir + "/" + name)
        << "robot: 3-RPR of bars\nunits: mm-N-s\nparams: {px: 25, py: 43.30127, a: px + sqrt(200^2 - py^2)}\n"
           "planar: true\ntask: [x, y, rz]\ntool: [0, 0, 0]\nlegs:\n  - copies: 3\n    chain:\n"
           "      - revolute: {at: [a, 0, 0], axis: [0, 0, 1]}\n"
           "      - prismatic: {at: [a, 0, 0], axis: [px - a, py, 0], actuated: true}\n"
           "      - link: {to: [px, py, 0], spring: {fea: {mesh: "
        << mesh
        << ", material: steel, clamp: x=0, reference: x=200, size: 20}}}\n"
           "      - revolute: {at: [px, py, 0], axis: [0, 0, 1]}\n";
    return dir + "/" + name;
  };
  const std::string file = write("robot.yaml", "bar.off");
  CliRun r = run_cli({"vjm", file});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("vjm: meshing "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("Cartesian stiffness"), std::string::npos) << r.out;
  r = run_cli({"vjm", file, "--quiet"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_EQ(r.err.find("meshing"), std::string::npos) << r.err;
  r = run_cli({"map", file, "--box", "-10:10,-10:10,0:0", "--step", "10", "--quiet"});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  r = run_cli({"map", file, "--box", "-10:10,-10:10,0:0", "--step", "10", "--method", "msa", "--quiet"});
  EXPECT_EQ(r.code, kExitOk) << r.err;  // the full 6x6 as a coupled joint element
  r = run_cli({"vjm", write("missing.yaml", "missing.off")});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("missing.yaml:12: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such mesh file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kinestat::cli
