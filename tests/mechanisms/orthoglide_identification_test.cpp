// The declared calibration of the Orthoglide models against Pashkevich et al. 2009, Tables 1-3
// (docs/vjm.md, "Identified inputs"). The paper publishes compliance, not the inputs behind it (FEA
// link stiffness, actuator stiffness, platform geometry). Five inputs are identified from five
// declared entries of Tables 1-2; every other entry is a prediction and is compared here:
//
//   calibration entries (unloaded, diagonal terms)      identified input (mainly)
//   Q0 k_tran 2.78 (both tables, equal)                 actuator stiffness
//   Table 1 Q0 k_rot 20.9                               bar section scale (legs' bending/torsion)
//   Table 2 Q0 k_rot 1.94                               parallelogram bar spacing w
//   Table 1 Q2 k_tran 71.3                              platform offset d (lever arm of the legs)
//   Table 2 Q2 k_tran 21.2                              foot length (the foot's bending compliance)
//
// Units of the tables: k_tran 1e-4 mm/N, k_rot 1e-7 rad/(N mm); each 3x3 block is a on the diagonal
// and b off it (q_axis_form in orthoglide_stiffness_test.cpp checks that form).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <iostream>

#include "kinestat/mechanisms/orthoglide_identification.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr double kQ0 = 0.0, kQ1 = -73.65, kQ2 = 126.35;                             // tables' x = y = z (mm)
constexpr double kTran = 1e-7;                                                      // 1e-4 mm/N in m/N
constexpr double kRot = 1e-4;                                                       // 1e-7 rad/(N mm) in rad/(N m)
const Vec6 kPaperLoad = (Vec6() << -0.5e-3, -0.5e-3, -0.5e-3, 0, 0, 0).finished();  // tables' (0.5, 0.5, 0.5) mm

using A = OrthoglideArchitecture;

const std::vector<OrthoglideInput> kInputs = paper_calibration_inputs();

const OrthoglideIdentification& identified() {
  static const OrthoglideIdentification id = [] {
    StatusOr<OrthoglideIdentification> r =
        identify_orthoglide_inputs(paper_calibration_start(), kInputs, paper_calibration_targets());
    EXPECT_TRUE(r.ok()) << r.status().message();
    return r.ok() ? *r : OrthoglideIdentification{};
  }();
  return id;
}

TEST(OrthoglideIdentification, FiveInputsReproduceTheFiveDeclaredEntries) {
  const OrthoglideIdentification& id = identified();
  ASSERT_EQ(id.relative_residual.size(), 5u);
  for (double r : id.relative_residual) EXPECT_LT(std::abs(r), 1e-8) << id.report;
  std::cout << id.report;  // the figures of docs/vjm.md
  EXPECT_NE(id.report.find("Levenberg-Marquardt"), std::string::npos);
  // The identified inputs (also in models/orthoglide_*.yaml, checked by tests/io) are 4.17 N/um,
  // aluminium tube 14.87 x 1.487 mm bars, w = 26.0 mm, d = 28.5 mm and a foot of 633 mm of the 60 x 60 x 5
  // steel tube (an equivalent length: the foot lumps the slider's and guide's transverse compliance).
  // Independent route for the first entry: at Q0 a translation stretches one leg, so the hand series
  // of actuator, foot and leg (axial) must give Tables 1-2's 2.78e-4 mm/N with these inputs.
  const OrthoglideStiffnessModel& m = id.model;
  const double series = 1 / m.actuator_stiffness + m.foot_length / (m.foot_material.E * m.foot_section.A) +
                        m.link_length / (m.bar_material.E * 2 * m.bar_section.A);
  EXPECT_NEAR(series, 2.78 * kTran, 1e-8 * 2.78 * kTran);
  // Hardware, not a numerical artefact: a ball-screw axis of 1-100 N/um, bars of 5-50 mm, a bar spacing
  // and a platform half-width below the leg length.
  EXPECT_GT(m.actuator_stiffness, 1e6);
  EXPECT_LT(m.actuator_stiffness, 1e8);
  const double diameter = 0.020 * std::sqrt(m.bar_section.A / tube_section(0.020, 0.002).A);
  EXPECT_GT(diameter, 0.005);
  EXPECT_LT(diameter, 0.050);
  EXPECT_LT(m.parallelogram_width, m.link_length);
  EXPECT_LT(m.platform_offset, m.link_length);
}

