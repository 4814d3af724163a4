// The Orthoglide as an MSA frame (orthoglide_frame) against the VJM chains (orthoglide_chains) on the
// same inputs. Both models are exact for beams, linear springs and ideal joints: the VJM's springs are
// the cantilever condensations of the same beams (the 3-PUU leg's doubled section = the frame's two
// bars; the 3-PRPaR's parallelogram spring = the frame's two pinned bars), its passive joints are the
// frame's released rotations. So the 6x6 Cartesian stiffness matrices must agree to round-off.
#include <gtest/gtest.h>

#include "kinestat/mechanisms/orthoglide_frame.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::mechanisms {
namespace {

struct Case {
  OrthoglideArchitecture architecture;
  double table_coordinate_mm;  // tables' x = y = z: Q0 = 0, Q1 = -73.65, Q2 = 126.35
  double platform_offset_mm = 0.0;
};

Mat6 msa_stiffness(const OrthoglideStiffnessModel& m, const Case& c) {
  StatusOr<msa::Structure> s = orthoglide_frame(m, c.architecture, paper_table_point(c.table_coordinate_mm));
  EXPECT_TRUE(s.ok()) << s.status().message();
  if (!s.ok()) return Mat6::Zero();
  msa::Workspace ws;
  StatusOr<CartesianStiffness> K = msa::cartesian_stiffness(*s, ws, *s->report_node());
  EXPECT_TRUE(K.ok()) << K.status().message();
  if (!K.ok()) return Mat6::Zero();
  EXPECT_TRUE(K->stiffness_defined) << K->note;
  return K->stiffness;
}

Mat6 vjm_stiffness(const OrthoglideStiffnessModel& m, const Case& c) {
  StatusOr<std::vector<vjm::Chain>> chains =
      orthoglide_chains(m, c.architecture, paper_table_point(c.table_coordinate_mm));
  EXPECT_TRUE(chains.ok()) << chains.status().message();
  if (!chains.ok()) return Mat6::Zero();
  StatusOr<CartesianStiffness> K = vjm::platform_unloaded_stiffness(*chains);
  EXPECT_TRUE(K.ok() && K->status.ok()) << (K.ok() ? K->status.message() : K.status().message());
  return K.ok() ? K->stiffness : Mat6::Zero();
}

double max_rel(const Mat6& A, const Mat6& B) { return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff(); }

class OrthoglideFrame : public ::testing::TestWithParam<Case> {};

// Measured max|K_msa - K_vjm| / max|K_vjm| (Release build, recorded as the test property max_rel_diff):
// 3-PUU 1.5e-14 at Q0, 2.4e-12 at Q1; 3-PRPaR 1.2e-13 at Q0, 4.6e-13 at Q1. The 1e-6 bound leaves room
// for other platforms' round-off, not for a modelling difference: an Euler-Bernoulli foot in the frame
// (the VJM's is Timoshenko) gives 3.6e-3 at Q1 (1e-14 at Q0, where the feet are only loaded axially).
// With a platform offset (28.5 mm, the identified value of models/orthoglide_*.yaml) the frame's
// rigid platform links and the chains' platform translations must still agree; measured 3-PUU
// 7.6e-13 at Q1 and 2.5e-12 at Q2, 3-PRPaR 4.9e-13 and 7.5e-14 (Q2 included: the offset matters most
// there).
TEST_P(OrthoglideFrame, EqualsTheVjmStiffness) {
  OrthoglideStiffnessModel m;
  m.platform_offset = GetParam().platform_offset_mm * 1e-3;
  const Mat6 Km = msa_stiffness(m, GetParam()), Kv = vjm_stiffness(m, GetParam());
  ASSERT_GT(Kv.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LT(max_rel(Km, Kv), 1e-6) << "MSA\n" << Km << "\nVJM\n" << Kv;
  EXPECT_LT(max_rel(Km, Km.transpose()), 1e-12);
  RecordProperty("max_rel_diff", ::testing::PrintToString(max_rel(Km, Kv)));
}

INSTANTIATE_TEST_SUITE_P(Postures, OrthoglideFrame,
                         ::testing::Values(Case{OrthoglideArchitecture::kPUU, 0.0},
                                           Case{OrthoglideArchitecture::kPUU, -73.65},
                                           Case{OrthoglideArchitecture::kPRPaR, 0.0},
                                           Case{OrthoglideArchitecture::kPRPaR, -73.65},
                                           Case{OrthoglideArchitecture::kPUU, -73.65, 28.5},
                                           Case{OrthoglideArchitecture::kPUU, 126.35, 28.5},
                                           Case{OrthoglideArchitecture::kPRPaR, -73.65, 28.5},
                                           Case{OrthoglideArchitecture::kPRPaR, 126.35, 28.5}));

TEST(OrthoglideFrameQ0, TranslationalComplianceIsTheSeriesOfActuatorFootAndLeg) {
  // At Q0 leg i lies on slider axis e_i; a force along e_i loads leg i axially (actuator, foot, both
  // bars in series) while the other two legs, ending in joints whose released rotations let them
  // swing along e_i, carry nothing: c = 1/k_act + l_foot/(E_f A_f) + L/(E 2 A_bar) for both legs.
  const OrthoglideStiffnessModel m;
  const double c = 1.0 / m.actuator_stiffness + m.foot_length / (m.foot_material.E * m.foot_section.A) +
                   m.link_length / (m.bar_material.E * 2.0 * m.bar_section.A);
  for (auto a : {OrthoglideArchitecture::kPUU, OrthoglideArchitecture::kPRPaR}) {
    const Mat3 C = msa_stiffness(m, {a, 0.0}).inverse().topLeftCorner<3, 3>();
    EXPECT_LT((C - c * Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-9 * c) << C;
  }
}

TEST(OrthoglideFrameInput, UnreachablePointAndBadValuesAreInvalidInput) {
  const OrthoglideStiffnessModel m;
  StatusOr<msa::Structure> far = orthoglide_frame(m, OrthoglideArchitecture::kPUU, Vec3(0.0, 0.4, 0.0));
  ASSERT_FALSE(far.ok());
  EXPECT_EQ(far.status().code(), StatusCode::kInvalidInput);
  OrthoglideStiffnessModel bad = m;
  bad.actuator_stiffness = -1.0;
  StatusOr<msa::Structure> s = orthoglide_frame(bad, OrthoglideArchitecture::kPRPaR, Vec3::Zero());
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("actuator_stiffness = -1 N/m must be positive"), std::string::npos)
      << s.status().message();
  bad = m;
  bad.bar_section.J = 0.0;
  s = orthoglide_frame(bad, OrthoglideArchitecture::kPUU, Vec3::Zero());
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.status().message().find("bar_section.J = 0 m^4 must be positive"), std::string::npos)
      << s.status().message();
}

}  // namespace
}  // namespace kinestat::mechanisms
