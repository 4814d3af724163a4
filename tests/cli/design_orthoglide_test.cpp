// kinestat design orthoglide: the paper's analyses beyond Table 4 are printed (section 5.2 switch
// points, Fig. 3 and Table 2 volumes, the software limit's share of the joint box, section 6's encoder
// offsets), with the values the library tests check against independent routes
// (tests/mechanisms/orthoglide_design_test.cpp).
#include <gtest/gtest.h>

#include <string>

#include <fmt/format.h>

#include "cli_run.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"

namespace kinestat::cli {
namespace {

// The text after `label` on its line.
std::string after(const std::string& out, const std::string& label) {
  const std::size_t at = out.find(label);
  if (at == std::string::npos) return "(missing: " + label + ")";
  const std::size_t end = out.find('\n', at);
  return out.substr(at + label.size(), end - at - label.size());
}

TEST(DesignOrthoglide, PrintsThePapersOtherAnalyses) {
  const CliRun r = run_cli({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "1"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const mechanisms::OrthoglideDesign d = *mechanisms::design_orthoglide(1, 0.5, 0.2);
  EXPECT_EQ(
      after(r.out, "joint box kept"),
      fmt::format("              {:.2f} % of [rho_min, rho_max]^3 within the software limit", 100 * d.joint_box_kept));
  // Section 6: the paper's 2.42 and 3.42 for 5 and 10 mm.
  EXPECT_EQ(after(r.out, "cube, encoders +5.0 mm    ").substr(0, 14), "[0.507, 2.419]") << r.out;
  EXPECT_EQ(after(r.out, "cube, encoders +10.0 mm   ").substr(0, 14), "[0.515, 3.420]") << r.out;
  // Section 5.2: the formulas' switch points, the search's minimum there, the true switch.
  EXPECT_NE(r.out.find("rho_SR = 0.1093, mu = 0.3232; numerical search there 0.3208"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rho_RQ = 0.2240, mu = 0.4210; numerical search there 0.4175"), std::string::npos) << r.out;
  EXPECT_NE(after(r.out, "true switch to Q-").find("rho = 0.2398, mu = 0.4275"), std::string::npos) << r.out;
  // Fig. 3 and Table 2.
  EXPECT_NE(r.out.find("V0 = 95.0 % of the sphere"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("lower 0.842 V0, two-sided 0.684 V0, upper 0.734 V0"), std::string::npos) << r.out;
}

TEST(DesignOrthoglide, EncoderOffsetsOption) {
  CliRun r =
      run_cli({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--strategy", "2", "--encoder-offsets", "-5,0"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("cube, encoders -5.0 mm"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("5.0 mm further in than commanded"), std::string::npos) << r.out;
  // Zero offset: the cube's own factors (Proposition 1).
  EXPECT_EQ(after(r.out, "cube, encoders +0.0 mm    ").substr(0, 14),
            after(r.out, "    cube                      ").substr(0, 14))
      << r.out;
  EXPECT_EQ(r.out.find("joint box kept"), std::string::npos);  // strategy 2 has no software limit
  r = run_cli({"design", "orthoglide", "--cube", "200", "--mu", "0.5", "--encoder-offsets", "nan"});
  EXPECT_EQ(r.code, kExitBadInput);
  EXPECT_NE(r.err.find("--encoder-offsets"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace kinestat::cli