TEST(OrthoglideIdentification, TheSolutionDoesNotDependOnTheStart) {
  // Well-posed: five entries pin five inputs. Starting far from the solution lands on the same one.
  OrthoglideStiffnessModel far = paper_calibration_start();
  far.actuator_stiffness = 4e7;
  far.bar_section = tube_section(0.01, 0.001);
  far.parallelogram_width = 0.15;
  far.platform_offset = 0.08;
  far.foot_length = 0.05;
  StatusOr<OrthoglideIdentification> r = identify_orthoglide_inputs(far, kInputs, paper_calibration_targets());
  ASSERT_TRUE(r.ok()) << r.status().message();
  const OrthoglideStiffnessModel &a = r->model, &b = identified().model;
  EXPECT_NEAR(a.actuator_stiffness, b.actuator_stiffness, 1e-6 * b.actuator_stiffness);
  EXPECT_NEAR(a.bar_section.Iy, b.bar_section.Iy, 1e-6 * b.bar_section.Iy);  // both tubes with t = D/10
  EXPECT_NEAR(a.parallelogram_width, b.parallelogram_width, 1e-6 * b.parallelogram_width);
  EXPECT_NEAR(a.platform_offset, b.platform_offset, 1e-6 * b.platform_offset);
  EXPECT_NEAR(a.foot_length, b.foot_length, 1e-6 * b.foot_length);
}

TEST(OrthoglideIdentification, BadRequestsAreRefusedWithAReason) {
  StatusOr<OrthoglideIdentification> few = identify_orthoglide_inputs(paper_calibration_start(), kInputs, {});
  ASSERT_FALSE(few.ok());
  EXPECT_EQ(few.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(few.status().message().find("0 target(s) for 5 input(s)"), std::string::npos);
  StatusOr<OrthoglideIdentification> zero = identify_orthoglide_inputs({}, kInputs, paper_calibration_targets());
  ASSERT_FALSE(zero.ok());  // the nominal platform offset is 0: no log-start
  EXPECT_NE(zero.status().message().find("platform offset"), std::string::npos);
  OrthoglideStiffnessModel overridden = paper_calibration_start();
  overridden.foot_spring = Mat6::Identity() * 1e6;
  StatusOr<OrthoglideIdentification> ignored =
      identify_orthoglide_inputs(overridden, kInputs, paper_calibration_targets());
  ASSERT_FALSE(ignored.ok());
  EXPECT_NE(ignored.status().message().find("overrides the foot spring"), std::string::npos);
  std::vector<ComplianceTarget> unreachable = paper_calibration_targets();
  unreachable[0].point = Vec3(0, 0.4, 0);
  StatusOr<OrthoglideIdentification> far = identify_orthoglide_inputs(paper_calibration_start(), kInputs, unreachable);
  EXPECT_FALSE(far.ok());
}

// Inputs the targets cannot determine used to end as a "success" anywhere along the undetermined
// direction; impossible targets and a tolerance that is not a number used to end as internal failures.
TEST(OrthoglideIdentification, UndeterminedOrImpossibleRequestsAreBadInput) {
  auto expect_invalid = [](const StatusOr<OrthoglideIdentification>& r, const std::string& part) {
    ASSERT_FALSE(r.ok()) << "expected a refusal with \"" << part << "\":\n" << r->report;
    EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput) << r.status().message();
    EXPECT_NE(r.status().message().find(part), std::string::npos) << r.status().message();
  };
  const OrthoglideStiffnessModel start = paper_calibration_start();
  const std::vector<ComplianceTarget> targets = paper_calibration_targets();
  expect_invalid(identify_orthoglide_inputs(start, kInputs, targets, std::nan("")), "tolerance nan");
  expect_invalid(identify_orthoglide_inputs(start, kInputs, targets, 0.0), "tolerance 0");

  // Target 2 repeated in place of target 5: five targets, four distinct terms, five inputs.
  std::vector<ComplianceTarget> repeated = targets;
  repeated[4] = repeated[1];
  repeated[4].label = "copy";
  repeated[4].source = "t.yaml:9";
  expect_invalid(identify_orthoglide_inputs(start, kInputs, repeated), "t.yaml:9: target 'copy': the same term as");

  // The parallelogram exists only in the 3-PRPaR: with 3-PUU targets alone its width changes nothing.
  const std::vector<ComplianceTarget> puu_only = {targets[0], targets[1], targets[3]};
  expect_invalid(identify_orthoglide_inputs(
                     start, {OrthoglideInput::kActuatorStiffness, OrthoglideInput::kParallelogramWidth}, puu_only),
                 "the parallelogram width (m) has no effect on the targets");

  // Distinct terms that carry the same information: at Q0, C(0,0) = C(1,1) = C(2,2) by symmetry, so
  // two of them cannot separate the actuator from the foot.
  std::vector<ComplianceTarget> symmetric = {targets[0], targets[0]};
  symmetric[1].row = symmetric[1].col = 1;
  expect_invalid(
      identify_orthoglide_inputs(start, {OrthoglideInput::kActuatorStiffness, OrthoglideInput::kFootLength}, symmetric),
      "the targets cannot determine the inputs");

  std::vector<ComplianceTarget> negative = targets;
  negative[0].value = -negative[0].value;
  expect_invalid(identify_orthoglide_inputs(start, kInputs, negative), "is negative");
}

TEST(OrthoglideIdentification, AnUnreachableTargetNamesItsSource) {
  std::vector<ComplianceTarget> targets = paper_calibration_targets();
  targets[2].point = Vec3(0, 0.4, 0);
  targets[2].source = "targets.yaml:7";
  StatusOr<OrthoglideIdentification> r = identify_orthoglide_inputs(paper_calibration_start(), kInputs, targets);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().message().rfind("targets.yaml:7: target 'Table 2, Q0, k_rot': ", 0), 0u) << r.status().message();
}

// ---- Predictions: the entries not used above, against the tables. ----

struct Blocks {
  double tran_a, tran_b, rot_a, rot_b;  // tables' units
};
struct Point {
  Blocks unloaded, loaded;
  double force;   // Table 3, N per axis
  double moment;  // Table 3, N mm per axis (ours: the wrench's Mx on the kinematics' axes; not compared)
};

Point computed(A a, double c) {
  StatusOr<OrthoglideStiffness> s = orthoglide_stiffness(identified().model, a, paper_table_point(c), kPaperLoad);
  EXPECT_TRUE(s.ok()) << s.status().message();
  if (!s.ok()) return {};
  auto blocks = [](const CartesianStiffness& k) {
    const Mat6& C = k.compliance;
    return Blocks{C(0, 0) / kTran, C(0, 1) / kTran, C(3, 3) / kRot, C(3, 4) / kRot};
  };
  // Forces change sign on the tables' reversed axes; a moment's sign depends on the model's handedness.
  return {blocks(s->unloaded), blocks(s->loaded), -s->loaded_state.wrench(0), s->loaded_state.wrench(3) * 1e3};
}

// Tables 1-2 as printed (rows: unloaded, loaded; a and b of k_tran and k_rot) and Table 3's F.
Point paper(A a, double c) {
  const bool puu = a == A::kPUU;
  if (c == kQ0)
    return puu ? Point{{2.78, 0, 20.9, 0}, {2.74, -0.02, 16.7, -0.02}, 1823, -101}
               : Point{{2.78, 0, 1.94, 0}, {2.74, -0.02, 1.88, 0.01}, 1823, 63.54};
  if (c == kQ1)
    return puu ? Point{{10.9, 5.5, 24.1, 7.5}, {10.5, 5.3, 22.0, 6.0}, 234, 524}
               : Point{{9.86, 5.80, 2.06, -0.32}, {9.55, 5.52, 2.05, -0.31}, 248, -6045};
  return puu ? Point{{71.3, -35.0, 25.8, -7.4}, {39.1, -18.9, 15.4, -0.7}, 4104, -2525}
             : Point{{21.2, -10.2, 2.65, 1.14}, {16.7, -7.9, 2.50, 1.28}, 9418, 68376};
}

// A prediction against a printed entry. `measured` is our value when this test was written (the
// comments list them): the bound is twice its distance from the paper, or 1.5 units of the entry's
// last printed digit where that is coarser (what the paper's rounding alone allows). So an entry we
// reproduce to 0.2 % is held to that, and one we miss by 7 % (said so in docs/vjm.md) is held to its
// miss, not to a blanket 10 %. Printed with its bound.
void expect_reproduced(double ours, double printed, double last_digit, double measured, const std::string& what) {
  const double bound = std::max(2.0 * std::abs(measured - printed), 1.5 * last_digit);
  std::cout << fmt::format("{}: ours {:.4g}, paper {:g}, |difference| {:.3g} <= {:.3g}\n", what, ours, printed,
                           std::abs(ours - printed), bound);
  EXPECT_LE(std::abs(ours - printed), bound) << what << ": ours " << ours << ", paper " << printed;
}

TEST(OrthoglidePrediction, Q0LoadedModeOfBothTables) {
  // At Q0 only the loaded entries are predictions: 2.74/-0.02 and 16.7/-0.02 (3-PUU), 1.88/0.01
  // (3-PRPaR). Measured: 2.771/-0.009, 16.93/-0.019, 1.898/+0.002; F = 1807 N (Table 3: 1823).
  for (A a : {A::kPUU, A::kPRPaR}) {
    const bool puu = a == A::kPUU;
    const Point ours = computed(a, kQ0), p = paper(a, kQ0);
    expect_reproduced(ours.loaded.tran_a, p.loaded.tran_a, 0.01, 2.771, "Q0 loaded k_tran a");
    expect_reproduced(ours.loaded.tran_b, p.loaded.tran_b, 0.01, -0.008794, "Q0 loaded k_tran b");
    expect_reproduced(ours.loaded.rot_a, p.loaded.rot_a, puu ? 0.1 : 0.01, puu ? 16.93 : 1.898, "Q0 loaded k_rot a");
    expect_reproduced(ours.loaded.rot_b, p.loaded.rot_b, 0.01, puu ? -0.01938 : 0.00243, "Q0 loaded k_rot b");
    expect_reproduced(ours.force, p.force, 1, 1807, "Q0 Table 3 F");
    // The load lowers every diagonal term at Q0 (tension in the legs).
    EXPECT_LT(ours.loaded.tran_a, ours.unloaded.tran_a);
    EXPECT_LT(ours.loaded.rot_a, ours.unloaded.rot_a);
  }
  // The 3-PUU's rotations soften most under load: 16.7/20.9 = 0.80 in Table 1, ours 0.81.
  const Point puu = computed(A::kPUU, kQ0);
  EXPECT_NEAR(puu.loaded.rot_a / puu.unloaded.rot_a, 16.7 / 20.9, 0.03);
}

TEST(OrthoglidePrediction, RotationalComplianceAtQ1AndQ2) {
  // Measured (unloaded a, b; loaded a, b): 3-PUU Q1 24.15, 7.49; 21.38, 5.56 (paper 24.1, 7.5; 22.0,
  // 6.0); Q2 25.93, -7.39 (25.8, -7.4); 3-PRPaR Q1 2.170, -0.344; 2.150, -0.337 (2.06, -0.32; 2.05,
  // -0.31). Not reproduced (docs/vjm.md): 3-PRPaR Q2 3.10, 1.37 (2.65, 1.14) and both loaded Q2 blocks.
  const Point puu1 = computed(A::kPUU, kQ1), puu2 = computed(A::kPUU, kQ2), pa1 = computed(A::kPRPaR, kQ1);
  const Point ppuu1 = paper(A::kPUU, kQ1), ppuu2 = paper(A::kPUU, kQ2), ppa1 = paper(A::kPRPaR, kQ1);
  expect_reproduced(puu1.unloaded.rot_a, ppuu1.unloaded.rot_a, 0.1, 24.15, "3-PUU Q1 k_rot a");
  expect_reproduced(puu1.unloaded.rot_b, ppuu1.unloaded.rot_b, 0.1, 7.49, "3-PUU Q1 k_rot b");
  expect_reproduced(puu1.loaded.rot_a, ppuu1.loaded.rot_a, 0.1, 21.38, "3-PUU Q1 loaded k_rot a");
  expect_reproduced(puu1.loaded.rot_b, ppuu1.loaded.rot_b, 0.1, 5.563, "3-PUU Q1 loaded k_rot b");
  expect_reproduced(puu2.unloaded.rot_a, ppuu2.unloaded.rot_a, 0.1, 25.93, "3-PUU Q2 k_rot a");
  expect_reproduced(puu2.unloaded.rot_b, ppuu2.unloaded.rot_b, 0.1, -7.392, "3-PUU Q2 k_rot b");
  expect_reproduced(pa1.unloaded.rot_a, ppa1.unloaded.rot_a, 0.01, 2.170, "3-PRPaR Q1 k_rot a");
  expect_reproduced(pa1.unloaded.rot_b, ppa1.unloaded.rot_b, 0.01, -0.3436, "3-PRPaR Q1 k_rot b");
  expect_reproduced(pa1.loaded.rot_a, ppa1.loaded.rot_a, 0.01, 2.150, "3-PRPaR Q1 loaded k_rot a");
  expect_reproduced(pa1.loaded.rot_b, ppa1.loaded.rot_b, 0.01, -0.337, "3-PRPaR Q1 loaded k_rot b");
  // Ratios between points of the 3-PUU's rotational compliance: Q1/Q0 = 1.153, Q2/Q0 = 1.234 in
  // Table 1; ours 1.156 and 1.241.
  EXPECT_NEAR(puu1.unloaded.rot_a / 20.9, 24.1 / 20.9, 0.02);
  EXPECT_NEAR(puu2.unloaded.rot_a / 20.9, 25.8 / 20.9, 0.02);
}

TEST(OrthoglidePrediction, SignOfEveryOffDiagonalTerm) {
  // The 20 non-zero printed couplings of Tables 1-2 (the nominal model has the same signs,
  // orthoglide_stiffness_test.cpp), including the tiny loaded ones at Q0.
  std::cout << "Tables 1-3 (a, b of each block; paper in brackets): unloaded k_tran | k_rot || loaded k_tran | "
               "k_rot | F | M\n";
  for (A a : {A::kPUU, A::kPRPaR}) {
    for (double c : {kQ0, kQ1, kQ2}) {
      const Point ours = computed(a, c), p = paper(a, c);
      std::cout << fmt::format(
          "{:7} {:7.2f} | {:.4g}, {:.4g} ({:g}, {:g}) | {:.4g}, {:.4g} ({:g}, {:g}) || {:.4g}, {:.4g} ({:g}, {:g}) | "
          "{:.4g}, {:.4g} ({:g}, {:g}) | {:.0f} ({:g}) | {:.0f} ({:g})\n",
          a == A::kPUU ? "3-PUU" : "3-PRPaR", c, ours.unloaded.tran_a, ours.unloaded.tran_b, p.unloaded.tran_a,
          p.unloaded.tran_b, ours.unloaded.rot_a, ours.unloaded.rot_b, p.unloaded.rot_a, p.unloaded.rot_b,
          ours.loaded.tran_a, ours.loaded.tran_b, p.loaded.tran_a, p.loaded.tran_b, ours.loaded.rot_a,
          ours.loaded.rot_b, p.loaded.rot_a, p.loaded.rot_b, ours.force, p.force, ours.moment, p.moment);
      const std::pair<double, double> pairs[] = {{ours.unloaded.tran_b, p.unloaded.tran_b},
                                                 {ours.unloaded.rot_b, p.unloaded.rot_b},
                                                 {ours.loaded.tran_b, p.loaded.tran_b},
                                                 {ours.loaded.rot_b, p.loaded.rot_b}};
      for (const auto& [mine, printed] : pairs) {
        if (printed != 0) {
          EXPECT_GT(mine * printed, 0) << c << ": ours " << mine << ", paper " << printed;
        }
      }
    }
  }
}

TEST(OrthoglidePrediction, TranslationalOffDiagonalAtQ2) {
  // The Q2 diagonal terms are calibration entries; the coupling b is not: -34.82 (Table 1: -35.0),
  // -9.77 (Table 2: -10.2). It sets the compliance along the diagonal (1,1,1), a + 2b.
  expect_reproduced(computed(A::kPUU, kQ2).unloaded.tran_b, -35.0, 0.1, -34.82, "3-PUU Q2 k_tran b");
  expect_reproduced(computed(A::kPRPaR, kQ2).unloaded.tran_b, -10.2, 0.1, -9.774, "3-PRPaR Q2 k_tran b");
}

TEST(OrthoglidePrediction, LoadedOverUnloadedRatiosAtQ0AndQ1) {
  // The "ratios between loaded and unloaded modes": at Q0 and Q1, for both architectures and
  // both blocks, ours within 0.03 of the tables' (measured largest difference 0.028, 3-PUU Q1 k_rot:
  // 0.885 vs 0.913).
  for (A a : {A::kPUU, A::kPRPaR}) {
    for (double c : {kQ0, kQ1}) {
      const Point ours = computed(a, c), p = paper(a, c);
      EXPECT_NEAR(ours.loaded.tran_a / ours.unloaded.tran_a, p.loaded.tran_a / p.unloaded.tran_a, 0.03) << c;
      EXPECT_NEAR(ours.loaded.rot_a / ours.unloaded.rot_a, p.loaded.rot_a / p.unloaded.rot_a, 0.03) << c;
    }
  }
}

TEST(OrthoglidePrediction, LoadedChangePerNewtonAtQ2) {
  // At Q2 the loaded blocks are not reproduced as such (ours 46.5 vs 39.1 for the 3-PUU's k_tran a)
  // because the load is not: the 0.5 mm displacement along the diagonal (1,1,1) needs F = 0.5 mm /
  // (a + 2b), and a + 2b is the small difference of two printed numbers (71.3 - 2 x 35.0 = 1.3 +- 0.1,
  // ours 1.65), so our F is 3025 N against Table 3's 4104 N. The loaded-mode change divided by the
  // load is reproduced: 3-PUU k_tran (71.3 - 39.1)/4104 = 7.85e-3 per N, ours 8.20e-3; k_rot
  // (25.8 - 15.4)/4104 = 2.53e-3, ours 2.71e-3. (Table 2's F = 9418 N at Q2 contradicts Table 2 itself:
  // its a + 2b gives 5600-6300 N; with the printed F its k_tran change per N is 4.8e-4, ours 4.7e-4.)
  const Point ours = computed(A::kPUU, kQ2), p = paper(A::kPUU, kQ2);
  const double tran = (ours.unloaded.tran_a - ours.loaded.tran_a) / ours.force;
  const double rot = (ours.unloaded.rot_a - ours.loaded.rot_a) / ours.force;
  EXPECT_NEAR(tran, (p.unloaded.tran_a - p.loaded.tran_a) / p.force, 0.10 * tran);
  EXPECT_NEAR(rot, (p.unloaded.rot_a - p.loaded.rot_a) / p.force, 0.10 * rot);
  const Point pa = computed(A::kPRPaR, kQ2), ppa = paper(A::kPRPaR, kQ2);
  const double pa_tran = (pa.unloaded.tran_a - pa.loaded.tran_a) / pa.force;
  EXPECT_NEAR(pa_tran, (ppa.unloaded.tran_a - ppa.loaded.tran_a) / ppa.force, 0.10 * pa_tran);
  // Our F follows our own a + 2b (a tangent against a secant: within 10 %).
  EXPECT_NEAR(ours.force, 0.5 / ((ours.unloaded.tran_a + 2 * ours.unloaded.tran_b) * 1e-4), 0.1 * ours.force);
}

TEST(OrthoglidePrediction, Q1TranslationMissesByOneCommonFactor) {
  // Not reproduced: the translational compliance at Q1 is about 0.70 of the tables' (3-PUU 7.77, 3.72
  // vs 10.9, 5.5; 3-PRPaR 6.87, 4.17 vs 9.86, 5.80), and so Table 3's F at Q1 is 335 N against 234 and
  // 248 N. What is asserted is the structure of the miss: nearly one factor for every term (a and b),
  // both architectures, unloaded and loaded (measured 0.676-0.723 around 0.702: +-3.8 %, of which the
  // tables' rounding explains about 1 %). A miss that the parallelogram, the load or one block caused
  // would differ between those terms by far more (docs/vjm.md).
  std::vector<double> ratios;
  for (A a : {A::kPUU, A::kPRPaR}) {
    const Point ours = computed(a, kQ1), p = paper(a, kQ1);
    for (double r : {ours.unloaded.tran_a / p.unloaded.tran_a, ours.unloaded.tran_b / p.unloaded.tran_b,
                     ours.loaded.tran_a / p.loaded.tran_a, ours.loaded.tran_b / p.loaded.tran_b})
      ratios.push_back(r);
  }
  double mean = 0;
  for (double r : ratios) mean += r / static_cast<double>(ratios.size());
  for (double r : ratios) EXPECT_NEAR(r, mean, 0.05 * mean);
}

}  // namespace
}  // namespace kinestat::mechanisms
